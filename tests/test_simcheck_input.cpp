// simcheck on hostile files: whatever the scene and the output hold, it
// answers with a verdict or one clear error (exit 2 naming the line), never
// crashes, never hangs, and its memory follows the files' size, not the
// number of particles a header claims. Also run under the sanitizers.

#include "check.hpp"
#include "run_process.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace {

const std::string simcheck = SIMCHECK_PATH;

// The files the checks write, in a directory of this run's that goes when it ends.
struct TemporaryDirectory {
    std::string path;
    TemporaryDirectory() {
        char name_template[] = "/tmp/particlesim-simcheck-input-XXXXXX";
        if (!mkdtemp(name_template)) std::abort();
        path = name_template;
    }
    ~TemporaryDirectory() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

std::string write_file(const std::string& name, const std::string& text) {
    static const TemporaryDirectory dir;
    const std::string path = dir.path + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

run_process::Result check(const std::string& scene, const std::string& output) {
    return run_process::run(simcheck, {write_file("scene.in", scene), write_file("out.txt", output)});
}

// A head-on pair: contact at t = 0.5, back where they started after step 1.
const std::string pair_scene = "2 20 1 2 print\n0 5 10 2 0\n1 9 10 -2 0\n";
const std::string pair_output =
    "0 0 5.00000000 10.00000000 2.00000000 0.00000000\n"
    "0 1 9.00000000 10.00000000 -2.00000000 0.00000000\n"
    "1 0 5.00000000 10.00000000 -2.00000000 0.00000000\n"
    "1 1 9.00000000 10.00000000 2.00000000 0.00000000\n"
    "2 0 3.00000000 10.00000000 -2.00000000 0.00000000 1 0\n"
    "2 1 11.00000000 10.00000000 2.00000000 0.00000000 1 0\n";

void the_reference_output_conforms() {
    const run_process::Result r = check(pair_scene, pair_output);
    CHECK_EQ(r.status, 0);
    CHECK(r.out.rfind("conforms: 2 particles, 2 steps", 0) == 0);
    // Windows line endings change nothing.
    std::string crlf;
    for (const char c : pair_output) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    CHECK_EQ(check(pair_scene, crlf).status, 0);
}

// A zero printed as -0.00000000 is a deviation of shape: named, and the physics judged.
void negative_zero_is_a_deviation_of_shape() {
    std::string output = pair_output;
    output.replace(output.find(" 0.00000000"), 11, " -0.00000000");
    const run_process::Result r = check(pair_scene, output);
    CHECK_EQ(r.status, 4);
    CHECK(r.out.find("a zero printed as -0.00000000 (first: line 1)") != std::string::npos);
}

void unreadable_lines_name_their_line() {
    static constexpr char nul_line[] = "0 0 5.00000000 10\0.00000000 2.00000000 0.00000000\n";
    const std::string with_nul(nul_line, sizeof nul_line - 1);
    const std::vector<std::pair<std::string, std::string>> cases{
        {"0 0 5.00000000 10.00000000 2.00000000\n", "out.txt:1: expected \"s i x y vx vy\""},
        {"0 0 nan 10.00000000 2.00000000 0.00000000\n", "out.txt:1: x is not a finite number"},
        {"0 0 1e999 10.00000000 2.00000000 0.00000000\n", "out.txt:1: x is not a finite number"},
        {"99999999999999999999 0 5.00000000 10.00000000 2.00000000 0.00000000\n",
         "out.txt:1: the step is not a whole number"},
        {"0 -1 5.00000000 10.00000000 2.00000000 0.00000000\n", "out.txt:1: the particle index is not a whole number"},
        {"0 0 5.0000000\x01 10.00000000 2.00000000 0.00000000\n",
         "out.txt:1: x is not a finite number: \"5.0000000\\x01\""},
        // A terminal's escape sequences are shown, not sent: the message cannot clear or retitle the screen.
        {"0 0 5.0\x1b[2J\x1b]0;title\x07 10.00000000 2.00000000 0.00000000\n",
         "out.txt:1: x is not a finite number: \"5.0\\x1B[2J\\x1B]0;title\\x07\""},
        {"0 0 \xc3\xa9 10.00000000 2.00000000 0.00000000\n", "out.txt:1: x is not a finite number: \"\\xC3\\xA9\""},
        // printf's "%+.8f": named as the sign it is, not as "not a number".
        {"0 0 +5.00000000 10.00000000 2.00000000 0.00000000\n",
         "out.txt:1: x = \"+5.00000000\" has a '+' sign, which io.md's numbers never carry"},
        {"0 0 5.00000000 10.00000000 2.00000000 +0.00000000\n", "out.txt:1: vy = \"+0.00000000\" has a '+' sign"},
        {"+0 0 5.00000000 10.00000000 2.00000000 0.00000000\n", "out.txt:1: the step = \"+0\" has a '+' sign"},
        {"0 0 ++5.00000000 10.00000000 2.00000000 0.00000000\n", "out.txt:1: x is not a finite number"},
        {with_nul, "out.txt:1: "},
        {pair_output.substr(0, pair_output.rfind("1 0\n")) + "1 99999999999999999999\n",
         "out.txt:6: wc is not a whole number"},
        {std::string(1 << 20, '7'), "out.txt:1: the line is longer than 4096 characters"},
    };
    for (const auto& [output, message] : cases) {
        const run_process::Result r = check(pair_scene, output);
        CHECK_EQ(r.status, 2);
        CHECK(r.out.empty());
        const bool named = r.err.find("simcheck: ") == 0 && r.err.find(message) != std::string::npos &&
                           std::none_of(r.err.begin(), r.err.end() - 1, [](char c) {
                               const auto byte = static_cast<unsigned char>(c);
                               return byte < 0x20 || byte >= 0x7f;
                           });
        if (!named) std::fprintf(stderr, "expected \"%s\", got: %s", message.c_str(), r.err.c_str());
        CHECK(named);
    }
}

void shape_errors_name_their_step() {
    // Nothing at all, a block cut short, one line too many: exit 1, "step N:".
    const run_process::Result empty = check(pair_scene, "");
    CHECK_EQ(empty.status, 1);
    CHECK(empty.out.rfind("step 0: the output ends (after line 0) before particle 0 of step 0", 0) == 0);
    const run_process::Result cut = check(pair_scene, pair_output.substr(0, pair_output.find("1 1 ")));
    CHECK_EQ(cut.status, 1);
    CHECK(cut.out.rfind("step 1: the output ends (after line 3) before particle 1 of step 1", 0) == 0);
    const run_process::Result extra =
        check(pair_scene, pair_output + "3 0 1.00000000 1.00000000 0.00000000 0.00000000\n");
    CHECK_EQ(extra.status, 1);
    CHECK(extra.out.rfind("step 2: the output goes on after the final block: line 7", 0) == 0);
    std::string swapped = pair_output;
    swapped.replace(swapped.find("1 0 5."), 4, "1 1 ");
    const run_process::Result order = check(pair_scene, swapped);
    CHECK_EQ(order.status, 1);
    CHECK(order.out.rfind("step 1: line 3 reads \"1 1 5.00000000", 0) == 0);
}

// Outputs whose physics is right and whose shape is not: exit 4, each deviation named.
void deviations_of_shape_are_named() {
    const std::string step2 = pair_output.substr(pair_output.find("2 0 "));
    const std::string step2_bare =
        "2 0 3.00000000 10.00000000 -2.00000000 0.00000000\n"
        "2 1 11.00000000 10.00000000 2.00000000 0.00000000\n";
    const std::string before_final = pair_output.substr(0, pair_output.find("2 0 "));
    std::string spaced;
    for (const char c : pair_output) spaced += c == '\n' ? std::string(" \n") : std::string(1, c);
    const std::vector<std::pair<std::string, std::string>> cases{
        {before_final + step2_bare + step2,
         "step 2 is printed twice (lines 5-6 and lines 7-8); the copy without counters was set aside"},
        {before_final + step2_bare, "the final block has no counters (pc wc); they are not judged"},
        {pair_output.substr(pair_output.find("1 0 ")), "no step-0 block (the initial state)"},
        {spaced, "trailing spaces (first: line 1)"},
        {pair_output.substr(0, pair_output.find("1 0 ")) + "\n" + pair_output.substr(pair_output.find("1 0 ")),
         "blank lines (first: line 3)"},
    };
    for (const auto& [output, deviation] : cases) {
        const run_process::Result r = check(pair_scene, output);
        CHECK_EQ(r.status, 4);
        CHECK(r.out.rfind("shape: the physics conforms", 0) == 0);
        const bool named = r.out.find(deviation) != std::string::npos;
        if (!named) std::fprintf(stderr, "expected \"%s\", got: %s", deviation.c_str(), r.out.c_str());
        CHECK(named);
    }
    // Read despite its shape, wrong physics is still wrong: the block printed
    // twice, and a wrong final position.
    std::string wrong = before_final + step2_bare + step2;
    for (int copy = 0; copy < 2; ++copy) wrong.replace(wrong.find("2 0 3.00000000"), 14, "2 0 3.50000000");
    const run_process::Result r = check(pair_scene, wrong);
    CHECK_EQ(r.status, 1);
    CHECK(r.out.rfind("step 2:", 0) == 0);
    CHECK(r.out.find("printed twice") != std::string::npos);
    // A random scene without its step-0 block cannot be judged: its start is unknown.
    CHECK_EQ(check("2 20 1 2 print\n", pair_output.substr(pair_output.find("1 0 "))).status, 1);
}

// simcheck SCENE OUTPUT with its address space limited to 512 MB: its exit
// status, or -1 when it did not exit.
int status_within_512_mb(const std::string& scene, const std::string& out) {
    const pid_t child = fork();
    if (child == 0) {
        const rlimit limit{512u << 20, 512u << 20};
        setrlimit(RLIMIT_AS, &limit);
        const int devnull = open("/dev/null", O_WRONLY);
        dup2(devnull, 1);
        dup2(devnull, 2);
        execl(simcheck.c_str(), simcheck.c_str(), scene.c_str(), out.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void memory_follows_the_files() {
#if defined(__SANITIZE_ADDRESS__)
    // AddressSanitizer reserves terabytes of address space: no limit can be set
    // under it. The Release pass runs this case.
    std::printf("memory limit not testable under AddressSanitizer; checked in the Release pass\n");
    CHECK(true);
    return;
#endif
    // A 20-byte scene claiming 5 x 10^7 particles, over a three-line output:
    // refused at once, without allocating gigabytes.
    const std::string huge = write_file("huge.in", "50000000 1e6 1 5 print\n");
    const std::string three_lines = write_file("huge.out", pair_output.substr(0, pair_output.find("1 0 ")));
    CHECK_EQ(status_within_512_mb(huge, three_lines), 1);  // the output ends before particle 3 of step 0

    // An output of 40 MB in lines of 12 bytes, read for its shape and then
    // strictly: its memory follows its bytes, not its lines (a parsed line
    // takes about 300 bytes).
    std::string short_lines;
    for (int k = 0; k < 3500000; ++k) short_lines += "0 0 1 1 1 1\n";
    const std::string many = write_file("many.out", short_lines);
    CHECK_EQ(status_within_512_mb(write_file("pair.in", pair_scene), many), 1);  // line 2 repeats particle 0
}

// An output on stdin longer than the shape reader's reach is judged as it
// comes, not stored whole first: an endless stream wrong at its second line
// ends at once (before, it was copied for ever).
void an_endless_stream_on_stdin_ends() {
    const std::string scene = write_file("endless.in", pair_scene);
    const run_process::Result r = run_process::run(
        "/bin/sh", {"-c", "timeout 60 sh -c 'yes \"0 0 1 1 1 1\" | \"$0\" \"$1\" -' \"$0\" \"$1\"", simcheck, scene});
    CHECK_EQ(r.status, 1);
    CHECK(r.out.rfind("step 0: line 2 reads \"0 0 1 1 1 1\" where particle 1 of step 0 belongs", 0) == 0);
}

void bad_usage() {
    CHECK_EQ(run_process::run(simcheck, {}).status, 2);
    CHECK_EQ(run_process::run(simcheck, {"-", "-"}).status, 2);
    CHECK_EQ(run_process::run(simcheck, {"/nonexistent/scene", "/nonexistent/out"}).status, 2);
    // A directory as the scene or the output, named or on stdin: said as what it is, and not judged.
    const std::string scene = write_file("s.in", pair_scene), output = write_file("s.out", pair_output);
    const std::vector<std::pair<std::vector<std::string>, std::string>> directories{
        {{scene, "/tmp"}, "simcheck: /tmp: is a directory\n"},
        {{"/tmp", output}, "simcheck: /tmp: is a directory\n"},
        {{scene, "-"}, "simcheck: <stdin>: is a directory\n"},
        {{"-", output}, "simcheck: <stdin>: is a directory\n"}};
    for (const auto& [files, message] : directories) {
        std::vector<std::string> args{"-c", "exec \"$0\" \"$@\" < /", simcheck};
        args.insert(args.end(), files.begin(), files.end());
        const run_process::Result r = run_process::run("/bin/sh", args);
        CHECK_EQ(r.status, 2);
        CHECK(r.out.empty());
        CHECK_EQ(r.err, message);
    }
    // A report that cannot be written is said so (stdout closed).
    const run_process::Result closed =
        run_process::run("/bin/sh", {"-c", "exec \"$0\" \"$@\" >&-", simcheck, scene, output});
    CHECK_EQ(closed.status, 2);
    CHECK_EQ(closed.err, std::string("simcheck: cannot write the report: Bad file descriptor\n"));
    // A third file (a value given to --json, which takes none) is named.
    const run_process::Result third = run_process::run(simcheck, {scene, output, "--json", "report.json"});
    CHECK_EQ(third.status, 2);
    CHECK(third.err.find("\"report.json\" would be a third") != std::string::npos);
    CHECK_EQ(run_process::run(simcheck, {"--substeps", "0", "a", "b"}).status, 2);
    CHECK_EQ(run_process::run(simcheck, {"--frobnicate", "a", "b"}).status, 2);
    const run_process::Result help = run_process::run(simcheck, {"--help"});
    CHECK_EQ(help.status, 0);
    CHECK(help.out.find("usage: simcheck SCENE OUTPUT") == 0);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_simcheck_input",
                      {{"the reference output conforms", the_reference_output_conforms},
                       {"unreadable lines name their line", unreadable_lines_name_their_line},
                       {"negative zero is a deviation of shape", negative_zero_is_a_deviation_of_shape},
                       {"shape errors name their step", shape_errors_name_their_step},
                       {"deviations of shape are named", deviations_of_shape_are_named},
                       {"an endless stream on stdin ends", an_endless_stream_on_stdin_ends},
                       {"memory follows the files", memory_follows_the_files},
                       {"bad usage", bad_usage}});
}
