// simcheck grade: a suite run on simcli (everything conforms), on the
// textbook implementation with its classic mistakes (each "wrong" at the step
// plain simcheck names for the same output) and with the last block printed
// twice ("shape"), and on programs that misbehave: one that sleeps for ever,
// writes for ever, segfaults, prints garbage, exits 3 after a correct output,
// leaves a child holding stdout open, or looks at and writes into its working
// directory. Each gets its verdict, and the grader neither hangs nor leaves
// anything behind.

#include "check.hpp"
#include "mini_json.hpp"
#include "run_process.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <netinet/in.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/ipc.h>
#include <sys/mount.h>
#include <sys/msg.h>
#include <sys/prctl.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string simcheck = SIMCHECK_PATH;
const std::string simcli = SIMCLI_PATH;
const std::string simgen = SIMGEN_PATH;
const std::string textbook = TEXTBOOK_SIMULATOR_PATH;

const fs::path& work() {
    static const fs::path dir = [] {
        std::string path = (fs::temp_directory_path() / "particlesim-grade-XXXXXX").string();
        if (!mkdtemp(path.data())) std::abort();
        // Run by root, the graded programs are users of their own: they note what they saw here.
        chmod(path.c_str(), 01777);
        return fs::path(path);
    }();
    return dir;
}

// Four small cases of simgen's suite (a touching row, the tie rules, a row
// into a wall, paths across the box), with their manifest.
const fs::path& small_suite() {
    static const fs::path dir = [] {
        const fs::path small = work() / "small";
        run_process::run(simgen, {"suite", small.string(), "--only", "cradle,ties,line,fast"});
        return small;
    }();
    return dir;
}

// The cradle's right output, outside the suite: the programs below that
// print it read it here (the suite's own copy is hidden from them where
// they run isolated).
std::string cradle_answer() {
    const fs::path answer = work() / "cradle-answer.out";
    if (!fs::exists(answer)) fs::copy_file(small_suite() / "01-cradle.out", answer);
    return answer.string();
}

// The first of them alone, without a manifest.
fs::path one_scene_suite() {
    const fs::path one = work() / "one";
    if (!fs::exists(one)) {
        fs::create_directories(one);
        fs::copy_file(small_suite() / "01-cradle.in", one / "01-cradle.in");
        fs::copy_file(small_suite() / "01-cradle.out", one / "01-cradle.out");
    }
    return one;
}

// An empty directory that the graded programs may write their notes into
// whichever user they run as (like /tmp), made afresh.
void fresh_shared_directory(const fs::path& path) {
    fs::remove_all(path);
    fs::create_directories(path);
    chmod(path.c_str(), 01777);
}

std::string script(const std::string& name, const std::string& body) {
    const fs::path path = work() / name;
    std::ofstream(path) << "#!/bin/sh\n" << body;
    chmod(path.c_str(), 0755);
    return path.string();
}

struct Graded {
    run_process::Result result;
    mini_json::Value json;
    double seconds = 0.0;
};

// `launcher`: a command that runs simcheck (none: simcheck itself).
Graded grade(const fs::path& suite, std::vector<std::string> options, const std::vector<std::string>& program,
             const std::vector<std::string>& launcher = {}) {
    const fs::path json = work() / "report.json";
    fs::remove(json);
    std::vector<std::string> args{"grade", suite.string(), "--json", json.string()};
#if defined(__SANITIZE_ADDRESS__)
    // AddressSanitizer's programs reserve terabytes of address space: no memory limit.
    args.insert(args.end(), {"--memory", "0"});
#endif
    args.insert(args.end(), options.begin(), options.end());
    args.emplace_back("--");
    args.insert(args.end(), program.begin(), program.end());
    const auto start = std::chrono::steady_clock::now();
    Graded g;
    if (launcher.empty()) {
        g.result = run_process::run(simcheck, args);
    } else {
        std::vector<std::string> launched(launcher.begin() + 1, launcher.end());
        launched.push_back(simcheck);
        launched.insert(launched.end(), args.begin(), args.end());
        g.result = run_process::run(launcher.front(), launched);
    }
    g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    try {
        g.json = mini_json::Parser(run_process::slurp(json.string())).parse();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "no JSON report: %s\n%s%s", e.what(), g.result.out.c_str(), g.result.err.c_str());
    }
    return g;
}

const mini_json::Value& scenes(const Graded& g) { return g.json["scenes"]; }

void reference_conforms_everywhere() {
    const fs::path markdown = work() / "report.md";
    // Under the sanitizers, this grade's simcheck and simclis check their own leaks at exit (a leak: exit 23).
    const Graded g = [&] {
        const run_process::ChildrenWithLeakChecks leak_checks;
        return grade(small_suite(), {"--markdown", markdown.string()}, {simcli, "{}"});
    }();
    CHECK_EQ(g.result.status, 0);
    CHECK_EQ(scenes(g).items.size(), std::size_t{4});
    for (const mini_json::Value& s : scenes(g).items) {
        CHECK_EQ(s["verdict"].text, std::string("conforms"));
        CHECK(s["step"].kind == mini_json::Value::Kind::null);
        CHECK_EQ(s["exit_status"].number, 0.0);
        CHECK(s["reference_seconds"].kind == mini_json::Value::Kind::number);
        CHECK(s["seconds"].number > 0.0);
        CHECK_EQ(s["left_running"].number, 0.0);
        CHECK_EQ(s["message"].text, std::string());
    }
    CHECK_EQ(scenes(g)[1]["scene"].text, std::string("02-ties"));
    CHECK(scenes(g)[1]["exercises"].text.rfind("exact ties", 0) == 0);
    CHECK(g.result.out.find("4 of 4 scenes conform") != std::string::npos);
    const std::string md = run_process::slurp(markdown.string());
    CHECK(md.find("| scene | exercises | verdict | first wrong step | seconds | x simcli |") != std::string::npos);
    CHECK(md.find("| 02-ties | exact ties") != std::string::npos);
    // A scene whose name holds the table's separator stays in its cell.
    const fs::path odd_suite = work() / "odd-suite";
    fs::create_directories(odd_suite);
    std::ofstream(odd_suite / "odd|name.in") << "2 20 1 3 print\n";
    const Graded odd = grade(odd_suite, {"--no-reference", "--markdown", markdown.string()}, {"/bin/true"});
    CHECK_EQ(odd.result.status, 1);
    const std::string odd_md = run_process::slurp(markdown.string());
    CHECK(odd_md.find("| odd\\|name |  | malformed |") != std::string::npos);
    CHECK(odd_md.find("- **odd\\|name** (malformed): ") != std::string::npos);
    // Side by side: the same verdicts, and the report says the times are shared.
    const Graded side = grade(small_suite(), {"--jobs", "2"}, {simcli, "{}"});
    CHECK_EQ(side.result.status, 0);
    CHECK(side.result.out.find("2 scenes ran side by side") != std::string::npos);
    // No more ran side by side than there are scenes.
    const Graded wide = grade(small_suite(), {"--jobs", "8", "--no-reference"}, {"/bin/true"});
    CHECK(wide.result.out.find("(4 scenes ran side by side") != std::string::npos);
    // Under the exact rules the default scene's steps are judged only where
    // they are not too chaotic within rounding: the row says how many were.
    const fs::path default_suite = work() / "default-suite";
    fs::create_directories(default_suite);
    std::ofstream(default_suite / "default.in") << "1000 20000 1 60 print\n";
    const Graded exact = grade(default_suite, {"--engine", "exact"}, {simcli, "--engine", "exact", "{}"});
    CHECK_EQ(exact.result.status, 0);
    CHECK_EQ(scenes(exact)[0]["verdict"].text, std::string("conforms"));
    const std::string judged = scenes(exact)[0]["message"].text;
    check::Context judged_context("message \"", judged, "\"");
    const int count = std::atoi(judged.c_str());
    CHECK(count > 0 && count < 60);
    CHECK_EQ(judged, std::to_string(count) + " of the 60 steps judged");
}

// The verdicts alone: no reference simcli is timed (--no-reference).
void textbook_mistakes_are_wrong_at_their_step() {
    const Graded right = grade(small_suite(), {"--no-reference"}, {textbook, "none"});
    CHECK_EQ(right.result.status, 0);
    int wrong_rows = 0;
    for (const char* mistake : {"no-stop-at-the-wall", "ties-broken-by-index-only", "two-collisions-per-step",
                                "counters-off-by-one", "a-dropped-line"}) {
        check::Context context(mistake);
        const Graded g = grade(small_suite(), {"--no-reference"}, {textbook, mistake});
        CHECK_EQ(g.result.status, 1);
        for (std::size_t k = 0; k < scenes(g).items.size(); ++k) {
            const mini_json::Value& s = scenes(g)[k];
            if (s["verdict"].text == "conforms") continue;  // the mistake made no difference here
            CHECK_EQ(s["verdict"].text, std::string("wrong"));
            ++wrong_rows;
            // Plain simcheck names the same first wrong step for the same output.
            const fs::path scene = small_suite() / (s["scene"].text + ".in");
            const run_process::Result out = run_process::run(textbook, {mistake}, run_process::slurp(scene.string()));
            const fs::path output = work() / "mistake.out";
            std::ofstream(output, std::ios::binary) << out.out;
            const run_process::Result plain = run_process::run(simcheck, {scene.string(), output.string()});
            CHECK_EQ(plain.status, 1);
            CHECK_EQ(plain.out.rfind("step " + std::to_string(static_cast<long long>(s["step"].number)) + ": ", 0),
                     std::size_t{0});
            CHECK(s["message"].text.rfind("step ", 0) == 0);
        }
    }
    CHECK(wrong_rows >= 5);
    // The peer's shape: the last step printed twice, the physics right.
    const Graded twice = grade(small_suite(), {"--no-reference"}, {textbook, "last-block-twice"});
    CHECK_EQ(twice.result.status, 1);
    for (const mini_json::Value& s : scenes(twice).items) {
        CHECK_EQ(s["verdict"].text, std::string("shape"));
        CHECK(s["message"].text.find("is printed twice") != std::string::npos);
        CHECK(s["message"].text.find("without counters was set aside") != std::string::npos);
    }
}

void misbehaving_programs_get_their_verdicts() {
    const fs::path suite = one_scene_suite();
    const std::string expected = cradle_answer();
    struct Case {
        std::string name, body, verdict;
        std::vector<std::string> options;
    };
    const std::vector<Case> cases{
        {"sleeps", "exec sleep 1000\n", "timeout", {"--timeout", "1"}},
        {"writes", "exec yes '0 0 1.00000000 1.00000000 1.00000000 1.00000000'\n", "output-limit", {}},
        {"segfaults", "kill -SEGV $$\n", "crashed", {}},
        {"garbage", "echo 'hello world'\n", "malformed", {}},
        {"silent", "exit 0\n", "malformed", {}},
        {"exit3", "cat '" + expected + "'\nexit 3\n", "exit-status", {}},
    };
    for (const Case& c : cases) {
        check::Context context(c.name);
        const Graded g = grade(suite, c.options, {script(c.name + ".sh", c.body)});
        CHECK_EQ(g.result.status, 1);
        CHECK_EQ(scenes(g)[0]["verdict"].text, c.verdict);
        CHECK(g.seconds < 20.0);
        if (c.verdict == "crashed") CHECK_EQ(scenes(g)[0]["signal"].number, static_cast<double>(SIGSEGV));
        if (c.verdict == "exit-status") {
            CHECK_EQ(scenes(g)[0]["exit_status"].number, 3.0);
            CHECK(scenes(g)[0]["message"].text.find("exit status 3 after an output judged conforms") !=
                  std::string::npos);
        }
        if (c.verdict == "timeout") CHECK(scenes(g)[0]["seconds"].number < 5.0);
    }
    // Its stderr's escape sequences (clear the screen, retitle the window, return to the line's start to
    // overwrite the verdict) reach neither the grader's terminal nor the reports: shown as \xNN.
    const std::string escapes = "printf '\\033[2J\\033]0;title\\007\\rconforms\\r\\n' >&2\nexit 3\n";
    const Graded g = grade(suite, {"--no-reference"}, {script("escapes.sh", escapes)});
    CHECK_EQ(scenes(g)[0]["verdict"].text, std::string("exit-status"));
    CHECK(scenes(g)[0]["message"].text.find("stderr: \\x1B[2J\\x1B]0;title\\x07\\x0Dconforms") != std::string::npos);
    const auto shows = [](const std::string& text) {
        return std::none_of(text.begin(), text.end(), [](char c) {
            const auto byte = static_cast<unsigned char>(c);
            return (byte < 0x20 && c != '\n') || byte == 0x7f;
        });
    };
    CHECK(shows(g.result.out));
    CHECK(shows(scenes(g)[0]["message"].text));
}

// The processes still running (not zombies: killed but not yet reaped by
// whoever adopted them) with `argument` among their arguments. By
// argument, not by pid: a program in a PID namespace of its own notes pids
// that mean nothing outside it.
int running_with_argument(const std::string& argument) {
    int running = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const std::string command = run_process::slurp((entry.path() / "cmdline").string());
        if (command.find('\0' + argument + '\0') == std::string::npos) continue;
        std::ifstream stat(entry.path() / "stat");
        std::string line;
        std::getline(stat, line);
        const std::size_t name_end = line.rfind(") ");
        if (name_end != std::string::npos && line[name_end + 2] != 'Z') ++running;
    }
    return running;
}

// Each file a program writes is capped (RLIMIT_FSIZE), and so are its
// files together: twelve files of 100 MiB (1.2 GiB allocated, past the
// smallest cap of 1 GiB) in its working directory, or, run as a user of
// its own, in $TMPDIR, and two of 600 MiB that it holds open after
// removing them (as a memfd is), stop it with output-limit long before its
// timeout, and nothing of them is left; so do directories nested deeper
// than the grader walks. fallocate allocates without writing, where the
// file system can.
void files_together_are_capped() {
    const std::string many =
        "i=0\nwhile [ $i -lt 12 ]; do\n  f={place}/filler-$$-$i\n"
        "  fallocate -l 100M \"$f\" 2>/dev/null || head -c 104857600 /dev/zero > \"$f\"\n"
        "  i=$((i + 1))\ndone\nexec sleep 1000.3\n";
    const std::string held_open =
        "t=\"${TMPDIR:-/tmp}\"/filler-$$\nexec 3>\"$t-1\" 4>\"$t-2\"\nrm \"$t-1\" \"$t-2\"\n"
        "for fd in 3 4; do\n"
        "  fallocate -l 600M /proc/self/fd/$fd 2>/dev/null || head -c 629145600 /dev/zero >&$fd\n"
        "done\nexec sleep 1000.3\n";
    const auto in = [](std::string body, const std::string& place) {
        body.replace(body.find("{place}"), 7, place);
        return body;
    };
    // Deeper than the grader walks: stopped as well, however little the directories hold.
    const std::string nested =
        "i=0\nwhile [ $i -lt 200 ]; do mkdir d && cd d || exit 1; i=$((i + 1)); done\n"
        "exec sleep 1000.3\n";
    const std::vector<std::pair<std::string, std::string>> cases{{"its directory", in(many, ".")},
                                                                 {"$TMPDIR", in(many, "\"${TMPDIR:-/tmp}\"")},
                                                                 {"held open, named nowhere", held_open},
                                                                 {"nested 200 deep", nested}};
    for (const auto& [place, body] : cases) {
        check::Context context(place);
        const Graded g = grade(one_scene_suite(), {"--timeout", "60", "--no-reference"}, {script("files.sh", body)});
        if (g.json.kind != mini_json::Value::Kind::object) continue;
        if (place == "$TMPDIR" && g.json["own_users"].number != 1.0) {
            std::printf("not run by root: files outside its directory are not counted, not checked\n");
            for (const fs::directory_entry& entry : fs::directory_iterator(fs::temp_directory_path()))
                if (entry.path().filename().string().rfind("filler-", 0) == 0) fs::remove(entry.path());
            continue;
        }
        CHECK_EQ(g.result.status, 1);
        CHECK_EQ(scenes(g)[0]["verdict"].text, std::string("output-limit"));
        const std::string stopped_when = place == "nested 200 deep"
                                             ? "stopped when it nested directories more than 64 deep"
                                             : "stopped when its files together held";
        CHECK(scenes(g)[0]["message"].text.find(stopped_when) != std::string::npos);
        if (place == "held open, named nowhere")
            CHECK(scenes(g)[0]["message"].text.find("and the files it held open that no directory names") !=
                  std::string::npos);
        CHECK(scenes(g)[0]["seconds"].number < 30.0);
        CHECK_EQ(running_with_argument("1000.3"), 0);
        std::size_t fillers = 0;
        for (const fs::directory_entry& entry : fs::directory_iterator(fs::temp_directory_path()))
            fillers += entry.path().filename().string().rfind("filler-", 0) == 0;
        CHECK_EQ(fillers, std::size_t{0});
    }
}

constexpr char hold_memory_option[] = "--hold-memory";

// test_grade --hold-memory KIND MEGABYTES: a graded program that holds that
// much memory where RLIMIT_AS does not count it together, then waits to be
// stopped: "resident" in itself (one of several such processes), "sockets"
// queued in socket pairs (as many as its descriptors allow), "pipes" a page
// a byte in pipes (MEGABYTES unused: as many as it may open), "shared" in
// System V shared memory segments it touches and detaches. Exit 3, with the
// reason on stderr, where it cannot.
int hold_memory(const std::string& kind, const char* megabytes_text) {
    const std::size_t bytes = std::strtoull(megabytes_text, nullptr, 10) << 20;
    if (kind == "resident") {
        static std::vector<char> held;
        held.assign(bytes, 1);
    } else if (kind == "sockets") {
        static char block[1 << 16];
        std::size_t queued = 0;
        while (queued < bytes) {
            int pair[2];
            if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0, pair) != 0) break;
            for (const int end : pair) {
                for (ssize_t wrote; (wrote = write(end, block, sizeof block)) > 0;)
                    queued += static_cast<std::size_t>(wrote);
            }
        }
    } else if (kind == "pipes") {
        // In packet mode each write takes a page of its own: 16 bytes hold 64 KiB.
        for (int pipe_ends[2]; pipe2(pipe_ends, O_DIRECT | O_NONBLOCK) == 0;) {
            for (int k = 0; k < 16; ++k) {
                if (write(pipe_ends[1], "x", 1) != 1) break;
            }
        }
    } else if (kind == "shared") {
        // In segments of 32 MB, each mapped only while it is touched: the address space never holds two.
        constexpr std::size_t segment_bytes = std::size_t{32} << 20;
        for (std::size_t held = 0; held < bytes; held += segment_bytes) {
            const int segment = shmget(IPC_PRIVATE, segment_bytes, IPC_CREAT | 0600);
            void* const mapped = segment < 0 ? reinterpret_cast<void*>(-1) : shmat(segment, nullptr, 0);
            if (mapped == reinterpret_cast<void*>(-1)) {
                std::fprintf(stderr, "cannot hold %s MB of System V shared memory: %s\n", megabytes_text,
                             std::strerror(errno));
                return 3;
            }
            std::memset(mapped, 1, segment_bytes);
            shmdt(mapped);
        }
    }
    for (;;) pause();
}

// Memory that RLIMIT_AS, which caps each process, does not count together:
// several processes under the cap each, buffers queued in socket pairs, and
// System V shared memory, which no process need map. Each is stopped (as a
// crash, named) once its processes together hold more than --memory; an
// isolated program's IPC namespace refuses shared memory past it. Pipes
// count a page for each byte waiting in them. Each
// process may hold at most 1024 descriptors.
void memory_together_is_capped() {
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    {
        check::Context context("descriptors");
        const std::string body =
            "n=$(ulimit -n)\n[ \"$n\" != unlimited ] && [ \"$n\" -le 1024 ] || "
            "{ echo \"ulimit -n: $n\" >&2; exit 9; }\ncat '" +
            cradle_answer() + "'\n";
        const Graded g = grade(one_scene_suite(), {"--no-reference"}, {script("descriptors.sh", body)});
        CHECK_EQ(g.result.status, 0);
        if (g.json.kind == mini_json::Value::Kind::object)
            CHECK_EQ(scenes(g)[0]["verdict"].text, std::string("conforms"));
    }
#if defined(__SANITIZE_ADDRESS__)
    std::printf("under AddressSanitizer, whose programs are graded with --memory 0: memory caps not checked\n");
#else
    const std::string hold = "'" + self + "' " + hold_memory_option;
    struct Case {
        std::string name, body;
        int megabytes;  // --memory
        std::vector<std::string> launcher;
    };
    std::vector<Case> cases{
        {"four processes of 60 MB", "for i in 1 2 3 4; do " + hold + " resident 60 & done\nwait\n", 160, {}},
        {"socket pairs", "exec " + hold + " sockets 1000\n", 160, {}},
        // 32 MB a process, below the 64 MB of full pipes a user may have (fs.pipe-user-pages-soft).
        {"pipes in packet mode, two processes", "for i in 1 2; do " + hold + " pipes 0 & done\nwait\n", 40, {}},
        {"System V shared memory", "exec " + hold + " shared 300\n", 160, {}}};
    if (geteuid() == 0)
        cases.push_back({"System V shared memory, root without CAP_SYS_ADMIN",
                         cases.back().body,
                         160,
                         {"/usr/bin/setpriv", "--inh-caps", "-all", "--bounding-set", "-sys_admin", "--"}});
    for (const Case& c : cases) {
        check::Context context(c.name);
        const Graded g =
            grade(one_scene_suite(), {"--timeout", "60", "--no-reference", "--memory", std::to_string(c.megabytes)},
                  {script("memory.sh", c.body)}, c.launcher);
        CHECK_EQ(g.result.status, 1);
        if (g.json.kind != mini_json::Value::Kind::object) continue;
        const mini_json::Value& scene = scenes(g)[0];
        const bool isolated = g.json["isolated"].number == 1.0, own_users = g.json["own_users"].number == 1.0;
        CHECK(scene["seconds"].number < 30.0);
        CHECK_EQ(running_with_argument(hold_memory_option), 0);
        if (c.name.find("System V") != std::string::npos) {
            if (isolated) {
                // Its IPC namespace holds no more than --memory: the segment is refused.
                CHECK_EQ(scene["verdict"].text, std::string("exit-status"));
                CHECK(scene["message"].text.find("cannot hold 300 MB of System V shared memory") != std::string::npos);
                continue;
            }
            if (!own_users) {
                std::printf("%s: not isolated and not root: System V memory not checked\n", c.name.c_str());
                continue;
            }
        }
        CHECK_EQ(scene["verdict"].text, std::string("crashed"));
        CHECK(scene["message"].text.find("stopped when its processes together held") != std::string::npos);
        const std::string cap =
            "bytes of memory, more than --memory (" + std::to_string(c.megabytes << 20) + "; counted:";
        CHECK(scene["message"].text.find(cap) != std::string::npos);
    }
#endif
}

// A name for each run of a grade, for the files a program notes: its
// working directory's (a fresh one each run), not its pid, which in a PID
// namespace of its own is the same in every run.
constexpr char run_name[] = "run=$(basename \"$PWD\")\n";

void a_child_holding_stdout_does_not_hang_the_grader() {
    // Its sleep is told by its argument.
    const std::string body = "cat '" + cradle_answer() + "'\nsleep 1000.1 &\nexit 0\n";
    const Graded g = grade(one_scene_suite(), {"--timeout", "30"}, {script("holder.sh", body)});
    CHECK_EQ(g.result.status, 0);
    CHECK_EQ(scenes(g)[0]["verdict"].text, std::string("conforms"));
    CHECK_EQ(scenes(g)[0]["left_running"].number, 1.0);
    CHECK_EQ(scenes(g)[0]["message"].text, std::string("it left 1 process running after it ended (killed)"));
    CHECK(g.seconds < 10.0);
    CHECK_EQ(running_with_argument("1000.1"), 0);
}

// What leaves the program's process group is killed too: a process detached
// by setsid and a daemon's double fork, one at a time and with
// runs side by side, the programs' own runs undisturbed.
void processes_that_leave_the_group_are_killed() {
    const fs::path pids = work() / "escaped";
    for (const std::string jobs : {"1", "2"}) {
        check::Context context("--jobs ", jobs);
        fresh_shared_directory(pids);
        // Each run notes both pids, and waits until the double fork is done before it runs simcli. Its sleeps
        // are told by their argument.
        const std::string body =
            std::string(run_name) + "d='" + pids.string() +
            "'\n"
            "setsid sleep 1000.2 </dev/null >/dev/null 2>&1 &\n"
            "echo $! > \"$d/$run.first\"\n"
            "(setsid sh -c 'sleep 1000.2 & echo $! > \"$0\"; exec sleep 1000.2' \"$d/$run.second\" "
            "</dev/null >/dev/null 2>&1 &)\n"
            "while [ ! -s \"$d/$run.second\" ]; do sleep 0.01; done\n"
            "exec '" +
            simcli + "'\n";
        const Graded g = grade(small_suite(), {"--jobs", jobs}, {script("escapes.sh", body)});
        CHECK_EQ(g.result.status, 0);
        for (std::size_t k = 0; k < scenes(g).items.size(); ++k) {
            CHECK_EQ(scenes(g)[k]["verdict"].text, std::string("conforms"));
            // Run alone, each left three (the two noted and the double fork's own sleep), all counted; side by
            // side, what left the group cannot be told apart by run, and is not counted, unless each run is
            // a user of its own or has a PID namespace of its own.
            const bool counted =
                jobs == "1" || g.json["own_users"].number == 1.0 || g.json["processes_hidden"].number == 1.0;
            CHECK_EQ(scenes(g)[k]["left_running"].number, counted ? 3.0 : 0.0);
        }
        std::size_t noted = 0;
        for (const fs::directory_entry& file : fs::directory_iterator(pids)) {
            pid_t pid = 0;
            if (std::ifstream(file.path()) >> pid) ++noted;
        }
        CHECK_EQ(noted, std::size_t{8});  // two a scene
        CHECK_EQ(running_with_argument("1000.2"), 0);
    }
}

std::string first_line(const fs::path& file) {
    std::string line;
    std::getline(std::ifstream(file), line);
    return line;
}

constexpr uid_t nobody = 65534;

// In a child of this test run by root: becomes nobody, with no groups and no capabilities.
bool become_nobody() {
    return setgroups(0, nullptr) == 0 && setresgid(nobody, nobody, nobody) == 0 &&
           setresuid(nobody, nobody, nobody) == 0;
}

// Runs simcheck as nobody (setpriv is util-linux's, on every Debian machine).
const std::vector<std::string> as_nobody{"/usr/bin/setpriv", "--reuid=65534",   "--regid=65534",
                                         "--clear-groups",   "--inh-caps=-all", "--"};

// What the programs of one grade saw, run as users of their own by root
// (`as_root`) or as the grader's user otherwise. `launcher` runs simcheck
// (setpriv to take capabilities away); `may_write_anywhere`: the program
// keeps CAP_DAC_OVERRIDE (no CAP_DAC_READ_SEARCH to keep).
void check_programs_as_users(const std::vector<std::string>& launcher, bool as_root, bool may_write_anywhere) {
    const fs::path notes = work() / "own-users";
    const fs::path private_dir = notes / "root-only";
    fresh_shared_directory(notes);
    fs::create_directory(private_dir);
    chmod(private_dir.c_str(), 0700);
    std::ofstream(private_dir / "secret") << "42\n";
    chmod((private_dir / "secret").c_str(), 0600);
    // Each run notes, by its run's name: its user, whether it may signal its parent (the grader, or the init of
    // its PID namespace), what it read of the secret, and the pids of the sleeps it started before fork failed
    // (at most 40; told by their argument).
    const std::string body =
        std::string(run_name) + "n='" + notes.string() + "'/$run\n" +
        "id -u > \"$n.user\"\n"
        "if kill -0 $PPID 2>/dev/null; then echo yes; else echo no; fi > \"$n.signal\"\n"
        "cat '" +
        (private_dir / "secret").string() +
        "' > \"$n.read\" 2>/dev/null\n"
        "(echo x > '" +
        (private_dir / "written").string() +
        "') 2>/dev/null\n"
        "echo junk > /tmp/particlesim-grade-junk-$run\n"
        "mkdir /var/tmp/particlesim-grade-junk-$run && echo junk > /var/tmp/particlesim-grade-junk-$run/f\n"
        "sh -c 'i=0; while [ $i -lt 40 ]; do sleep 30.3 & echo $! >> \"$0\"; i=$((i+1)); done' "
        "\"$n.started\" 2>/dev/null\n"
        "exit 4\n";
    // Side by side only as users of their own: one user's runs share the limit.
    const Graded g = grade(small_suite(), {"--jobs", as_root ? "2" : "1", "--processes", "6"},
                           {script("own-user.sh", body)}, launcher);
    CHECK_EQ(g.result.status, 1);
    CHECK(g.seconds < 30.0);
    CHECK_EQ(g.json["own_users"].number, as_root ? 1.0 : 0.0);
    std::size_t runs = 0;
    double sleeps_started = 0;
    for (const fs::directory_entry& file : fs::directory_iterator(notes)) {
        if (file.path().extension() != ".user") continue;
        ++runs;
        const fs::path base = file.path().parent_path() / file.path().stem();
        check::Context context("run ", base.filename().string());
        std::vector<pid_t> started;
        {
            std::ifstream in(base.string() + ".started");
            for (pid_t pid = 0; in >> pid;) started.push_back(pid);
        }
        // The script and its inner shell count too: 6 tasks added at most.
        CHECK(!started.empty());
        CHECK(started.size() <= 5);
        const std::string junk = "particlesim-grade-junk-" + base.filename().string();
        for (const fs::path& left : {fs::path("/tmp") / junk, fs::path("/var/tmp") / junk}) {
            CHECK_EQ(fs::exists(left), !as_root);
            fs::remove_all(left);
        }
        sleeps_started += static_cast<double>(started.size());
        if (as_root) {
            CHECK(first_line(file.path()) != "0");
            CHECK_EQ(first_line(base.string() + ".signal"), std::string("no"));
            CHECK_EQ(first_line(base.string() + ".read"), std::string("42"));
        }
    }
    CHECK_EQ(runs, std::size_t{4});
    CHECK_EQ(running_with_argument("30.3"), 0);
    // The sleeps stayed in the program's group: each is counted as left running.
    double left_running = 0;
    for (const mini_json::Value& scene : scenes(g).items) {
        left_running += scene["left_running"].number;
        // The file and the directory (not the run's own directory), told in the message.
        CHECK_EQ(scene["left_files"].number, as_root ? 2.0 : 0.0);
        if (as_root) CHECK(scene["message"].text.find("it left 2 files in /tmp") != std::string::npos);
    }
    CHECK_EQ(left_running, sleeps_started);
    if (as_root) CHECK_EQ(fs::exists(private_dir / "written"), may_write_anywhere);
}

// Run by root, each program is a user of its own: the process limit holds
// (root is exempt from RLIMIT_NPROC), it cannot signal the grader, it
// still reads a file only root may read (its own files under /root, say),
// it cannot write where only root may, and what it leaves in /tmp and
// /var/tmp is removed. Run by another user (nobody here), the process
// limit holds as RLIMIT_NPROC over that user's tasks (in its user
// namespace where it runs isolated).
void programs_run_by_root_are_users_of_their_own() {
    const bool root = geteuid() == 0;
    if (!root) std::printf("not run by root: checking the process limit only, the programs running as this user\n");
    check_programs_as_users({}, root, false);
    if (root) {
        {
            // Nobody runs other processes beside the grade, as a user's shells and editors are: the limit
            // still holds the program to what --processes adds.
            check::Context context("nobody");
            std::vector<pid_t> others;
            for (int k = 0; k < 12; ++k) {
                const pid_t other = fork();
                if (other == 0) {
                    if (become_nobody()) execl("/bin/sleep", "sleep", "60", static_cast<char*>(nullptr));
                    _exit(127);
                }
                others.push_back(other);
            }
            check_programs_as_users(as_nobody, false, false);
            for (const pid_t other : others) {
                kill(other, SIGKILL);
                waitpid(other, nullptr, 0);
            }
        }
        // A program only root may run is refused before any run, with what to do.
        const std::string closed = script("closed.sh", "exit 0\n");
        chmod(closed.c_str(), 0744);
        const run_process::Result refused = run_process::run(simcheck, {"grade", small_suite().string(), "--", closed});
        CHECK_EQ(refused.status, 2);
        CHECK(refused.err.find("chmod o+x") != std::string::npos);
    }
}

// Docker's default capabilities leave out CAP_DAC_READ_SEARCH: root there
// still runs each program as a user of its own, which keeps
// CAP_DAC_OVERRIDE instead (it reaches its files, and may write where root
// may).
void programs_run_by_root_without_read_search() {
    if (geteuid() != 0) {
        std::printf("not run by root: nothing to take away\n");
        return;
    }
    // util-linux's, on every Debian machine.
    const std::string setpriv = "/usr/bin/setpriv";
    CHECK(fs::exists(setpriv));
    check_programs_as_users({setpriv, "--inh-caps", "-all", "--bounding-set", "-dac_read_search", "--"}, true, true);
}

// Connections made to `listener` so far (it does not block).
int connections_made(int listener) {
    int made = 0;
    for (int client; (client = accept(listener, nullptr, nullptr)) >= 0; ++made) close(client);
    return made;
}

// Whether a user other than root may make a user namespace here: a child
// that becomes nobody tries.
bool unprivileged_user_namespaces_work() {
    const pid_t child = fork();
    if (child == 0) {
        const bool not_root = geteuid() != 0 || become_nobody();
        _exit(not_root && unshare(CLONE_NEWUSER) == 0 ? 0 : 1);
    }
    int status = 0;
    return child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

constexpr char without_user_namespaces_option[] = "--as-nobody-without-user-namespaces";

// test_grade --as-nobody-without-user-namespaces COMMAND...: runs COMMAND as
// nobody where no user namespace can be made (a user namespace of this
// test's own, root and nobody mapped, whose limit on user namespaces below
// it is 0). Run by root; the command's exit status, or 125.
int run_as_nobody_without_user_namespaces(char** command) {
    int unshared[2], mapped[2];
    if (pipe(unshared) != 0 || pipe(mapped) != 0) return 125;
    const pid_t child = fork();
    if (child == 0) {
        char byte = 0;
        if (unshare(CLONE_NEWUSER) != 0 || write(unshared[1], &byte, 1) != 1 || read(mapped[0], &byte, 1) != 1)
            _exit(125);
        std::ofstream("/proc/sys/user/max_user_namespaces") << "0\n";
        if (!become_nobody()) _exit(125);
        execv(command[0], command);
        _exit(125);
    }
    char byte = 0;
    if (child < 0 || read(unshared[0], &byte, 1) != 1) return 125;
    const std::string maps = "0 0 1\n65534 65534 1\n";
    for (const char* map : {"uid_map", "gid_map"}) {
        std::ofstream("/proc/" + std::to_string(child) + "/" + map) << maps;
    }
    if (write(mapped[1], &byte, 1) != 1) return 125;
    int status = 0;
    waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 125;
}

constexpr char without_system_calls_option[] = "--without-system-calls";

// test_grade --without-system-calls NAMES COMMAND...: runs COMMAND (as
// nobody, run by root) where the system calls NAMES (mount_setattr and/or
// landlock_create_ruleset, with commas between) fail with ENOSYS, as on a
// kernel that lacks them (a seccomp filter). The command's exit status, or
// 125.
int run_without_system_calls(const std::string& names, char** command) {
#if defined(SYS_mount_setattr) && defined(SYS_landlock_create_ruleset)
    std::vector<sock_filter> filter{BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr))};
    const std::pair<std::string, long> calls[] = {{"mount_setattr", SYS_mount_setattr},
                                                  {"landlock_create_ruleset", SYS_landlock_create_ruleset}};
    for (const auto& [name, number] : calls) {
        if (("," + names + ",").find("," + name + ",") == std::string::npos) continue;
        filter.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, static_cast<unsigned>(number), 0, 1));
        filter.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | ENOSYS));
    }
    filter.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW));
    if (filter.size() == 2 || (geteuid() == 0 && !become_nobody())) return 125;
    const sock_fprog program{static_cast<unsigned short>(filter.size()), filter.data()};
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 || prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &program) != 0)
        return 125;
    execv(command[0], command);
#else
    (void)names, (void)command;
#endif
    return 125;
}

// Whether this kernel has mount_setattr (Linux 5.12): a call with no
// attributes fails, but not with ENOSYS.
bool kernel_has_mount_setattr() {
#ifdef SYS_mount_setattr
    return syscall(SYS_mount_setattr, -1, "", 0, nullptr, 0) == 0 || errno != ENOSYS;
#else
    return false;
#endif
}

// This kernel's Landlock ABI: 3 (Linux 6.2) limits writes, 6 (6.12) scopes
// signals; below 1, none.
long kernel_landlock_abi() {
#ifdef SYS_landlock_create_ruleset
    constexpr unsigned version = 1U << 0;  // LANDLOCK_CREATE_RULESET_VERSION
    return syscall(SYS_landlock_create_ruleset, nullptr, 0, version);
#else
    return 0;
#endif
}

// Whether a PID namespace with a /proc of its own can be made here: by
// root, or by nobody in a user namespace (`as_nobody`). A child tries.
bool pid_namespace_with_its_proc_works(bool as_nobody) {
    const pid_t child = fork();
    if (child == 0) {
        if (as_nobody && geteuid() == 0 && !become_nobody()) _exit(1);
        const int user_namespace = geteuid() != 0 ? CLONE_NEWUSER : 0;
        if (unshare(user_namespace | CLONE_NEWNS | CLONE_NEWPID) != 0 ||
            mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0)
            _exit(1);
        const pid_t first = fork();  // the namespace's first process
        if (first == 0) _exit(mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr) == 0 ? 0 : 1);
        int status = 0;
        _exit(first > 0 && waitpid(first, &status, 0) == first && WIFEXITED(status) ? WEXITSTATUS(status) : 1);
    }
    int status = 0;
    return child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Whether every user may pass through each directory from / to `place`:
// a program run as another user (nobody) reaches it only then (a root
// whose $HOME is /root, mode 0700, does not qualify).
bool reachable_by_any_user(const fs::path& place) {
    fs::path walked;
    for (const fs::path& part : place) {
        walked /= part;
        struct stat info {};
        if (stat(walked.c_str(), &info) != 0 || (info.st_mode & S_IXOTH) == 0) return false;
    }
    return true;
}

// A directory that any user may write, outside the scratch places (/tmp,
// /var/tmp, /dev/shm, $TMPDIR): beside this test or in $HOME, where every
// user can reach it. Empty where every candidate lies in one, or out of
// other users' reach.
fs::path writable_outside_scratch_places() {
    std::vector<fs::path> scratch{"/tmp", "/var/tmp", "/dev/shm"};
    if (const char* tmpdir = std::getenv("TMPDIR"); tmpdir && *tmpdir) scratch.emplace_back(tmpdir);
    std::vector<fs::path> candidates{fs::current_path()};
    if (const char* home = std::getenv("HOME"); home && *home) candidates.emplace_back(home);
    for (const fs::path& candidate : candidates) {
        std::error_code error;
        const fs::path place = fs::canonical(candidate, error);
        if (error) continue;
        const bool in_scratch = std::any_of(scratch.begin(), scratch.end(), [&](const fs::path& s) {
            std::error_code ignored;
            const std::string prefix = fs::canonical(s, ignored).string();
            const std::string text = place.string();
            return !ignored && text.compare(0, prefix.size(), prefix) == 0 &&
                   (text.size() == prefix.size() || text[prefix.size()] == '/' || prefix == "/");
        });
        if (in_scratch || !reachable_by_any_user(place)) continue;
        std::string path = (place / "particlesim-grade-outside-XXXXXX").string();
        if (!mkdtemp(path.data())) continue;
        chmod(path.c_str(), 01777);
        return path;
    }
    return {};
}

// Where namespaces can be made, a program cannot read the answers it is
// graded against (the suite's expected outputs, the outputs kept with
// --outputs) and has no network: a TCP listener of this test on 127.0.0.1
// gets no connection. So with root's namespaces, and for another user
// (nobody here) with a user namespace. Where they cannot be made (root
// without CAP_SYS_ADMIN; nobody where user namespaces cannot be made) the
// grader says so, and the program reads the answers and connects. It
// cannot write outside the scratch places (into a directory any user may
// write, beside this test) where the namespace's mounts are read-only
// (mount_setattr) or Landlock limits its writes, and with neither the
// grader says so. The grader's user's processes are out of its signals'
// reach: a user of its own's by user, a program run as the grader's user by
// its PID namespace (isolated) or Landlock's signal scope (and with
// neither, the grader says so): where they are, each run starts with
// `kill -KILL -1`, and the grade and a process of the grader's user live
// on. In its PID namespace it does not even see them. Each of
// mount_setattr and Landlock is taken away by a seccomp filter.
void programs_cannot_read_the_answers() {
    const int listener = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    CHECK(listener >= 0);
    CHECK_EQ(bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    CHECK_EQ(listen(listener, 16), 0);
    CHECK_EQ(getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length), 0);
    const std::string port = std::to_string(ntohs(address.sin_port));
    const fs::path kept = work() / "kept-outputs";
    const fs::path notes = work() / "answers";
    const fs::path outside = writable_outside_scratch_places();
    if (outside.empty())
        std::printf(
            "no directory outside /tmp, /var/tmp, /dev/shm and $TMPDIR that every user can reach and write: "
            "read-only files not checked\n");
    // Each run notes, by its pid, how many bytes of the suite's answers and of the kept outputs it read,
    // whether it wrote outside the scratch places and in its working directory, and whether it reached the
    // listener; then it runs simcli, its streams opened again by their names (/dev/stdout: a pipe that a user of
    // its own may open), and conforms.
    const std::string writes_outside =
        outside.empty() ? std::string("false") : "echo x 2>/dev/null > '" + outside.string() + "'/$run";
    // The run also notes whether it may signal a process of the grader's user (`$grader_user`: this test where
    // it is the grader's user, else a sleep of nobody's; a user of its own's by user, a program run as the
    // grader's user by its PID namespace or Landlock's signal scope), and whether it sees that process at all.
    const std::string body =
        std::string(run_name) + "n='" + notes.string() + "'/$run\n" + "cat '" + small_suite().string() +
        "'/*.out 2>/dev/null | wc -c > \"$n.suite\"\n" + "cat '" + kept.string() +
        "'/*.out 2>/dev/null | wc -c > \"$n.kept\"\n" + "if " + writes_outside +
        "; then echo yes; else echo no; fi > \"$n.outside\"\n" +
        "if echo x 2>/dev/null > mine && [ -s mine ]; then echo yes; else echo no; fi > \"$n.here\"\n" +
        "if echo x 2>/dev/null > '" + small_suite().string() +
        "'/intruder-$run; then echo yes; else echo no; fi > \"$n.into_suite\"\n" +
        "if kill -0 $grader_user 2>/dev/null; then echo yes; else echo no; fi > \"$n.signal\"\n" +
        "if [ -e /proc/$grader_user ]; then echo yes; else echo no; fi > \"$n.sees\"\n" +
        "if bash -c 'echo hello > /dev/tcp/127.0.0.1/" + port +
        "' 2>/dev/null; then echo yes; else echo no; fi > \"$n.network\"\n" + "exec '" + simcli +
        "' < /dev/stdin > /dev/stdout 2> /dev/stderr\n";
    // `mount_setattr`, `landlock`: whether the mode leaves these calls to the grader.
    struct Mode {
        std::string name;
        std::vector<std::string> launcher;
        bool isolated;
        bool mount_setattr = true, landlock = true;
        bool read_only = false, signals_confined = false;  // expected, set below
        bool suite_read_only = false;                      // the suite, in /tmp here: by the namespace's mounts alone
        bool processes_hidden = false;                     // a PID namespace of its own
        bool as_nobody = false;                            // the grader runs as nobody
    };
    const bool user_namespaces = unprivileged_user_namespaces_work();
    if (!user_namespaces) std::printf("user namespaces cannot be made here: nobody's programs run not isolated\n");
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    const std::string user = geteuid() == 0 ? "nobody" : "this user";
    std::vector<Mode> modes;
    if (geteuid() == 0) {
        modes = {{"root", {}, true},
                 {"root without CAP_SYS_ADMIN",
                  {"/usr/bin/setpriv", "--inh-caps", "-all", "--bounding-set", "-sys_admin", "--"},
                  false},
                 {"nobody", as_nobody, user_namespaces},
                 {"nobody without user namespaces", {self, without_user_namespaces_option}, false}};
    } else {
        modes = {{"this user", {}, user_namespaces}};
    }
#if defined(SYS_mount_setattr) && defined(SYS_landlock_create_ruleset)
    const auto without = [&](const std::string& names) {
        return std::vector<std::string>{self, without_system_calls_option, names};
    };
    modes.push_back({user + " without mount_setattr", without("mount_setattr"), user_namespaces, false, true});
    modes.push_back({user + " without Landlock", without("landlock_create_ruleset"), user_namespaces, true, false});
    modes.push_back(
        {user + " without either", without("mount_setattr,landlock_create_ruleset"), user_namespaces, false, false});
#endif
    // What this kernel can do at all (Debian 12's own kernel, 6.1, has Landlock's ABI 2).
    const bool kernel_mount_setattr = kernel_has_mount_setattr();
    const long landlock_abi = kernel_landlock_abi();
    if (!kernel_mount_setattr) std::printf("no mount_setattr in this kernel: no read-only mounts checked\n");
    if (landlock_abi < 3) std::printf("Landlock ABI %ld here: its limit on writes not checked\n", landlock_abi);
    if (landlock_abi < 6) std::printf("Landlock ABI %ld here: its signal scope not checked\n", landlock_abi);
    const bool root = geteuid() == 0;
    const bool pid_namespaces_for_root = root && pid_namespace_with_its_proc_works(false);
    const bool pid_namespaces_for_nobody = pid_namespace_with_its_proc_works(true);
    if (!pid_namespaces_for_nobody)
        std::printf("no PID namespace with its own /proc here: hidden processes not checked\n");
    for (Mode& mode : modes) {
        mode.as_nobody = mode.name.rfind("root", 0) != 0;
        mode.suite_read_only = mode.isolated && mode.mount_setattr && kernel_mount_setattr;
        mode.read_only = mode.suite_read_only || (mode.landlock && landlock_abi >= 3);
        mode.processes_hidden = mode.isolated && (mode.as_nobody ? pid_namespaces_for_nobody : pid_namespaces_for_root);
        mode.signals_confined = (mode.landlock && landlock_abi >= 6) || mode.processes_hidden;
    }
    // A process of nobody's beside the grades that nobody runs (a user's shells and editors).
    pid_t nobody_sleep = -1;
    if (root) {
        nobody_sleep = fork();
        if (nobody_sleep == 0) {
            if (become_nobody()) execl("/bin/sleep", "sleep", "600", static_cast<char*>(nullptr));
            _exit(127);
        }
    }
    // The suite lies in /tmp, a scratch place; any user may write into it here but where it is kept read-only.
    fs::permissions(small_suite(), fs::perms::all | fs::perms::sticky_bit);
    for (const Mode& mode : modes) {
        check::Context context(mode.name);
        fs::remove_all(kept);
        fresh_shared_directory(notes);
        const pid_t grader_user = root && mode.as_nobody ? nobody_sleep : getpid();
        // Where its signals are confined, each run first sends SIGKILL to every process it may signal: the
        // grade goes on, and the grader's user's process lives.
        const std::string kill_everything = mode.signals_confined ? "kill -KILL -1\n" : "";
        const Graded g =
            grade(small_suite(), {"--outputs", kept.string()},
                  {script("answers.sh", kill_everything + "grader_user=" + std::to_string(grader_user) + "\n" + body)},
                  mode.launcher);
        CHECK_EQ(g.result.status, 0);
        if (nobody_sleep > 0) CHECK_EQ(waitpid(nobody_sleep, nullptr, WNOHANG), 0);  // still running
        if (g.json.kind != mini_json::Value::Kind::object) continue;                 // no report: failed above
        CHECK_EQ(g.json["isolated"].number, mode.isolated ? 1.0 : 0.0);
        CHECK_EQ(g.json["read_only"].number, mode.read_only ? 1.0 : 0.0);
        CHECK_EQ(g.json["signals_confined"].number, mode.signals_confined ? 1.0 : 0.0);
        CHECK_EQ(g.json["processes_hidden"].number, mode.processes_hidden ? 1.0 : 0.0);
        const bool own_users = g.json["own_users"].number == 1.0;
        CHECK_EQ(g.result.err.find("unable to confine the programs' signals") != std::string::npos,
                 !mode.signals_confined && !own_users);
        CHECK_EQ(g.result.err.find("unable to make namespaces") != std::string::npos, !mode.isolated);
        // The warning names the cause it found.
        if (mode.name == "root without CAP_SYS_ADMIN")
            CHECK(g.result.err.find("(run by root without CAP_SYS_ADMIN") != std::string::npos);
        if (mode.name == "nobody without user namespaces")
            CHECK(g.result.err.find("(user namespaces turned off: user.max_user_namespaces = 0): ") !=
                  std::string::npos);
        CHECK_EQ(g.result.err.find("unable to make files read-only") != std::string::npos, !mode.read_only);
        int runs = 0, read_kept = 0;
        for (const fs::directory_entry& file : fs::directory_iterator(notes)) {
            if (file.path().extension() != ".suite") continue;
            ++runs;
            const std::string base = (file.path().parent_path() / file.path().stem()).string();
            const long suite_bytes = std::stol(first_line(file.path()));
            const long kept_bytes = std::stol(first_line(base + ".kept"));
            CHECK_EQ(suite_bytes > 0, !mode.isolated);
            if (mode.isolated) CHECK_EQ(kept_bytes, 0L);
            read_kept += kept_bytes > 0 ? 1 : 0;
            if (!outside.empty()) {
                const fs::path written = outside / file.path().stem();
                CHECK_EQ(first_line(base + ".outside"), std::string(mode.read_only ? "no" : "yes"));
                CHECK_EQ(fs::exists(written), !mode.read_only);
                fs::remove(written);
            }
            CHECK_EQ(first_line(base + ".here"), std::string("yes"));
            const fs::path intruder = small_suite() / ("intruder-" + file.path().stem().string());
            CHECK_EQ(first_line(base + ".into_suite"), std::string(mode.suite_read_only ? "no" : "yes"));
            CHECK_EQ(fs::exists(intruder), !mode.suite_read_only);
            fs::remove(intruder);
            // A process of the grader's user: out of reach of a user of its own and of a confined program, and
            // not even seen from a PID namespace of its own.
            CHECK_EQ(first_line(base + ".signal"), std::string(mode.signals_confined || own_users ? "no" : "yes"));
            CHECK_EQ(first_line(base + ".sees"), std::string(mode.processes_hidden ? "no" : "yes"));
            CHECK_EQ(first_line(base + ".network"), std::string(mode.isolated ? "no" : "yes"));
        }
        CHECK_EQ(runs, 4);
        // Not isolated, every run after the first reads the outputs kept before it.
        CHECK_EQ(read_kept, mode.isolated ? 0 : 3);
        CHECK_EQ(connections_made(listener), mode.isolated ? 0 : 4);
    }
    close(listener);
    if (nobody_sleep > 0) {
        kill(nobody_sleep, SIGKILL);
        waitpid(nobody_sleep, nullptr, 0);
    }
    fs::permissions(small_suite(), fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                       fs::perms::others_read | fs::perms::others_exec);
    if (!outside.empty()) fs::remove_all(outside);
}

// A program run under mpirun is graded like any other: MPI's runtime makes
// files of megabytes, whatever the output's size, and runs isolated (its
// own network namespace, loopback up; by another user than root, in a user
// namespace too) and, by root, as a user of its own.
void programs_under_mpirun_are_graded() {
#if defined(SIMCLI_MPI_PATH) && defined(MPIEXEC_PATH)
    const Graded g = grade(small_suite(), {"--timeout", "60"}, {MPIEXEC_PATH, "-n", "2", SIMCLI_MPI_PATH});
    CHECK_EQ(g.result.status, 0);
    CHECK_EQ(g.json["isolated"].number, geteuid() == 0 || unprivileged_user_namespaces_work() ? 1.0 : 0.0);
    for (const mini_json::Value& scene : scenes(g).items) {
        check::Context context(scene["scene"].text);
        CHECK_EQ(scene["verdict"].text, std::string("conforms"));
    }
#else
    std::printf("built without MPI: no program graded under mpirun\n");
#endif
}

// Ctrl-C or a batch system's SIGTERM in the middle of a grade: the
// programs running (two, side by side) are stopped, nothing of them is left
// (no process, no directory in $TMPDIR), no report is written, and simcheck
// ends by the signal.
void an_interrupted_grade_leaves_nothing_behind() {
    const fs::path pids = work() / "interrupted";
    const fs::path temporary = work() / "interrupted-tmp";
    const fs::path report = work() / "interrupted.json";
    const std::string body = std::string(run_name) + "echo $$ > '" + pids.string() + "'/$run\nexec sleep 1000.4\n";
    const std::string program = script("interrupted.sh", body);
    for (const int signal : {SIGINT, SIGTERM}) {
        check::Context context(strsignal(signal));
        fresh_shared_directory(pids);
        fresh_shared_directory(temporary);
        fs::remove(report);
        const std::string err_path = (work() / "interrupted.err").string();
        const pid_t grader = fork();
        if (grader == 0) {
            setenv("TMPDIR", temporary.c_str(), 1);
            const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            dup2(err, 2);
            execl(simcheck.c_str(), simcheck.c_str(), "grade", small_suite().c_str(), "--jobs", "2", "--json",
                  report.c_str(), "--", program.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        // Both runs started: two pids noted.
        const auto started = std::chrono::steady_clock::now();
        const auto noted = [&] {
            return static_cast<std::size_t>(std::distance(fs::directory_iterator(pids), fs::directory_iterator()));
        };
        while (noted() < 2 && std::chrono::steady_clock::now() - started < std::chrono::seconds(20))
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        CHECK_EQ(noted(), std::size_t{2});
        kill(grader, signal);
        int status = 0;
        const auto signalled = std::chrono::steady_clock::now();
        while (waitpid(grader, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() - signalled > std::chrono::seconds(20)) kill(grader, SIGKILL);
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        CHECK(std::chrono::steady_clock::now() - signalled < std::chrono::seconds(5));
        CHECK(WIFSIGNALED(status) && WTERMSIG(status) == signal);
        CHECK(run_process::slurp(err_path).find("interrupted") != std::string::npos);
        CHECK(!fs::exists(report));
        CHECK_EQ(running_with_argument("1000.4"), 0);
        CHECK(fs::is_empty(temporary));
    }
}

constexpr char leave_ipc_option[] = "--leave-ipc";

// test_grade --leave-ipc KEY ANSWER: a graded program that makes a System V
// shared memory segment, semaphore set and message queue under KEY, then
// prints ANSWER (conforms) and leaves them behind.
int leave_ipc_and_answer(const char* key_text, const char* answer) {
    const auto key = static_cast<key_t>(std::strtol(key_text, nullptr, 10));
    if (shmget(key, 1 << 16, IPC_CREAT | 0600) < 0 || semget(key, 1, IPC_CREAT | 0600) < 0 ||
        msgget(key, IPC_CREAT | 0600) < 0)
        return 125;
    std::fputs(run_process::slurp(answer).c_str(), stdout);
    return 0;
}

// What a program leaves in System V IPC, which outlives its processes, is
// gone when its run ends: isolated, with its IPC namespace; run by root
// without namespaces (no CAP_SYS_ADMIN, as in a container), removed by its
// own user's id and counted in left_ipc.
void programs_leave_no_ipc_behind() {
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    const auto key = static_cast<key_t>(0x50530000 | (getpid() & 0xffff));
    struct Mode {
        std::string name;
        std::vector<std::string> launcher;
    };
    std::vector<Mode> modes{{geteuid() == 0 ? "root" : "this user", {}}};
    if (geteuid() == 0)
        modes.push_back({"root without CAP_SYS_ADMIN",
                         {"/usr/bin/setpriv", "--inh-caps", "-all", "--bounding-set", "-sys_admin", "--"}});
    for (const Mode& mode : modes) {
        check::Context context(mode.name);
        const Graded g = grade(one_scene_suite(), {"--no-reference"},
                               {self, leave_ipc_option, std::to_string(key), cradle_answer()}, mode.launcher);
        CHECK_EQ(g.result.status, 0);
        if (g.json.kind != mini_json::Value::Kind::object) continue;
        CHECK_EQ(scenes(g)[0]["verdict"].text, std::string("conforms"));
        const bool isolated = g.json["isolated"].number == 1.0, own_users = g.json["own_users"].number == 1.0;
        const int segment = shmget(key, 0, 0), semaphores = semget(key, 0, 0), queue = msgget(key, 0);
        if (!isolated && !own_users) {
            // Neither isolated nor a user of its own: nothing tells the program's objects from its grader's.
            std::printf("%s: not isolated and not root: System V IPC left behind not checked\n", mode.name.c_str());
            if (segment >= 0) shmctl(segment, IPC_RMID, nullptr);
            if (semaphores >= 0) semctl(semaphores, 0, IPC_RMID);
            if (queue >= 0) msgctl(queue, IPC_RMID, nullptr);
            continue;
        }
        CHECK_EQ(segment, -1);
        CHECK_EQ(semaphores, -1);
        CHECK_EQ(queue, -1);
        CHECK_EQ(scenes(g)[0]["left_ipc"].number, isolated ? 0.0 : 3.0);
        if (!isolated) CHECK(scenes(g)[0]["message"].text.find("it left 3 System V IPC objects") != std::string::npos);
    }
}

constexpr char reach_terminal_option[] = "--reach-terminal";

// test_grade --reach-terminal NOTE ANSWER: a graded program that tries to
// write on its controlling terminal and to push input into it (TIOCSTI,
// which the shell reading that terminal would run after the grade), notes
// in NOTE what it managed, and prints ANSWER (conforms).
int reach_terminal_and_answer(const char* note, const char* answer) {
    std::string reached = "no terminal";
    const int terminal = open("/dev/tty", O_RDWR | O_NOCTTY);
    if (terminal >= 0) {
        reached = "opened";
        constexpr char text[] = "INJECTED-TEXT\n";
        if (write(terminal, text, sizeof text - 1) > 0) reached += ", wrote";
        const char pushed = '#';
        if (ioctl(terminal, TIOCSTI, &pushed) == 0) reached += ", pushed input";
        close(terminal);
    }
    std::ofstream(note) << reached;
    std::fputs(run_process::slurp(answer).c_str(), stdout);
    return 0;
}

// Graded from a terminal (the grader's controlling terminal a pseudo-
// terminal here), a program reaches neither it nor its input: it runs with
// no controlling terminal (setsid).
void a_program_cannot_reach_the_graders_terminal() {
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    fresh_shared_directory(work() / "terminal");
    const fs::path note_path = work() / "terminal" / "note";
    const int master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0 || !ptsname(master)) {
        // A container without /dev/pts: no terminal to grade from, none for a program to reach.
        std::printf("no pseudo-terminal here: a program's reach into the grader's terminal not checked\n");
        if (master >= 0) close(master);
        return;
    }
    const std::string terminal = ptsname(master);
    const std::string answer = cradle_answer();
    const std::string suite = one_scene_suite().string();
    const pid_t grader = fork();
    if (grader == 0) {
        const int tty = setsid() >= 0 ? open(terminal.c_str(), O_RDWR) : -1;
        if (tty < 0 || ioctl(tty, TIOCSCTTY, 0) != 0 || dup2(tty, 0) < 0 || dup2(tty, 1) < 0 || dup2(tty, 2) < 0)
            _exit(125);
        execl(simcheck.c_str(), simcheck.c_str(), "grade", suite.c_str(),
#if defined(__SANITIZE_ADDRESS__)
              "--memory", "0",
#endif
              "--", self.c_str(), reach_terminal_option, note_path.c_str(), answer.c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    // The terminal's output read as it comes (a full terminal would stop the grader).
    std::string shown;
    int status = -1;
    for (bool ended = false; !ended;) {
        ended = waitpid(grader, &status, WNOHANG) == grader;
        pollfd ready{master, POLLIN, 0};
        while (poll(&ready, 1, ended ? 0 : 50) > 0) {
            char buffer[4096];
            const ssize_t got = read(master, buffer, sizeof buffer);
            if (got <= 0) break;
            shown.append(buffer, static_cast<std::size_t>(got));
        }
    }
    close(master);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    CHECK(shown.find("1 of 1 scenes conform") != std::string::npos);
    CHECK_EQ(first_line(note_path), std::string("no terminal"));
    CHECK(shown.find("INJECTED-TEXT") == std::string::npos);
}

// A program gets PATH, the locale, OpenMP's, MPI's and the sanitizers'
// settings and HOME as its working directory, not the grader's secrets;
// more by --env NAME or NAME=VALUE, everything by --full-env.
void programs_get_a_chosen_environment() {
    const fs::path notes = work() / "environment";
    fresh_shared_directory(notes);
    setenv("PARTICLESIM_GRADE_SECRET", "hidden-value", 1);
    setenv("OMP_PARTICLESIM_SETTING", "kept", 1);
    const std::string body = "env > '" + (notes / "seen").string() + "'\npwd > '" + (notes / "pwd").string() +
                             "'\ncat '" + cradle_answer() + "'\n";
    const auto seen = [&] {
        std::ifstream in(notes / "seen");
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        return lines;
    };
    const auto has = [](const std::vector<std::string>& lines, const std::string& line) {
        return std::find(lines.begin(), lines.end(), line) != lines.end();
    };
    const std::string grader_home = std::getenv("HOME") ? std::getenv("HOME") : "";
    struct Case {
        std::string name;
        std::vector<std::string> options;
        bool secret, home_is_directory;
        std::string assigned;
    };
    const std::vector<Case> cases{
        {"default", {}, false, true, ""},
        {"--env NAME", {"--env", "PARTICLESIM_GRADE_SECRET"}, true, true, ""},
        {"--env NAME=VALUE",
         {"--env", "PARTICLESIM_GRADE_OTHER=given", "--env", "OMP_PARTICLESIM_SETTING=replaced"},
         false,
         true,
         "PARTICLESIM_GRADE_OTHER=given"},
        {"--full-env", {"--full-env"}, true, false, ""}};
    for (const Case& c : cases) {
        check::Context context(c.name);
        std::vector<std::string> options = c.options;
        options.emplace_back("--no-reference");  // the program alone is looked at
        const Graded g = grade(one_scene_suite(), options, {script("environment.sh", body)});
        CHECK_EQ(g.result.status, 0);
        const std::vector<std::string> lines = seen();
        CHECK(!lines.empty());
        CHECK_EQ(has(lines, "PARTICLESIM_GRADE_SECRET=hidden-value"), c.secret);
        CHECK(has(lines, "PATH=" + std::string(std::getenv("PATH"))));
        const bool replaced = c.name == "--env NAME=VALUE";
        CHECK(has(lines, replaced ? "OMP_PARTICLESIM_SETTING=replaced" : "OMP_PARTICLESIM_SETTING=kept"));
        CHECK(!has(lines, "OMP_PARTICLESIM_SETTING=kept") || !replaced);
        if (!c.assigned.empty()) CHECK(has(lines, c.assigned));
        const std::string directory = first_line(notes / "pwd");
        CHECK_EQ(has(lines, "HOME=" + directory), c.home_is_directory);
        if (!c.home_is_directory && !grader_home.empty()) CHECK(has(lines, "HOME=" + grader_home));
    }
    unsetenv("PARTICLESIM_GRADE_SECRET");
    unsetenv("OMP_PARTICLESIM_SETTING");
    // A name not set here, or not a name, is refused before any run.
    for (const std::string bad : {"PARTICLESIM_GRADE_UNSET", "=value", "1NAME", "NA-ME=x"}) {
        check::Context context("--env ", bad);
        const run_process::Result refused =
            run_process::run(simcheck, {"grade", one_scene_suite().string(), "--env", bad, "--", simcli});
        CHECK_EQ(refused.status, 2);
        CHECK(refused.err.rfind("simcheck grade: --env: ", 0) == 0);
        CHECK(refused.out.empty());
    }
}

// What others may not read in /etc and in the homes (the grader's own here,
// a directory of this test's as HOME) reads as empty to a program that runs
// isolated, though run by root it keeps the right to read every file: a
// private file and a private directory's file, not a public one; and
// /etc/shadow where it is private.
void programs_cannot_read_private_files() {
    const fs::path home = work() / "grader-home";
    fs::create_directories(home / "private");
    fs::create_directories(home / "public");
    std::ofstream(home / "secret.txt") << "secret\n";
    std::ofstream(home / "private" / "key") << "key\n";
    std::ofstream(home / "public" / "notes") << "notes\n";
    chmod((home / "secret.txt").c_str(), 0600);
    chmod((home / "private").c_str(), 0700);
    chmod(home.c_str(), 0755);
    const fs::path notes = work() / "private-notes";
    fresh_shared_directory(notes);
    const auto bytes_of = [&](const std::string& name, const fs::path& path) {
        return "wc -c < '" + path.string() + "' > '" + (notes / name).string() + "' 2>/dev/null\n";
    };
    const std::string body = bytes_of("secret", home / "secret.txt") + bytes_of("key", home / "private" / "key") +
                             bytes_of("notes", home / "public" / "notes") + bytes_of("shadow", "/etc/shadow") +
                             "cat '" + cradle_answer() + "'\n";
    const std::string grader_home = std::getenv("HOME") ? std::getenv("HOME") : "";
    setenv("HOME", home.c_str(), 1);
    const Graded g = grade(one_scene_suite(), {"--no-reference"}, {script("private.sh", body)});
    if (grader_home.empty()) {
        unsetenv("HOME");
    } else {
        setenv("HOME", grader_home.c_str(), 1);
    }
    CHECK_EQ(g.result.status, 0);
    if (g.json.kind != mini_json::Value::Kind::object) return;
    if (g.json["isolated"].number != 1.0) {
        std::printf("not isolated: private files not hidden, not checked\n");
        return;
    }
    const auto noted = [&](const std::string& name) { return first_line(notes / name); };
    CHECK_EQ(noted("secret"), std::string("0"));
    CHECK(noted("key") != std::string("4"));  // its directory is empty: no such file
    CHECK_EQ(noted("notes"), std::string("6"));
    struct stat shadow {};
    if (stat("/etc/shadow", &shadow) == 0 && (shadow.st_mode & S_IROTH) == 0)
        CHECK(noted("shadow").empty() || noted("shadow") == std::string("0"));
}

void each_run_has_a_fresh_empty_directory() {
    const fs::path seen = work() / "directories.txt";
    fs::remove(seen);
    // Fails unless its directory is empty and stdin is empty (the scene comes as {}).
    const std::string body = "[ -z \"$(ls -A)\" ] || exit 5\n[ -z \"$(cat)\" ] || exit 6\npwd >> '" + seen.string() +
                             "'\necho junk > junk.txt\nexec '" + simcli + "' \"$1\"\n";
    const Graded g = grade(small_suite(), {}, {script("files.sh", body), "{}"});
    CHECK_EQ(g.result.status, 0);
    std::ifstream in(seen);
    std::vector<std::string> directories;
    for (std::string line; std::getline(in, line);) directories.push_back(line);
    CHECK_EQ(directories.size(), std::size_t{4});
    for (const std::string& d : directories) {
        CHECK(!fs::exists(d));
        for (const std::string& other : directories) CHECK(&d == &other || d != other);
    }
}

// Started with its standard streams closed (a batch system's `<&- >&-
// 2>&-`), simcheck still grades: a pipe it makes for a run must not take
// their numbers, onto which the program's streams are moved. Its summary
// cannot be written: it says so (with stderr open), and the JSON report
// holds the verdicts.
void a_grade_with_its_streams_closed() {
    const fs::path json = work() / "streams-closed.json";
    const fs::path err = work() / "streams-closed.err";
    for (const bool stderr_open : {false, true}) {
        check::Context context(stderr_open ? "stdin and stdout closed" : "stdin, stdout and stderr closed");
        fs::remove(json);
        const pid_t grader = fork();
        if (grader == 0) {
            const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
            if (err_fd < 0 || dup2(err_fd, 2) != 2) _exit(127);
            for (int fd = 0; fd < (stderr_open ? 2 : 3); ++fd) close(fd);
            execl(simcheck.c_str(), simcheck.c_str(), "grade", small_suite().c_str(), "--json", json.c_str(),
#if defined(__SANITIZE_ADDRESS__)
                  "--memory", "0",
#endif
                  "--", simcli.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        int status = -1;
        CHECK(grader > 0 && waitpid(grader, &status, 0) == grader);
        CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 2);
        CHECK_EQ(run_process::slurp(err.string())
                         .find("simcheck grade: cannot write the summary to stdout: Bad file "
                               "descriptor (the reports are written)\n") != std::string::npos,
                 stderr_open);
        const mini_json::Value report = mini_json::Parser(run_process::slurp(json.string())).parse();
        CHECK_EQ(report["scenes"].items.size(), std::size_t{4});
        for (const mini_json::Value& scene : report["scenes"].items)
            CHECK_EQ(scene["verdict"].text, std::string("conforms"));
    }
}

void bad_usage() {
    CHECK_EQ(run_process::run(simcheck, {"grade", small_suite().string()}).status, 2);
    CHECK_EQ(run_process::run(simcheck, {"grade", small_suite().string(), "--", "/no/such/program"}).status, 2);
    CHECK_EQ(run_process::run(simcheck, {"grade", (work() / "nowhere").string(), "--", simcli}).status, 2);
    const run_process::Result bad_timeout =
        run_process::run(simcheck, {"grade", small_suite().string(), "--timeout", "x", "--", simcli});
    CHECK_EQ(bad_timeout.status, 2);
    CHECK_EQ(bad_timeout.err,
             std::string("simcheck grade: --timeout needs a number from 0.01 to 1000000, not \"x\"\n"));
    // The outputs kept in the suite itself would replace its expected outputs.
    const run_process::Result into_suite = run_process::run(
        simcheck, {"grade", small_suite().string(), "--outputs", (small_suite() / ".").string(), "--", simcli});
    CHECK_EQ(into_suite.status, 2);
    CHECK(into_suite.err.find("would replace its expected outputs") != std::string::npos);
    // Reports and kept outputs that cannot be written are refused before any
    // run (the program would leave its mark in the run's directory's parent).
    const std::string marker = (work() / "ran.mark").string();
    const std::string marking = script("marking.sh", "touch " + marker + "\n");
    const fs::path a_file = work() / "a-file";
    std::ofstream(a_file) << "";
    const std::vector<std::pair<std::vector<std::string>, std::string>> unwritable{
        {{"--outputs", a_file.string()}, "--outputs " + a_file.string() + ": cannot make the directory: "},
        {{"--json", work().string()}, "--json " + work().string() + ": is a directory"},
        {{"--markdown", "/nonexistent/report.md"},
         "--markdown /nonexistent/report.md: cannot write: No such file or directory"},
    };
    for (const auto& [options, message] : unwritable) {
        std::vector<std::string> args{"grade", small_suite().string(), "--no-reference"};
        args.insert(args.end(), options.begin(), options.end());
        args.insert(args.end(), {"--", marking});
        const run_process::Result refused = run_process::run(simcheck, args);
        check::Context context(options[0], ": ", refused.err);
        CHECK_EQ(refused.status, 2);
        CHECK(refused.err.find("simcheck grade: " + message) == 0);
        CHECK(!fs::exists(marker));
    }
    // With a report it can write, the same grade runs the program, which leaves its mark.
    const run_process::Result writable =
        run_process::run(simcheck, {"grade", small_suite().string(), "--no-reference", "--json",
                                    (work() / "marking.json").string(), "--", marking});
    CHECK_EQ(writable.status, 1);  // no output: every scene malformed
    CHECK(fs::exists(marker));
    // A report that fails once the grade is done (a full disk): named with
    // its option, exit 2, and the summary and the other report still written.
    const fs::path after_markdown = work() / "after-full.md";
    fs::remove(after_markdown);
    const run_process::Result full =
        run_process::run(simcheck, {"grade", small_suite().string(), "--no-reference", "--json", "/dev/full",
                                    "--markdown", after_markdown.string(), "--", marking});
    check::Context full_context(full.err);
    CHECK_EQ(full.status, 2);
    CHECK(full.err.find("simcheck grade: --json /dev/full: cannot write: No space left on device (the grade is "
                        "done: its summary is on stdout)\n") != std::string::npos);
    CHECK(full.out.find("scenes conform") != std::string::npos);
    CHECK(fs::exists(after_markdown) && fs::file_size(after_markdown) > 0);
    // A directory is not a program; a scene the grader cannot read is named, before any run.
    const run_process::Result directory =
        run_process::run(simcheck, {"grade", small_suite().string(), "--", work().string()});
    CHECK_EQ(directory.status, 2);
    CHECK(directory.err.find("no such program (or not executable)") != std::string::npos);
    const fs::path unreadable = work() / "unreadable-suite";
    fs::create_directories(unreadable);
    chmod(unreadable.c_str(), 0755);
    fs::copy_file(small_suite() / "01-cradle.in", unreadable / "01-cradle.in", fs::copy_options::overwrite_existing);
    chmod((unreadable / "01-cradle.in").c_str(), 0);
    std::vector<std::string> grade_unreadable{"grade", unreadable.string(), "--", simcli};
    const run_process::Result unread =
        geteuid() == 0 ? [&] {
            std::vector<std::string> launched(as_nobody.begin() + 1, as_nobody.end());
            launched.push_back(simcheck);
            launched.insert(launched.end(), grade_unreadable.begin(), grade_unreadable.end());
            return run_process::run(as_nobody.front(), launched);
        }()
                       : run_process::run(simcheck, grade_unreadable);
    CHECK_EQ(unread.status, 2);
    CHECK(unread.err.find("01-cradle.in: cannot open: Permission denied\n") != std::string::npos);
    const run_process::Result help = run_process::run(simcheck, {"grade", "--help"});
    CHECK_EQ(help.status, 0);
    CHECK(help.out.find("--output-factor") != std::string::npos);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 2 && std::string(argv[1]) == without_user_namespaces_option)
        return run_as_nobody_without_user_namespaces(argv + 2);
    if (argc > 3 && std::string(argv[1]) == without_system_calls_option)
        return run_without_system_calls(argv[2], argv + 3);
    if (argc == 4 && std::string(argv[1]) == leave_ipc_option) return leave_ipc_and_answer(argv[2], argv[3]);
    if (argc == 4 && std::string(argv[1]) == hold_memory_option) return hold_memory(argv[2], argv[3]);
    if (argc == 4 && std::string(argv[1]) == reach_terminal_option) return reach_terminal_and_answer(argv[2], argv[3]);
    run_process::children_without_leak_checks();
    const int status = check::run(
        argc, argv, "test_grade",
        {{"reference conforms everywhere", reference_conforms_everywhere},
         {"textbook mistakes are wrong at their step", textbook_mistakes_are_wrong_at_their_step},
         {"misbehaving programs get their verdicts", misbehaving_programs_get_their_verdicts},
         {"files together are capped", files_together_are_capped},
         {"memory together is capped", memory_together_is_capped},
         {"a child holding stdout does not hang the grader", a_child_holding_stdout_does_not_hang_the_grader},
         {"processes that leave the group are killed", processes_that_leave_the_group_are_killed},
         {"programs run by root are users of their own", programs_run_by_root_are_users_of_their_own},
         {"programs run by root without CAP_DAC_READ_SEARCH", programs_run_by_root_without_read_search},
         {"programs cannot read the answers", programs_cannot_read_the_answers},
         {"programs under mpirun are graded", programs_under_mpirun_are_graded},
         {"an interrupted grade leaves nothing behind", an_interrupted_grade_leaves_nothing_behind},
         {"programs leave no System V IPC behind", programs_leave_no_ipc_behind},
         {"a program cannot reach the grader's terminal", a_program_cannot_reach_the_graders_terminal},
         {"programs get a chosen environment", programs_get_a_chosen_environment},
         {"programs cannot read private files", programs_cannot_read_private_files},
         {"each run has a fresh empty directory", each_run_has_a_fresh_empty_directory},
         {"a grade with its streams closed", a_grade_with_its_streams_closed},
         {"bad usage", bad_usage}});
    std::error_code ignored;
    fs::remove_all(work(), ignored);
    return status;
}
