// simcli when a run does not simply finish: interrupted by SIGINT or SIGTERM,
// checkpointed and resumed (the first part of the output and the resumed
// part together equal the uninterrupted run, byte for byte), written to a
// file that is replaced only on success, and the progress line.

#include "check.hpp"
#include "checkpoint_text.hpp"
#include "run_process.hpp"
#include "threads_stats_line.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using run_process::Result;

namespace {

const std::string simcli = SIMCLI_PATH;

Result simcli_run(const std::vector<std::string>& args, const std::string& input = "",
                  run_process::Signal signal = {}) {
    return run_process::run(simcli, args, input, "", false, signal);
}

class ScratchDir {
public:
    ScratchDir() {
        char name[] = "/tmp/particlesim-interrupts-XXXXXX";
        path_ = mkdtemp(name);
    }
    ~ScratchDir() { std::filesystem::remove_all(path_); }
    [[nodiscard]] std::string operator/(const std::string& file) const { return path_ + "/" + file; }
    [[nodiscard]] std::size_t file_count() const {
        return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(path_), {}));
    }

private:
    std::string path_;
};

void write_file(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// The first `lines` lines of `text`.
std::string head(const std::string& text, std::size_t lines) {
    std::size_t at = 0;
    for (std::size_t k = 0; k < lines && at != std::string::npos; ++k) {
        at = text.find('\n', at);
        if (at != std::string::npos) ++at;
    }
    return at == std::string::npos ? text : text.substr(0, at);
}

// A checkpoint every K steps keeps the last one, at floor(S / K) K: resuming
// it must write exactly what the whole run writes after that step's block.
void checkpoint_every_k_resumes_byte_for_byte() {
    const ScratchDir dir;
    const std::size_t count = 150;
    const std::int64_t steps = 40;
    for (const std::string mode : {"print", "perf"}) {
        const std::string scene = std::to_string(count) + " 70 1 " + std::to_string(steps) + " " + mode + "\n";
        const std::vector<std::vector<std::string>> runs = {{"-t", "1"},
                                                            {"--broadphase", "grid", "-t", "2"},
                                                            {"--substeps", "3", "-t", "2"},
                                                            {"--engine", "exact"},
                                                            {"--exact-numbers"}};
        for (const std::vector<std::string>& run_options : runs) {
            const Result whole = simcli_run(run_options, scene);
            CHECK_EQ(whole.status, 0);
            for (const std::int64_t every : {1, 7, 13, 40}) {
                check::Context context(mode, " ", run_options[0], " ", run_options.size() > 1 ? run_options[1] : "",
                                       ", checkpoint every ", every);
                std::vector<std::string> args = run_options;
                const std::string checkpoint = dir / "run.checkpoint";
                for (const std::string& a : {std::string("--checkpoint"), checkpoint, std::string("--checkpoint-every"),
                                             std::to_string(every)})
                    args.push_back(a);
                const Result first = simcli_run(args, scene);
                CHECK(first.out == whole.out);  // checkpoints change nothing in the output
                const std::int64_t saved_at = steps / every * every;
                // Threads and search may differ on resumption: they never change a result.
                const Result rest = simcli_run({"--resume", checkpoint, "-t", "2", "--quiet"});
                CHECK_EQ(rest.status, 0);
                const std::size_t blocks_before =
                    mode == "print" ? static_cast<std::size_t>(std::min(saved_at + 1, steps)) : 1;
                CHECK(head(whole.out, count * blocks_before) + rest.out == whole.out);
            }
        }
    }
}

// "--resume -" reads the checkpoint from stdin, as "-" reads a scene; a
// checkpoint that cannot be opened is refused with the reason.
void a_checkpoint_from_stdin() {
    const ScratchDir dir;
    const std::string checkpoint = dir / "run.checkpoint";
    CHECK_EQ(simcli_run({"--checkpoint", checkpoint, "--checkpoint-every", "25"}, "200 2000 1 60 print\n").status, 0);
    const Result from_file = simcli_run({"--resume", checkpoint});
    CHECK_EQ(from_file.status, 0);
    CHECK(!from_file.out.empty());
    const Result from_stdin = simcli_run({"--resume", "-"}, run_process::slurp(checkpoint));
    CHECK_EQ(from_stdin.status, 0);
    CHECK(from_stdin.out == from_file.out);
    const Result garbage = simcli_run({"--resume", "-"}, "not a checkpoint\n");
    CHECK_EQ(garbage.status, 2);
    CHECK(garbage.err.find("simcli: <stdin>: not a checkpoint simcli can resume") != std::string::npos);
    const Result missing = simcli_run({"--resume", dir / "missing"});
    CHECK_EQ(missing.status, 2);
    CHECK(missing.err.find("missing: cannot open the checkpoint: No such file or directory") != std::string::npos);
}

// --stats of a resumed run counts the steps that run made (in its time and
// rate, and its threads line): 60 steps with a
// checkpoint every 25 resume at step 50, so 10 steps, the last 2 of them
// (after 8 warm-up steps) the first steps of a trial, on one thread.
void resumed_stats_count_the_resumed_steps() {
    const ScratchDir dir;
    const std::string checkpoint = dir / "run.checkpoint";
    const Result first = simcli_run({"--checkpoint", checkpoint, "--checkpoint-every", "25"}, "200 2000 1 60 perf\n");
    CHECK_EQ(first.status, 0);
    const Result rest = simcli_run({"--resume", checkpoint, "--stats", "--quiet"});
    CHECK_EQ(rest.status, 0);
    CHECK(rest.err.find("stats: engine step, 10 steps in ") != std::string::npos);
    const threads_stats_line::Line line = threads_stats_line::read(rest.err);
    CHECK(line.found);
    if (line.threads > 1) {
        CHECK(line.trials);
        CHECK_EQ(line.one_thread_steps, 2LL);
        CHECK_EQ(line.steps, 10LL);
    } else {
        CHECK(line.threads == 1 && !line.trials);
    }
}

// A real signal at an arbitrary step: the output written so far (a file,
// renamed into place on the interrupt) and the resumed part equal the whole run.
void signals_checkpoint_and_resume() {
    const ScratchDir dir;
    const std::string scene = "1500 250 1 100000 print\n";
    for (const std::string engine : {"step", "exact"}) {
        for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
            check::Context context(engine, " engine, signal ", signal);
            const std::string out = dir / "first.out", checkpoint = dir / "run.checkpoint";
            const Result first =
                simcli_run({"--engine", engine, "-o", out, "--checkpoint", checkpoint}, scene, {signal, 250});
            CHECK_EQ(first.status, 128 + signal);
            CHECK(first.err.find("interrupted after step ") == 0 ||
                  first.err.find("simcli: interrupted after step ") == 0);
            CHECK(first.err.find("continue with: simcli --resume " + checkpoint) != std::string::npos);
            const std::string first_part = run_process::slurp(out);
            const std::size_t lines = static_cast<std::size_t>(std::count(first_part.begin(), first_part.end(), '\n'));
            CHECK(lines > 1500 && lines % 1500 == 0);  // whole blocks only
            // The whole run up to the interrupted step, then resumed to the end,
            // is too long for a test; S is cut instead: rewrite the checkpoint's S.
            const std::int64_t interrupted_at = static_cast<std::int64_t>(lines / 1500) - 1;
            const std::int64_t end = interrupted_at + 5;
            CHECK(checkpoint_text::set_steps(checkpoint, 100000, end));
            const Result rest = simcli_run({"--resume", checkpoint});
            CHECK_EQ(rest.status, 0);
            const std::string short_scene = "1500 250 1 " + std::to_string(end) + " print\n";
            const Result whole = simcli_run({"--engine", engine}, short_scene);
            CHECK(first_part + rest.out == whole.out);
        }
    }
}

// The lines of `text` after its first (a header).
std::vector<std::string> rows_of(const std::string& text) {
    std::vector<std::string> rows;
    std::size_t at = text.find('\n');
    while (at != std::string::npos && at + 1 < text.size()) {
        const std::size_t end = text.find('\n', at + 1);
        rows.push_back(text.substr(at + 1, end - at - 1));
        at = end;
    }
    return rows;
}

// A row's step (its first field) and its pair collisions (its third).
std::int64_t row_field(const std::string& row, int field) {
    std::size_t at = 0;
    for (int k = 0; k < field; ++k) at = row.find(',', at) + 1;
    return std::stoll(row.substr(at, row.find(',', at) - at));
}

// With a checkpoint, an interrupted run keeps its trajectory and its
// observables, the latter with a last row up to the interrupted step; the
// resumed run writes their rest. The trajectory's two parts are the
// uninterrupted run's frames; every observables row but the two around the
// interruption is the uninterrupted run's, byte for byte, and those two
// share its row's interval and collisions.
void observables_and_trajectory_resume() {
    const ScratchDir dir;
    // Rows every 40 steps: --stats needs four rows, and this scene runs about
    // 2000 steps a second on one quiet core, so the interrupt at 700 ms finds
    // them even on a machine ten times slower.
    const std::int64_t every = 40;
    const std::string checkpoint = dir / "run.checkpoint";
    const auto with_files = [&](std::vector<std::string> args, const std::string& name) {
        for (const std::string& a :
             {std::string("-o"), std::string("/dev/null"), std::string("--observables"), dir / (name + ".csv"),
              std::string("--observe-every"), std::to_string(every), std::string("--trajectory"), dir / (name + ".xyz"),
              std::string("--trajectory-every"), std::to_string(every)})
            args.push_back(a);
        return args;
    };
    const Result first = simcli_run(with_files({"--engine", "exact", "--checkpoint", checkpoint, "--stats"}, "first"),
                                    "400 150 1 100000 perf\n", {SIGINT, 700});
    CHECK_EQ(first.status, 130);
    CHECK(first.err.find("the output, " + (dir / "first.csv") + " and " + (dir / "first.xyz") + " hold steps up to ") !=
          std::string::npos);
    CHECK(first.err.find("stats: pressure beta P (2r)^2 = ") != std::string::npos);  // over the rows kept
    const std::size_t after = first.err.find("interrupted after step ");
    CHECK(after != std::string::npos);
    if (after == std::string::npos) return;
    const std::int64_t stopped = std::stoll(first.err.substr(after + 23));
    CHECK(stopped >= 4 * every);

    // The rest cut short, as in signals_checkpoint_and_resume().
    const std::int64_t end = stopped + 3 * every + 17;
    const bool cut_short = checkpoint_text::set_steps(checkpoint, 100000, end);
    CHECK(cut_short);
    if (!cut_short) return;
    CHECK_EQ(simcli_run(with_files({"--resume", checkpoint, "--quiet"}, "rest")).status, 0);
    CHECK_EQ(
        simcli_run(with_files({"--engine", "exact"}, "whole"), "400 150 1 " + std::to_string(end) + " perf\n").status,
        0);

    CHECK(run_process::slurp(dir / "first.xyz") + run_process::slurp(dir / "rest.xyz") ==
          run_process::slurp(dir / "whole.xyz"));
    const std::vector<std::string> head_rows = rows_of(run_process::slurp(dir / "first.csv"));
    const std::vector<std::string> rest_rows = rows_of(run_process::slurp(dir / "rest.csv"));
    const std::vector<std::string> whole_rows = rows_of(run_process::slurp(dir / "whole.csv"));
    CHECK(!head_rows.empty() && !rest_rows.empty());
    if (head_rows.empty() || rest_rows.empty()) return;
    CHECK_EQ(row_field(head_rows.back(), 0), stopped);
    const bool on_a_row = stopped % every == 0;  // then no row is split
    std::vector<std::string> joined(head_rows.begin(), head_rows.end() - (on_a_row ? 0 : 1));
    joined.insert(joined.end(), rest_rows.begin() + (on_a_row ? 0 : 1), rest_rows.end());
    CHECK_EQ(joined.size() + (on_a_row ? 0U : 1U), whole_rows.size());
    if (joined.size() + (on_a_row ? 0U : 1U) != whole_rows.size()) return;
    const std::size_t split = head_rows.size() - 1;  // the whole run's row that the interruption cut in two
    for (std::size_t k = 0, w = 0; k < joined.size(); ++k, ++w) {
        if (!on_a_row && w == split) ++w;
        check::Context context("row ", k);
        CHECK(joined[k] == whole_rows[w]);
    }
    if (!on_a_row) {
        CHECK_EQ(row_field(rest_rows.front(), 0), row_field(whole_rows[split], 0));
        CHECK_EQ(row_field(head_rows.back(), 2) + row_field(rest_rows.front(), 2), row_field(whole_rows[split], 2));
    }
}

// A run killed outright (SIGKILL, a lost node) after a periodic checkpoint
// has written on past it. --resume cuts its output, trajectory and
// observables back to the checkpoint's step and goes on with the observables'
// open row: the two parts join as the uninterrupted run's files, byte for
// byte, the observables' rows too.
void killed_run_resumes_from_its_last_checkpoint() {
    const ScratchDir dir;
    const std::string checkpoint = dir / "run.checkpoint";
    const auto with_files = [&](std::vector<std::string> args, const std::string& name) {
        for (const std::string& a :
             {std::string("-o"), dir / (name + ".out"), std::string("--observables"), dir / (name + ".csv"),
              std::string("--observe-every"), std::string("5"), std::string("--trajectory"), dir / (name + ".xyz"),
              std::string("--trajectory-every"), std::string("3")})
            args.push_back(a);
        return args;
    };
    const Result killed =
        simcli_run(with_files({"--engine", "exact", "--checkpoint", checkpoint, "--checkpoint-every", "7"}, "first"),
                   "400 150 1 100000 perf\n", {SIGKILL, 700});
    CHECK_EQ(killed.status, 128 + SIGKILL);
    const std::int64_t step = checkpoint_text::first_part_step(checkpoint);
    CHECK(step >= 7 && step % 7 == 0);
    if (step < 7) return;
    const std::int64_t end = step + 30;
    CHECK(checkpoint_text::set_steps(checkpoint, 100000, end));
    // What a kill may leave past the checkpoint (the buffers flushed since), made certain.
    for (const std::string extension : {".out", ".csv", ".xyz"}) {
        std::ofstream(dir / ("first" + extension), std::ios::app) << "written after the checkpoint\n";
    }
    const Result rest = simcli_run(with_files({"--resume", checkpoint, "--quiet"}, "rest"));
    CHECK_EQ(rest.status, 0);
    for (const std::string extension : {".out", ".csv", ".xyz"}) {
        CHECK(rest.err.find("first" + extension + " cut back to the checkpoint's step " + std::to_string(step)) !=
              std::string::npos);
    }
    const Result whole =
        simcli_run(with_files({"--engine", "exact"}, "whole"), "400 150 1 " + std::to_string(end) + " perf\n");
    CHECK_EQ(whole.status, 0);
    for (const std::string extension : {".out", ".xyz"}) {
        check::Context context(extension);
        CHECK(run_process::slurp(dir / ("first" + extension)) + run_process::slurp(dir / ("rest" + extension)) ==
              run_process::slurp(dir / ("whole" + extension)));
    }
    const std::string rest_rows = run_process::slurp(dir / "rest.csv");
    CHECK(run_process::slurp(dir / "first.csv") + rest_rows.substr(rest_rows.find('\n') + 1) ==
          run_process::slurp(dir / "whole.csv"));
}

// The same with the step engine's printed states, the run's last periodic
// checkpoint standing for the kill (the run wrote on to its end past it);
// a file replaced since the checkpoint is not the one recorded and is left
// alone, and a checkpoint whose files are recorded at another step than its
// state's is refused.
void last_periodic_checkpoint_cuts_the_output_back() {
    const ScratchDir dir;
    const std::string checkpoint = dir / "run.checkpoint", first = dir / "first.out";
    const std::string scene = "300 250 1 130 print\n";
    CHECK_EQ(simcli_run({"-o", first, "--checkpoint", checkpoint, "--checkpoint-every", "40"}, scene).status, 0);
    CHECK_EQ(checkpoint_text::first_part_step(checkpoint), 120);
    const std::string whole = run_process::slurp(first);
    const Result rest = simcli_run({"--resume", checkpoint, "-t", "2"});
    CHECK_EQ(rest.status, 0);
    CHECK(rest.err.find("first.out cut back to the checkpoint's step 120") != std::string::npos);
    CHECK(run_process::slurp(first) + rest.out == whole);

    // A new file (made while the old one is there: another inode) put in its place.
    write_file(dir / "copy.out", whole);
    std::filesystem::rename(dir / "copy.out", first);
    const Result again = simcli_run({"--resume", checkpoint});
    CHECK_EQ(again.status, 0);
    CHECK(again.err.find("cut back") == std::string::npos);
    CHECK(run_process::slurp(first) == whole);

    std::string saved = run_process::slurp(checkpoint);
    saved.replace(saved.find("first-part 120 "), 15, "first-part 80 ");
    write_file(checkpoint, saved);
    const Result refused = simcli_run({"--resume", checkpoint});
    CHECK_EQ(refused.status, 2);
    CHECK(refused.err.find("its files are recorded at step 80, its state at step 120") != std::string::npos);
}

// Standard output redirected to a file of its own is recorded and cut back
// as -o FILE is: the resumed part appended to it (`>>`) makes the whole
// run's output. Shared with stderr (`> log 2>&1`), whose lines would be cut
// with it, it is not recorded.
void stdout_file_cut_back_too() {
    const ScratchDir dir;
    const std::string checkpoint = dir / "run.checkpoint", first = dir / "first.out";
    const std::string scene = "300 250 1 130 print\n";
    const std::vector<std::string> checkpointed = {"--checkpoint", checkpoint, "--checkpoint-every", "40"};
    CHECK_EQ(run_process::run(simcli, checkpointed, scene, first).status, 0);
    CHECK_EQ(checkpoint_text::first_part_step(checkpoint), 120);
    CHECK_EQ(checkpoint_text::first_part_files(checkpoint), 1);
    const std::string whole = run_process::slurp(first);
    CHECK(whole == simcli_run({}, scene).out);
    const Result appended =
        run_process::run("/bin/sh", {"-c", "exec \"$0\" --resume \"$1\" >> \"$2\"", simcli, checkpoint, first});
    CHECK_EQ(appended.status, 0);
    CHECK(appended.err.find("first.out cut back to the checkpoint's step 120") != std::string::npos);
    CHECK(run_process::slurp(first) == whole);
    // `>` empties the first part before simcli starts: too late to save it, but said.
    const Result emptied =
        run_process::run("/bin/sh", {"-c", "exec \"$0\" --resume \"$1\" > \"$2\"", simcli, checkpoint, first});
    CHECK_EQ(emptied.status, 0);
    CHECK(emptied.err.find("first.out is shorter than at the checkpoint's step 120 (0 bytes, not ") !=
          std::string::npos);
    CHECK(emptied.err.find("): standard output was redirected to it with > (which empties it), not >>\n") !=
          std::string::npos);

    const std::string shared = dir / "shared.out";
    const std::vector<std::string> script = {
        "-c", "exec \"$0\" --checkpoint \"$1\" --checkpoint-every 40 > \"$2\" 2>&1", simcli, checkpoint, shared};
    CHECK_EQ(run_process::run("/bin/sh", script, scene).status, 0);
    CHECK_EQ(checkpoint_text::first_part_step(checkpoint), 120);
    CHECK_EQ(checkpoint_text::first_part_files(checkpoint), 0);
    CHECK(run_process::slurp(shared) == whole);
}

// A resumed run writes its files anew, so one named like a file of its first
// part would replace that part with the rest alone: refused before anything
// runs, the part left as it was. A link to it is not it (the link is what
// would be replaced).
void resume_never_writes_over_its_first_part() {
    const ScratchDir dir;
    const std::string checkpoint = dir / "run.checkpoint", first = dir / "first.out", frames = dir / "first.xyz";
    const std::string scene = "120 90 1 50 perf\n";
    CHECK_EQ(simcli_run({"--engine", "exact", "-o", first, "--trajectory", frames, "--trajectory-every", "5",
                         "--checkpoint", checkpoint, "--checkpoint-every", "20"},
                        scene)
                 .status,
             0);
    CHECK_EQ(checkpoint_text::first_part_files(checkpoint), 2);
    const std::string output = run_process::slurp(first), trajectory = run_process::slurp(frames);
    const Result over_output = simcli_run({"--resume", checkpoint, "-o", first});
    CHECK_EQ(over_output.status, 2);
    CHECK(over_output.err == "simcli: -o " + first +
                                 " holds the first part of the run, up to step 40, and the resumed run would replace "
                                 "it with the rest: write the rest to another file and join the two\n");
    const Result over_frames = simcli_run({"--resume", checkpoint, "--trajectory", frames});
    CHECK_EQ(over_frames.status, 2);
    CHECK(over_frames.err.find("--trajectory " + frames + " holds the first part") != std::string::npos);
    CHECK(run_process::slurp(first) == output);
    CHECK(run_process::slurp(frames) == trajectory);

    std::filesystem::create_symlink(first, dir / "link.out");
    const Result through_link = simcli_run({"--resume", checkpoint, "-o", dir / "link.out"});
    CHECK_EQ(through_link.status, 0);
    CHECK(!std::filesystem::is_symlink(dir / "link.out"));
    CHECK(run_process::slurp(first) + run_process::slurp(dir / "link.out") == output);
}

// Without a checkpoint an interrupted or failed run leaves FILE as it was,
// and no temporary file behind; a device is written in place.
void output_file_replaced_only_on_success() {
    const ScratchDir dir;
    const std::string out = dir / "result.out";
    write_file(out, "the previous result\n");
    const Result interrupted = simcli_run({"-o", out}, "3000 300 1 100000 print\n", {SIGINT, 500});
    CHECK_EQ(interrupted.status, 130);
    CHECK(interrupted.err.find(out + " left as it was") != std::string::npos);
    CHECK(run_process::slurp(out) == "the previous result\n");
    CHECK_EQ(dir.file_count(), 1U);

    // A run that fails (the exact engine's runaway guard) does not touch it either.
    const Result failed =
        simcli_run({"--engine", "exact", "-o", out}, "2\n4.000000001\n1\n5\nprint\n0 1 2 1 0\n1 3.000000001 2 -1 0\n");
    CHECK_EQ(failed.status, 1);
    CHECK(run_process::slurp(out) == "the previous result\n");
    CHECK_EQ(dir.file_count(), 1U);

    // Success replaces it, keeping its permissions.
    std::filesystem::permissions(out, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    const Result done = simcli_run({"-o", out}, "2 20 1 3 perf\n0 5 5 1 0\n1 15 5 -1 0\n");
    CHECK_EQ(done.status, 0);
    CHECK(run_process::slurp(out).rfind("0 0 5.00000000 5.00000000 1.00000000 0.00000000\n", 0) == 0);
    CHECK((std::filesystem::status(out).permissions() & std::filesystem::perms::all) ==
          (std::filesystem::perms::owner_read | std::filesystem::perms::owner_write));
    CHECK_EQ(dir.file_count(), 1U);

    // /dev/null stays a device: written directly, never renamed over.
    CHECK_EQ(simcli_run({"-o", "/dev/null"}, "2 20 1 3 perf\n0 5 5 1 0\n1 15 5 -1 0\n").status, 0);
    CHECK(std::filesystem::is_character_file("/dev/null"));
}

void exact_numbers() {
    // r = 1e-9: 8 decimals print only zeros for the velocities, exact numbers read back.
    const std::string scene = "2 1e-7 1e-9 2 print\n0 2e-8 5e-8 3e-9 1e-10\n1 8e-8 5e-8 -3e-9 0\n";
    const Result fixed = simcli_run({}, scene);
    const Result exact = simcli_run({"--exact-numbers"}, scene);
    CHECK_EQ(exact.status, 0);
    CHECK(fixed.out.find("0 0 0.00000002 0.00000005 0.00000000 0.00000000\n") == 0);
    CHECK(exact.out.find("0 0 2e-08 5e-08 3e-09 1e-10\n") == 0);
    CHECK_EQ(std::count(exact.out.begin(), exact.out.end(), '\n'), 6L);
}

// A second signal before the step ends stops simcli at once: a step of
// millions of events (disks crossing the box several times a step) would
// otherwise hold the first signal for seconds. It ends by the signal, the
// output file stays as it was and no temporary file is left.
void second_signal_stops_at_once() {
    const ScratchDir dir;
    const Result scene =
        run_process::run(SIMGEN_PATH, {"fast", "-n", "20000", "-L", "2000", "-s", "1", "--mode", "perf"});
    CHECK_EQ(scene.status, 0);
    const std::string out = dir / "out.txt";
    write_file(out, "the previous result\n");
    // The signals count from the output's temporary file, so that a slow start on a busy machine is not signalled.
    const Result forced =
        simcli_run({"--engine", "exact", "-o", out}, scene.out, {SIGINT, 300, dir / ".out.txt.simcli-{pid}.tmp", 300});
    CHECK_EQ(forced.status, 128 + SIGINT);
    CHECK(forced.err.find("simcli: stopped at once by a second signal") == 0);
    CHECK(forced.err.find("interrupted after step") == std::string::npos);  // not the step's end
    CHECK(run_process::slurp(out) == "the previous result\n");
    CHECK_EQ(dir.file_count(), 1U);
}

// 100 000 disks for 3 steps in print mode: writing a state takes a while.
std::string large_print_scene() {
    const Result scene = run_process::run(SIMGEN_PATH, {"gas", "-n", "100000", "-s", "3", "--mode", "print"});
    CHECK_EQ(scene.status, 0);
    return scene.out;
}

// A signal as soon as the first temporary file exists: the trajectory's,
// made before the engine, or the output's, made before step 0 of a large
// scene is written. The run goes on to the end of its first step, stops
// there as from any step, and leaves no temporary file behind.
void signal_while_the_run_starts() {
    const ScratchDir dir;
    const std::string scene = large_print_scene();
    const std::string out = dir / "out.txt", trajectory = dir / "t.xyz";
    write_file(out, "the previous result\n");
    const Result at_output = simcli_run({"-t", "1", "-o", out}, scene, {SIGINT, 0, dir / ".out.txt.simcli-{pid}.tmp"});
    CHECK_EQ(at_output.status, 128 + SIGINT);
    CHECK(at_output.err.find("simcli: interrupted after step 1 of 3; " + out + " left as it was") == 0);
    const Result at_trajectory = simcli_run({"-t", "1", "-o", out, "--trajectory", trajectory}, scene,
                                            {SIGINT, 0, dir / ".t.xyz.simcli-{pid}.tmp"});
    CHECK_EQ(at_trajectory.status, 128 + SIGINT);
    CHECK(at_trajectory.err.find("simcli: interrupted after step 1 of 3; " + out + " and " + trajectory +
                                 " left as they were") == 0);
    CHECK(run_process::slurp(out) == "the previous result\n");
    CHECK_EQ(dir.file_count(), 1U);
}

// A signal simcli was started ignoring (nohup; a shell's background job and
// SIGINT) stays ignored: the run goes on to its end.
void signal_started_ignored_stays_ignored() {
    const ScratchDir dir;
    const std::string scene = large_print_scene();
    const Result whole = simcli_run({"-t", "1"}, scene);
    CHECK_EQ(whole.status, 0);
    const std::string out = dir / "out.txt";
    for (const int signal : {SIGINT, SIGHUP}) {
        check::Context context("signal ", signal);
        struct sigaction ignore {};
        struct sigaction before {};
        ignore.sa_handler = SIG_IGN;
        sigemptyset(&ignore.sa_mask);
        sigaction(signal, &ignore, &before);  // inherited by the child
        const Result ignored =
            simcli_run({"-t", "1", "-o", out}, scene, {signal, 0, dir / ".out.txt.simcli-{pid}.tmp"});
        sigaction(signal, &before, nullptr);
        CHECK_EQ(ignored.status, 0);
        CHECK(ignored.err.empty());
        CHECK(run_process::slurp(out) == whole.out);
    }
}

void progress_line() {
    // Seconds of work; the line comes at the pace asked for, only when forced off a terminal.
    const std::string scene = "4000 800 1 100000 perf\n";
    const Result paced = simcli_run({"--progress-every", "0.2", "-t", "1"}, scene, {SIGINT, 900});
    CHECK(paced.err.find("simcli: step ") == 0);
    CHECK(paced.err.find(" of 100000 (") != std::string::npos);
    CHECK(paced.err.find(" steps/s, about ") != std::string::npos);
    // Lines at about 0.2, 0.4, 0.6 and 0.8 s of its run: more than one, as plain lines.
    const auto lines = std::count(paced.err.begin(), paced.err.end(), '\n');
    CHECK(lines >= 2 && lines <= 6);
    CHECK(paced.out.find("0 0 ") == 0);  // nothing of it on stdout
    // The default pace: nothing before about two seconds, then a line.
    const Result early = simcli_run({"--progress", "-t", "1"}, scene, {SIGINT, 1000});
    CHECK(early.err.find("simcli: step ") == std::string::npos);
    CHECK(early.err.find("simcli: interrupted after step ") == 0);
    // A resting disk for 2^63 - 1 steps shows its (very long) way, without overflow.
    const Result endless =
        simcli_run({"--progress-every", "0.2"}, "1 20 1 9223372036854775807 perf\n0 5 5 0 0\n", {SIGINT, 700});
    CHECK_EQ(endless.status, 130);
    CHECK(endless.err.find("simcli: step ") == 0);
    CHECK(endless.err.find(" years left") != std::string::npos);
    const Result automatic = simcli_run({"-t", "1"}, scene, {SIGINT, 2500});
    CHECK(automatic.err.find("simcli: step ") == std::string::npos);  // stderr is a file here
    CHECK(automatic.err.find("simcli: interrupted after step ") == 0);
}

void bad_usage() {
    const ScratchDir dir;
    const auto rejected = [](const std::vector<std::string>& args, const std::string& fragment) {
        const Result r = simcli_run(args, "2 20 1 3 perf\n");
        CHECK_EQ(r.status, 2);
        CHECK(r.out.empty());
        CHECK(r.err.find(fragment) != std::string::npos);
        if (r.err.find(fragment) == std::string::npos) std::fprintf(stderr, "  stderr was: %s", r.err.c_str());
    };
    rejected({"--checkpoint-every", "5"}, "--checkpoint-every K needs --checkpoint FILE");
    rejected({"--progress", "--quiet"}, "contradict");
    rejected({"--progress-every", "5", "--quiet"}, "contradict");
    for (const char* pace : {"0", "-1", "nan", "1e9", "2s", ""}) {
        rejected({"--progress-every", pace}, "--progress-every: expected seconds from 0.001 to 3.2e7");
    }
    rejected({"--resume", dir / "none", "scene.in"}, "takes no scene file");
    rejected({"--resume", dir / "none", "--engine", "exact"}, "come from the checkpoint");
    rejected({"--resume", dir / "none"}, "cannot open the checkpoint");
    rejected({"--resume", dir / "."}, dir / ".: is a directory");
    write_file(dir / "bad",
               "particlesim-checkpoint 1\nbox-size 20 radius 1 steps 3 mode perf engine step substeps 1 "
               "numbers fixed8\nstepped-engine-state 1\n5 0 0 0 0\n1 1 0 0 0 0\n");
    rejected({"--resume", dir / "bad"}, "the saved state is damaged");
    write_file(dir / "other", "something else\n");
    rejected({"--resume", dir / "other"}, "not a checkpoint simcli can resume");
    // The observables are the exact engine's, after a checkpoint too.
    const std::string stepped = dir / "stepped.checkpoint";
    CHECK_EQ(simcli_run({"--checkpoint", stepped, "--checkpoint-every", "2"}, "20 60 1 3 perf\n").status, 0);
    rejected({"--resume", stepped, "--observables", dir / "rows.csv"},
             "--observables needs the exact engine; " + stepped + " is a checkpoint of the step engine");
    rejected({"--resume", stepped, "--animate", dir / "page.html"}, "--animate and --snapshot need the whole run");
    // A first part whose file's path is not whole hexadecimal bytes.
    const std::string with_output = dir / "output.checkpoint";
    CHECK_EQ(
        simcli_run({"-o", dir / "o.out", "--checkpoint", with_output, "--checkpoint-every", "2"}, "20 60 1 3 perf\n")
            .status,
        0);
    std::string damaged = run_process::slurp(with_output);
    const std::size_t line_end = damaged.find(" \nobservables-row");
    CHECK(line_end != std::string::npos);
    if (line_end != std::string::npos) damaged.insert(line_end, "f");
    write_file(with_output, damaged);
    rejected({"--resume", with_output}, "a bad path");
    // A checkpoint whose steps left would take the exact engine more events
    // than it allows (one disk made a trillion times faster) is refused
    // before it runs, as such a scene is, instead of running for days.
    const std::string exact = dir / "exact.checkpoint";
    CHECK_EQ(
        simcli_run({"--engine", "exact", "--checkpoint", exact, "--checkpoint-every", "4"}, "20 60 1 6 perf\n").status,
        0);
    std::string saved = run_process::slurp(exact);
    std::size_t at = saved.find("exact-engine-state");
    for (int line = 0; line < 2; ++line) at = saved.find('\n', at) + 1;  // past the state's header and counts
    // The first disk's line: x y vx vy, its two counters, its time stamp, ...
    const std::size_t disk_line_end = saved.find('\n', at);
    std::istringstream disk_line(saved.substr(at, disk_line_end - at));
    std::vector<std::string> fields;
    for (std::string field; disk_line >> field;) fields.push_back(field);
    CHECK(fields.size() > 7);
    if (fields.size() <= 7) return;
    // Moved to the saved step (4), stamped there, then sped up: a state whose
    // disks are all in place, but one far too fast.
    const double stamp = std::stod(fields[6]);
    for (int axis = 0; axis < 2; ++axis) {
        char moved[32];
        std::snprintf(moved, sizeof moved, "%.17g",
                      std::stod(fields[axis]) + std::stod(fields[2 + axis]) * (4.0 - stamp));
        fields[axis] = moved;
    }
    fields[6] = "4";
    fields[2] = "1e12";
    std::string edited;
    for (const std::string& field : fields) edited += (edited.empty() ? "" : " ") + field;
    saved.replace(at, disk_line_end - at, edited);
    write_file(exact, saved);
    rejected({"--resume", exact}, "the exact engine would need about");
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_cli_interrupts",
                      {{"checkpoint every K resumes byte for byte", checkpoint_every_k_resumes_byte_for_byte},
                       {"signals, checkpoint and resume", signals_checkpoint_and_resume},
                       {"resumed stats count the resumed steps", resumed_stats_count_the_resumed_steps},
                       {"a checkpoint from stdin", a_checkpoint_from_stdin},
                       {"observables and trajectory resume", observables_and_trajectory_resume},
                       {"killed run resumes from its last checkpoint", killed_run_resumes_from_its_last_checkpoint},
                       {"last periodic checkpoint cuts the output back", last_periodic_checkpoint_cuts_the_output_back},
                       {"stdout to a file is cut back too", stdout_file_cut_back_too},
                       {"resume never writes over its first part", resume_never_writes_over_its_first_part},
                       {"output file replaced only on success", output_file_replaced_only_on_success},
                       {"exact numbers", exact_numbers},
                       {"second signal stops at once", second_signal_stops_at_once},
                       {"signal while the run starts", signal_while_the_run_starts},
                       {"signal started ignored stays ignored", signal_started_ignored_stays_ignored},
                       {"progress line", progress_line},
                       {"bad usage", bad_usage}});
}
