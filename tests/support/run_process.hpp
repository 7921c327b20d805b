#pragma once
// Runs a program with arguments and standard input, capturing its exit
// status, standard output and standard error (for tests of simcli).

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace run_process {

// ASAN_OPTIONS with `setting` after what it holds now (the later wins).
inline std::string asan_options_with(const std::string& setting) {
    const char* options = std::getenv("ASAN_OPTIONS");
    return (options && *options ? std::string(options) + ":" : std::string()) + setting;
}

// Under AddressSanitizer, the programs this test starts from now on (and
// theirs) run without LeakSanitizer, whose scan at each of their exits took
// 40 % of a test's CPU time there when it runs simcli or simcheck hundreds of
// times. AddressSanitizer and UndefinedBehaviorSanitizer still watch them,
// and the test program's own leaks (the library's, in process) are still
// checked. Elsewhere it does nothing.
inline void children_without_leak_checks() {
#if defined(__SANITIZE_ADDRESS__)
    setenv("ASAN_OPTIONS", asan_options_with("detect_leaks=0").c_str(), 1);
#endif
}

// For its lifetime, the programs this test starts run with LeakSanitizer
// again (after children_without_leak_checks()): for a run or two that must
// show the programs' own leaks at their exit.
class ChildrenWithLeakChecks {
public:
    ChildrenWithLeakChecks() {
#if defined(__SANITIZE_ADDRESS__)
        const char* options = std::getenv("ASAN_OPTIONS");
        saved_ = options ? options : "";
        setenv("ASAN_OPTIONS", asan_options_with("detect_leaks=1").c_str(), 1);
#endif
    }
    ~ChildrenWithLeakChecks() {
#if defined(__SANITIZE_ADDRESS__)
        setenv("ASAN_OPTIONS", saved_.c_str(), 1);
#endif
    }
    ChildrenWithLeakChecks(const ChildrenWithLeakChecks&) = delete;
    ChildrenWithLeakChecks& operator=(const ChildrenWithLeakChecks&) = delete;

private:
    [[maybe_unused]] std::string saved_;
};

struct Result {
    int status = -1;  // exit status, or 128 + signal
    std::string out;
    std::string err;
};

inline std::string slurp(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// A signal sent to the child `after_ms` milliseconds after its start (none
// when `number` is 0), or after `once_exists` appears, if named: a file the
// child writes once it has made progress, so that the signal lands mid-run
// however fast the machine runs it (not sent if the child ends first).
struct Signal {
    Signal() = default;
    Signal(int signal_number, int delay_ms, std::string file = {}, int again_delay_ms = -1)
        : number(signal_number), after_ms(delay_ms), once_exists(std::move(file)), again_after_ms(again_delay_ms) {}

    int number = 0;
    int after_ms = 0;
    std::string once_exists;  // "{pid}" in it stands for the child's process id
    int again_after_ms = -1;  // when 0 or more: the same signal once more, this long after the first
};

// Waits until `path` exists (true) or child `pid` has ended (false; its
// status is then in *status).
inline bool wait_for_file(pid_t pid, const std::string& path, int* status) {
    while (access(path.c_str(), F_OK) != 0) {
        if (waitpid(pid, status, WNOHANG) == pid) return false;
        usleep(2000);
    }
    return true;
}

// `stdout_path` empty: captured; otherwise the child's stdout goes there
// (e.g. /dev/full). `close_stdout_pipe`: stdout is a pipe nobody reads.
inline Result run(const std::string& program, const std::vector<std::string>& args, const std::string& input = "",
                  const std::string& stdout_path = "", bool close_stdout_pipe = false, Signal signal = {}) {
    char dir_template[] = "/tmp/particlesim-test-XXXXXX";
    const std::string dir = mkdtemp(dir_template);
    const std::string in_path = dir + "/in", out_path = dir + "/out", err_path = dir + "/err";
    std::ofstream(in_path, std::ios::binary) << input;

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, in_path.c_str(), O_RDONLY, 0);
    int pipe_fds[2] = {-1, -1};
    if (close_stdout_pipe) {
        if (pipe(pipe_fds) != 0) return {};
        posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
        posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
        posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);
    } else {
        const std::string target = stdout_path.empty() ? out_path : stdout_path;
        posix_spawn_file_actions_addopen(&actions, 1, target.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    }
    posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);

    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    Result result;
    if (posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ) == 0) {
        if (close_stdout_pipe) {
            close(pipe_fds[0]);  // nobody will read: the child's writes fail with EPIPE
            close(pipe_fds[1]);
        }
        int status = 0;
        bool running = true;
        if (signal.number != 0) {
            if (!signal.once_exists.empty()) {
                std::string path = signal.once_exists;
                const std::size_t at = path.find("{pid}");
                if (at != std::string::npos) path.replace(at, 5, std::to_string(pid));
                running = wait_for_file(pid, path, &status);
            }
            if (running) {
                usleep(static_cast<useconds_t>(signal.after_ms) * 1000);
                kill(pid, signal.number);
                if (signal.again_after_ms >= 0) {
                    usleep(static_cast<useconds_t>(signal.again_after_ms) * 1000);
                    kill(pid, signal.number);
                }
            }
        }
        if (running) waitpid(pid, &status, 0);
        result.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    posix_spawn_file_actions_destroy(&actions);
    result.out = slurp(out_path);
    result.err = slurp(err_path);
    std::remove(in_path.c_str());
    std::remove(out_path.c_str());
    std::remove(err_path.c_str());
    rmdir(dir.c_str());
    return result;
}

}  // namespace run_process
