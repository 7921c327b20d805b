#pragma once
// Whole program runs for the benchmark modes that time programs (simcli,
// loaded, programs): the wall time of one run, and a scratch directory.

#include "run_process.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace bench {

struct Timed {
    double seconds = -1.0;  // negative: the program failed
    std::string out;        // empty when sent to a file
    std::string err;
};

// Runs command[0] with the rest as arguments and `input` on stdin; its
// stdout goes to `stdout_path` (for example /dev/null) or is kept in `out`.
inline Timed run_timed(const std::vector<std::string>& command, const std::string& input = "",
                       const std::string& stdout_path = "") {
    const auto start = std::chrono::steady_clock::now();
    run_process::Result result =
        run_process::run(command.front(), {command.begin() + 1, command.end()}, input, stdout_path);
    Timed timed;
    timed.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (result.status != 0) timed.seconds = -1.0;
    timed.out = std::move(result.out);
    timed.err = std::move(result.err);
    return timed;
}

// A fresh directory under /tmp for a mode's scene files.
inline std::string temporary_directory() {
    char dir_template[] = "/tmp/particlesim-bench-XXXXXX";
    const char* dir = mkdtemp(dir_template);
    if (dir == nullptr) {
        std::perror("mkdtemp");
        std::exit(1);
    }
    return dir;
}

}  // namespace bench
