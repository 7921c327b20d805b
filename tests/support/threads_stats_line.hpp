#pragma once
// The threads line of `simcli --stats` for the step engine, read back:
//   "stats: threads N"                                              (-t N, or nothing timed)
//   "stats: threads N, one thread in K of S steps (timed trials)"  (threads unset, a small scene)

#include <cstdio>
#include <string>

namespace threads_stats_line {

struct Line {
    bool found = false;              // a whole line of one of the two forms
    int threads = 0;                 // N
    bool trials = false;             // the second form
    long long one_thread_steps = 0;  // K
    long long steps = 0;             // S
};

inline Line read(const std::string& err) {
    Line line;
    const std::size_t at = err.find("stats: threads ");
    if (at == std::string::npos) return line;
    int consumed = 0;
    if (std::sscanf(err.c_str() + at, "stats: threads %d%n", &line.threads, &consumed) != 1) return line;
    const std::string rest = err.substr(at + static_cast<std::size_t>(consumed));
    if (rest.rfind("\n", 0) == 0) {
        line.found = true;
        return line;
    }
    int tail = 0;
    if (std::sscanf(rest.c_str(), ", one thread in %lld of %lld steps (timed trials)%n", &line.one_thread_steps,
                    &line.steps, &tail) == 2 &&
        tail > 0 && rest.compare(static_cast<std::size_t>(tail), 1, "\n") == 0) {
        line.found = true;
        line.trials = true;
    }
    return line;
}

}  // namespace threads_stats_line
