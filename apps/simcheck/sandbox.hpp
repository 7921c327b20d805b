#pragma once
// Runs a program the grader does not trust: in a fresh empty working
// directory, in a process group of its own that is killed as a whole at the
// end (so a child left holding stdout open cannot hang the grader), and
// whatever left that group (setsid, a daemon's double fork) killed too, once
// adopted (simcheck is their subreaper, Linux's PR_SET_CHILD_SUBREAPER); with a
// wall-clock limit, a cap on the bytes it writes to stdout, and setrlimit
// limits on memory, processes, file sizes and core dumps. Standard input is
// the scene file or /dev/null; nothing else is passed in.

#include <cstdint>
#include <string>
#include <vector>

namespace simcheck {

struct SandboxLimits {
    double seconds = 10.0;                              // wall clock
    std::int64_t output_bytes = std::int64_t{1} << 30;  // stdout, and any file it writes
    std::int64_t memory_bytes = std::int64_t{4} << 30;  // address space (RLIMIT_AS); 0: none
    int processes = 256;                                // tasks beyond what its user runs already (RLIMIT_NPROC)
    // No other program runs beside it (grade --jobs 1): what left its group
    // is then known to be its own, and counted in left_running.
    bool runs_alone = true;
};

struct SandboxRun {
    enum class End { exited, signalled, timeout, output_limit };
    End end = End::exited;
    int exit_status = 0;  // exited
    int signal = 0;       // signalled
    double seconds = 0.0;
    std::int64_t output_bytes = 0;
    std::string stderr_head;  // the first few kilobytes of its standard error
    // Processes of the program still running when it had ended by itself,
    // all killed: its group's, and, run alone, what had left the group.
    int left_running = 0;
};

// Runs argv[0] (looked up in PATH) with stdin from `stdin_path` and stdout
// into `stdout_path` (created). Throws std::runtime_error when it cannot be
// started at all (no working directory, no fork).
SandboxRun run_sandboxed(const std::vector<std::string>& argv, const std::string& stdin_path,
                         const std::string& stdout_path, const SandboxLimits& limits);

// The tasks (processes and threads) the user of this process runs now.
int tasks_of_this_user();

}  // namespace simcheck
