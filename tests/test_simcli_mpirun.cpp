// simcli under mpirun against simcli in one process: the same bytes on
// stdout and in -o files, the same --stats counts, the same refusals (one
// line, exit 2), a checkpoint written at 3 ranks continued at 5 and in one
// process, an interrupted run that keeps whole blocks and continues (and
// one on standard output, which mpirun stops forwarding, that still writes
// its checkpoint), and an unwritable output that stops every rank with one message; and simcli
// itself free of MPI, running its sibling simcli-mpi under a launcher.

#include "check.hpp"
#include "checkpoint_text.hpp"
#include "run_process.hpp"

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::string simcli = SIMCLI_PATH;
const std::string simcli_mpi = SIMCLI_MPI_PATH;
const std::string mpirun = MPIEXEC_PATH;
const std::string readelf = READELF_PATH;
const std::string examples = PARTICLESIM_EXAMPLES_DIR;

std::filesystem::path work_dir() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "particlesim-simcli-mpirun";
    std::filesystem::create_directories(dir);
    return dir;
}

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = (work_dir() / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// `simcli ARGS` on `ranks` ranks (-q: mpirun's own notices of a non-zero exit left out).
run_process::Result on_ranks(int ranks, const std::vector<std::string>& args, run_process::Signal signal = {}) {
    std::vector<std::string> all{"-q", "-np", std::to_string(ranks), simcli};
    all.insert(all.end(), args.begin(), args.end());
    return run_process::run(mpirun, all, "", "", false, signal);
}

run_process::Result one_process(const std::vector<std::string>& args) { return run_process::run(simcli, args); }

long lines_starting(const std::string& text, const std::string& start) {
    long count = 0;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) count += line.rfind(start, 0) == 0 ? 1 : 0;
    return count;
}

// The lines of `output` whose step is above `step`.
std::string after_step(const std::string& output, long step) {
    std::istringstream in(output);
    std::string kept;
    for (std::string line; std::getline(in, line);) {
        if (std::stol(line.substr(0, line.find(' '))) > step) kept += line + "\n";
    }
    return kept;
}

// `count` disks within 1e-6 of the box's centre, where the ranks' cuts
// fall: every approaching pair a candidate at t = 0, most of them shared
// between ranks. 700 disks crowd the grid's first slice, which stops each
// rank's search until rank 0 has decided those pairs from the disks (with
// the brute force, they make more candidates than the searches keep, to
// the same end); 80 make fewer, the rounds stall, and rank 0 decides the
// rest from the candidates. The first three disks
// sit on the left wall moving into it (a wall collision at t = 0: no pair
// at t = 0), so that the disks that may pair hold some of the indices only.
std::string pile_across_the_cuts(int count) {
    std::string text = std::to_string(count + 3) + "\n20000\n1\n3\nprint\n";
    for (int i = 0; i < 3; ++i) text += std::to_string(i) + " 1 " + std::to_string(5000 + 10 * i) + " -3 1\n";
    std::uint64_t state = 4;
    const auto uniform = [&](double low, double high) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return low + (high - low) * static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < count; ++i) {
        char line[160];
        // One draw a statement: the order of a call's arguments is the compiler's.
        const double x = 10000 + uniform(-1e-6, 1e-6);
        const double y = 10000 + uniform(-1e-6, 1e-6);
        const double vx = uniform(-5, 5);
        const double vy = uniform(-5, 5);
        std::snprintf(line, sizeof line, "%d %.17g %.17g %.17g %.17g\n", i + 3, x, y, vx, vy);
        text += line;
    }
    return write_file("pile_of_" + std::to_string(count) + "_across_the_cuts.in", text);
}

// Disks piled on one to three points among a gas (some on the left wall,
// moving into it), L = 400, r = 1, at speeds from 1 to 100 a step: a pile
// may lie on one rank beside another rank's disks, which then holds
// candidates with the pile's disks that the pile's rank left out of its
// search once their pairs at t = 0 were decided.
std::string piles_among_a_gas(std::uint64_t seed) {
    std::uint64_t state = seed * 2654435761ULL + 1;
    const auto uniform = [&](double low, double high) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return low + (high - low) * static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    const int count = 2000 + static_cast<int>(uniform(0, 2500));
    const int piles = 1 + static_cast<int>(uniform(0, 3));
    double pile_x[3], pile_y[3];
    for (int k = 0; k < piles; ++k) {
        pile_x[k] = uniform(1, 399);
        pile_y[k] = uniform(1, 399);
    }
    std::string text = std::to_string(count) + "\n400\n1\n3\nprint\n";
    for (int i = 0; i < count; ++i) {
        const double kind = uniform(0, 1);
        double x = uniform(1, 399), y = uniform(1, 399);
        if (kind < 0.5) {
            const int k = std::min(piles - 1, static_cast<int>(uniform(0, piles)));
            x = std::clamp(pile_x[k] + uniform(-1e-6, 1e-6), 1.0, 399.0);
            y = std::clamp(pile_y[k] + uniform(-1e-6, 1e-6), 1.0, 399.0);
        } else if (kind < 0.55) {
            x = 1;
        }
        const double speeds[] = {1, 5, 50, 100};
        const double speed = speeds[std::min(3, static_cast<int>(uniform(0, 4)))];
        const double vx = uniform(-speed, speed);
        const double vy = uniform(-speed, speed);
        char line[160];
        std::snprintf(line, sizeof line, "%d %.17g %.17g %.17g %.17g\n", i, x, y, vx, vy);
        text += line;
    }
    return write_file("piles_among_a_gas_" + std::to_string(seed) + ".in", text);
}

void the_same_bytes_as_one_process() {
    const std::vector<std::string> scenes{examples + "/newtons_cradle.in",
                                          examples + "/head_on.in",
                                          examples + "/default.in",
                                          write_file("random_print.in", "400\n300\n1\n40\nprint\n"),
                                          write_file("random_perf.in", "3000\n900\n1\n60\nperf\n"),
                                          pile_across_the_cuts(700),
                                          pile_across_the_cuts(80)};
    const std::string pile = scenes[5];
    const run_process::Result brute_force = on_ranks(2, {"--broadphase", "brute", pile});
    CHECK_EQ(brute_force.status, 0);
    CHECK(brute_force.out == one_process({pile}).out);
    for (const std::uint64_t seed : {1, 7, 20}) {
        const std::string piles = piles_among_a_gas(seed);
        const run_process::Result expected = one_process({piles});
        CHECK_EQ(expected.status, 0);
        for (const int ranks : {2, 3}) {
            const check::Context context(piles + " on " + std::to_string(ranks) + " ranks");
            const run_process::Result got = on_ranks(ranks, {piles});
            CHECK_EQ(got.status, 0);
            CHECK(got.out == expected.out);
        }
    }
    for (const std::string& scene : scenes) {
        const run_process::Result expected = one_process({scene});
        CHECK_EQ(expected.status, 0);
        // More ranks than this machine's two cores wait on each other at
        // every exchange: the thousand-step scene and the examples on two only.
        const bool on_two = scene.find("examples") != std::string::npos;
        for (const int ranks : on_two ? std::vector<int>{2} : std::vector<int>{2, 3}) {
            const check::Context context(scene + " on " + std::to_string(ranks) + " ranks");
            const run_process::Result got = on_ranks(ranks, {scene});
            CHECK_EQ(got.status, 0);
            CHECK(got.out == expected.out);
            CHECK_EQ(got.err, std::string());
        }
    }
    // Two threads a rank, substeps, a seed, exact numbers.
    const std::string scene = write_file("options.in", "800\n200\n1\n25\nprint\n");
    const std::vector<std::string> options{"-t", "2", "--substeps", "2", "--seed", "99", "--exact-numbers", scene};
    const run_process::Result expected = one_process(options);
    const run_process::Result got = on_ranks(2, options);
    CHECK_EQ(got.status, 0);
    CHECK(got.out == expected.out);
}

void output_file_and_stats() {
    const std::string scene = write_file("stats.in", "1500\n500\n1\n30\nperf\n");
    const std::string file = (work_dir() / "ranks.out").string();
    std::filesystem::remove(file);
    const run_process::Result expected = one_process({"--stats", scene});
    const run_process::Result got = on_ranks(3, {"--stats", "-o", file, scene});
    CHECK_EQ(got.status, 0);
    CHECK(run_process::slurp(file) == expected.out);
    // Nothing left beside the file (its temporary was renamed over it).
    long beside = 0;
    for (const auto& entry : std::filesystem::directory_iterator(work_dir())) {
        beside += entry.path().filename().string().rfind("ranks.out", 0) == 0 ? 1 : 0;
    }
    CHECK_EQ(beside, 1L);
    // The counts and the energy drift are the whole run's, as one process prints them.
    std::istringstream lines(expected.err);
    for (std::string line; std::getline(lines, line);) {
        if (line.find("collisions") != std::string::npos || line.find("energy drift") != std::string::npos) {
            CHECK(got.err.find(line) != std::string::npos);
        }
    }
    CHECK(got.err.find("ranks 3") != std::string::npos);
}

void refusals_are_one_line_and_exit_two() {
    const std::string bad = write_file("bad.in", "3\n10\n1\n5\nprint\n0 2 3 4\n");
    const run_process::Result expected = one_process({bad});
    CHECK_EQ(expected.status, 2);
    for (const int ranks : {3}) {
        const run_process::Result got = on_ranks(ranks, {bad});
        CHECK_EQ(got.status, 2);
        CHECK_EQ(got.err, expected.err);
        CHECK_EQ(got.out, std::string());
    }
    const run_process::Result option = on_ranks(3, {"--substeps", "0", bad});
    CHECK_EQ(option.status, 2);
    CHECK_EQ(lines_starting(option.err, "simcli: "), 1L);
    const run_process::Result exact = on_ranks(2, {"--engine", "exact", examples + "/head_on.in"});
    CHECK_EQ(exact.status, 2);
    CHECK_EQ(lines_starting(exact.err, "simcli: --engine exact runs on one process"), 1L);
    CHECK_EQ(lines_starting(exact.err, "simcli: "), 1L);
    // A checkpoint that could not be written when due is refused before the run.
    const run_process::Result checkpoint = on_ranks(
        2, {"--checkpoint", "/nonexistent/run.checkpoint", "--checkpoint-every", "2", examples + "/head_on.in"});
    CHECK_EQ(checkpoint.status, 2);
    CHECK_EQ(lines_starting(checkpoint.err, "simcli: /nonexistent/run.checkpoint: cannot create"), 1L);
    CHECK_EQ(checkpoint.out, std::string());
    // One rank is simcli as without MPI: the exact engine runs.
    const run_process::Result one_rank = on_ranks(1, {"--engine", "exact", examples + "/head_on.in"});
    CHECK_EQ(one_rank.status, 0);
    CHECK(one_rank.out == one_process({"--engine", "exact", examples + "/head_on.in"}).out);
}

void checkpoint_at_three_ranks_resumed_at_five() {
    const std::string scene = write_file("resume.in", "600\n250\n1\n25\nprint\n");
    const std::string checkpoint = (work_dir() / "resume.checkpoint").string();
    const std::string first = (work_dir() / "first.out").string();
    const run_process::Result expected = one_process({scene});
    const run_process::Result run =
        on_ranks(3, {"--checkpoint", checkpoint, "--checkpoint-every", "10", "-o", first, scene});
    CHECK_EQ(run.status, 0);
    CHECK(run_process::slurp(first) == expected.out);
    // The last checkpoint is at step 20: the rest of the run from there.
    const run_process::Result resumed = on_ranks(5, {"--resume", checkpoint});
    CHECK_EQ(resumed.status, 0);
    CHECK(resumed.out == after_step(expected.out, 20));
    const run_process::Result in_one_process = one_process({"--resume", checkpoint});
    CHECK(in_one_process.out == after_step(expected.out, 20));
}

void an_interrupted_run_keeps_whole_blocks_and_goes_on() {
    const long particles = 300;
    const std::string scene = write_file("long.in", "300\n250\n1\n4000\nprint\n");
    const std::string checkpoint = (work_dir() / "long.checkpoint").string();
    const std::string output = (work_dir() / "long.out").string();
    std::filesystem::remove(checkpoint);
    // Interrupted once the first checkpoint (step 40 of 4000) is there: mid-run on any machine.
    const run_process::Result got =
        on_ranks(3, {"--checkpoint", checkpoint, "--checkpoint-every", "40", "-o", output, scene},
                 run_process::Signal{SIGINT, 0, checkpoint});
    // mpirun answers the signal with a status of its own; the ranks stop as one process does.
    CHECK(got.status != 0);
    CHECK_EQ(lines_starting(got.err, "simcli: interrupted after step "), 1L);
    CHECK_EQ(lines_starting(got.err, "simcli: "), 1L);
    // The output ends at a whole step, and the checkpoint goes on from it.
    const std::string first = run_process::slurp(output);
    CHECK(!first.empty() && first.back() == '\n');
    const std::size_t last_line = first.rfind('\n', first.size() - 2) + 1;
    const long last_step = std::stol(first.substr(last_line, first.find(' ', last_line) - last_line));
    CHECK(last_step > 0 && last_step < 4000);
    CHECK_EQ(static_cast<long>(std::count(first.begin(), first.end(), '\n')), (last_step + 1) * particles);
    // Continued at two ranks, cut short (a busy core makes every step's
    // exchange wait): the two parts are one process's run of that length.
    const long end = last_step + 20;
    const bool cut_short = checkpoint_text::set_steps(checkpoint, 4000, end);
    CHECK(cut_short);
    if (!cut_short) return;
    const run_process::Result rest = on_ranks(2, {"--resume", checkpoint});
    CHECK_EQ(rest.status, 0);
    const std::string short_scene = write_file("short.in", "300\n250\n1\n" + std::to_string(end) + "\nprint\n");
    CHECK(first + rest.out == one_process({short_scene}).out);
}

// The same run with its output on standard output, which mpirun forwards
// from a terminal it stops reading when it is signalled (and signals the
// ranks a second later, kills them a second after that): rank 0 may be
// waiting in a write that nobody reads. The checkpoint is still written and
// the message says how far the output can be trusted; what arrived is the
// start of the run's output, and the checkpoint goes on from its step.
void an_interrupted_run_on_standard_output_still_checkpoints() {
    const std::string scene = write_file("forwarded.in", "300\n250\n1\n4000\nprint\n");
    const std::string checkpoint = (work_dir() / "forwarded.checkpoint").string();
    std::filesystem::remove(checkpoint);
    const run_process::Result got = on_ranks(3, {"--checkpoint", checkpoint, "--checkpoint-every", "40", scene},
                                             run_process::Signal{SIGINT, 0, checkpoint});
    CHECK(got.status != 0);
    CHECK_EQ(lines_starting(got.err, "simcli: "), 1L);
    const std::string said = "simcli: interrupted after step ";
    const std::size_t at = got.err.find(said);
    CHECK(at != std::string::npos);
    if (at == std::string::npos) return;
    const long step = std::stol(got.err.substr(at + said.size()));
    CHECK(step >= 40 && step < 4000);
    CHECK(got.err.find("standard output went through the MPI launcher") != std::string::npos);
    CHECK(got.err.find("the checkpoint holds step " + std::to_string(step)) != std::string::npos);
    const long end = step + 20;
    const bool cut_short = checkpoint_text::set_steps(checkpoint, 4000, end);
    CHECK(cut_short);
    if (!cut_short) return;
    const std::string short_scene =
        write_file("forwarded_short.in", "300\n250\n1\n" + std::to_string(end) + "\nprint\n");
    const std::string expected = one_process({short_scene}).out;
    CHECK(got.out.size() < expected.size() && expected.compare(0, got.out.size(), got.out) == 0);
    const run_process::Result rest = on_ranks(2, {"--resume", checkpoint});
    CHECK_EQ(rest.status, 0);
    CHECK(rest.out == after_step(expected, step));
}

// The run's last periodic checkpoint (step 60 of 70) stands for a run
// killed after it: the output holds steps past it, and --resume on other
// ranks cuts it back to the checkpoint's step, so the two parts join.
void the_last_periodic_checkpoint_cuts_the_output_back() {
    const std::string scene = write_file("killed.in", "300\n250\n1\n70\nprint\n");
    const std::string checkpoint = (work_dir() / "killed.checkpoint").string();
    const std::string output = (work_dir() / "killed.out").string();
    CHECK_EQ(on_ranks(3, {"--checkpoint", checkpoint, "--checkpoint-every", "30", "-o", output, scene}).status, 0);
    const std::string whole = run_process::slurp(output);
    // The rest written over the first part would replace it: refused, as in one process.
    const run_process::Result over = on_ranks(2, {"--resume", checkpoint, "-o", output});
    CHECK_EQ(over.status, 2);
    CHECK(over.err.find("-o " + output + " holds the first part of the run, up to step 60") != std::string::npos);
    CHECK(run_process::slurp(output) == whole);
    const run_process::Result rest = on_ranks(2, {"--resume", checkpoint});
    CHECK_EQ(rest.status, 0);
    CHECK(rest.err.find("killed.out cut back to the checkpoint's step 60") != std::string::npos);
    CHECK(run_process::slurp(output) + rest.out == whole);
    CHECK(whole == one_process({scene}).out);
}

void an_unwritable_output_stops_every_rank() {
    const std::string scene = write_file("full.in", "500\n200\n1\n20\nprint\n");
    const run_process::Result expected = one_process({"-o", "/dev/full", scene});
    const run_process::Result got = on_ranks(3, {"-o", "/dev/full", scene});
    CHECK_EQ(expected.status, 1);
    CHECK_EQ(got.status, 1);
    CHECK_EQ(got.err, expected.err);
}

// A rank that runs out of memory names it, and every rank stops: a random
// scene of 6 million disks under a 600 MB address space.
void running_out_of_memory_on_a_rank_is_named() {
#if defined(__SANITIZE_ADDRESS__)
    std::printf("under AddressSanitizer, which reserves terabytes of address space: not checked\n");
#else
    const std::string scene = write_file("six_million.in", "6000000 300000 1 1 perf\n");
    const run_process::Result got = run_process::run(
        "/bin/sh", {"-c", "ulimit -v 600000 && exec \"$0\" \"$@\"", mpirun, "-q", "-np", "2", simcli, scene}, "", "",
        false);
    CHECK_EQ(got.status, 1);
    CHECK(got.out.empty());
    // Each rank that ran out says so in one line.
    const long lines = lines_starting(got.err, "");
    CHECK(lines >= 1 && lines <= 2);
    CHECK_EQ(lines_starting(got.err, "simcli: rank "), lines);
    std::istringstream said(got.err);
    for (std::string line; std::getline(said, line);) {
        CHECK(line.find(": out of memory while running (") != std::string::npos);
        CHECK(line.ends_with("; stopping every rank"));
    }
#endif
}

// simcli itself links no MPI (a run outside a launcher loads none of it);
// under a launcher it runs simcli-mpi beside it, and without that sibling it
// says so and stops instead of running every rank as a whole run.
void simcli_loads_no_mpi() {
    const run_process::Result own = run_process::run(readelf, {"-d", simcli});
    const run_process::Result sibling = run_process::run(readelf, {"-d", simcli_mpi});
    CHECK_EQ(own.status, 0);
    CHECK(own.out.find("(NEEDED)") != std::string::npos);
    CHECK(own.out.find("libmpi") == std::string::npos);
    CHECK(sibling.out.find("libmpi") != std::string::npos);

    const std::filesystem::path alone = work_dir() / "alone";
    std::filesystem::create_directories(alone);
    const std::filesystem::path copy = alone / "simcli";
    std::filesystem::copy_file(simcli, copy, std::filesystem::copy_options::overwrite_existing);
    const std::string scene = write_file("alone.in", "4\n100\n1\n2\nprint\n");
    const run_process::Result launched =
        run_process::run("/usr/bin/env", {"OMPI_COMM_WORLD_SIZE=1", copy.string(), scene});
    CHECK_EQ(launched.status, 1);
    CHECK_EQ(launched.out, "");
    CHECK(launched.err.find("started by an MPI launcher, but cannot start") != std::string::npos);
    CHECK(launched.err.find("simcli-mpi") != std::string::npos);
    CHECK_EQ(one_process({scene}).status, 0);  // the same simcli outside a launcher runs
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(
        argc, argv, "test_simcli_mpirun",
        {{"the same bytes as one process", the_same_bytes_as_one_process},
         {"an output file and the stats", output_file_and_stats},
         {"refusals are one line and exit 2", refusals_are_one_line_and_exit_two},
         {"a checkpoint at 3 ranks resumed at 5", checkpoint_at_three_ranks_resumed_at_five},
         {"an interrupted run keeps whole blocks", an_interrupted_run_keeps_whole_blocks_and_goes_on},
         {"an interrupted run on standard output still checkpoints",
          an_interrupted_run_on_standard_output_still_checkpoints},
         {"the last periodic checkpoint cuts the output back", the_last_periodic_checkpoint_cuts_the_output_back},
         {"running out of memory on a rank is named", running_out_of_memory_on_a_rank_is_named},
         {"an unwritable output stops every rank", an_unwritable_output_stops_every_rank},
         {"simcli loads no MPI", simcli_loads_no_mpi}});
}
