#pragma once
// Runs a program the grader does not trust: in a fresh empty working
// directory, in a process group of its own with no controlling terminal
// (setsid: it can neither write on the grader's nor push input into it),
// killed as a whole at the end (so a child left holding stdout open cannot
// hang the grader), and
// whatever left that group (setsid, a daemon's double fork) killed too, once
// adopted (simcheck is their subreaper, Linux's PR_SET_CHILD_SUBREAPER); with a
// wall-clock limit, a cap on the bytes it writes to stdout, and setrlimit
// limits on memory, processes, file sizes and core dumps. Standard input is
// the scene file or /dev/null; nothing else is passed in. Where the kernel
// allows, it runs isolated (isolation.hpp), and in a Landlock domain
// (landlock_domain.hpp) that may signal only its own processes and write
// only in the scratch places.
//
// Run by root, it runs each program as a user of its own (an unused user
// id, free again once nothing of the run is left), keeping only the right
// to read and search every file (CAP_DAC_READ_SEARCH): the process limit
// then holds (root is exempt from RLIMIT_NPROC), the program can neither
// signal the grader nor write outside its directory and what any user may
// write, and whatever it leaves running is found by its user id, also with
// runs side by side.

#include "isolation.hpp"
#include "program_environment.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace simcheck {

struct SandboxLimits {
    double seconds = 10.0;  // wall clock
    // Its stdout; also each file it writes, and its files together, but those at least 1 GiB.
    std::int64_t output_bytes = std::int64_t{1} << 30;
    // Each process's address space (RLIMIT_AS), and what its processes hold together (memory_held.hpp); 0: none.
    std::int64_t memory_bytes = std::int64_t{4} << 30;
    int processes = 256;  // tasks it may add (RLIMIT_NPROC)
    // No other program runs beside it (grade --jobs 1): what left its group
    // is then known to be its own, and counted in left_running (as it always
    // is with users of their own).
    bool runs_alone = true;
    // What the program must not read (the answers it is graded against,
    // other runs' outputs), hidden where it runs isolated; the caller's, made
    // once for every run. None: nothing hidden.
    const HiddenPaths* hidden = nullptr;
    // Its environment (program_environment.hpp); none: this process's whole one.
    const EnvironmentChoice* environment = nullptr;
};

struct SandboxRun {
    // output_limit: its stdout passed limits.output_bytes; files_limit: the
    // files it held (files_held.hpp) passed the largest a file may be, or
    // nested deeper than they are measured; memory_limit: its processes
    // together held more memory than limits.memory_bytes (memory_held.hpp).
    enum class End { exited, signalled, timeout, output_limit, files_limit, memory_limit };
    End end = End::exited;
    int exit_status = 0;  // exited
    int signal = 0;       // signalled
    double seconds = 0.0;
    std::int64_t output_bytes = 0;
    std::int64_t files_bytes = 0;   // what its files held when last measured
    std::int64_t files_limit = 0;   // the cap on them
    bool files_too_deep = false;    // it nested directories deeper than the grader walks (max_files_depth)
    std::int64_t memory_bytes = 0;  // what its processes held together when last measured
    std::int64_t memory_limit = 0;  // the cap on it; 0: none
    std::string stderr_head;        // the first few kilobytes of its standard error
    // Processes of the program still running when it had ended by itself,
    // all killed: its group's, and, run alone, as a user of its own or in a
    // PID namespace of its own, what had left the group.
    int left_running = 0;
    // Run as a user of its own: the entries it left in /tmp, /var/tmp,
    // /dev/shm or $TMPDIR, all removed.
    int left_files = 0;
    // Run as a user of its own without namespaces: the System V shared
    // memory segments, semaphore sets and message queues it left, all
    // removed (isolated, its IPC namespace takes them).
    int left_ipc = 0;
};

// Whether programs run as users of their own: this process is root, may
// change users and read every file, and has unused user ids to give.
bool runs_programs_as_own_users();

// Whether programs run isolated: namespaces of their own, the hidden paths
// hidden and no network (isolation.hpp).
bool runs_programs_isolated();
// Whether they may write nowhere but in the scratch places
// (scratch_places.hpp): by Landlock (Linux 6.2), or isolated by read-only
// mounts (Linux 5.12).
bool runs_programs_read_only();
// Whether a program sees only its own processes: a PID namespace of its
// own, with its own /proc (isolation.hpp). Its signals then reach nothing
// else either, and what it leaves running is counted and killed by run,
// also with runs side by side.
bool runs_programs_with_own_processes();
// Whether a program may signal only its own processes: by its PID
// namespace, or by Landlock's signal scope (landlock_domain.hpp, Linux 6.12).
bool runs_programs_with_signals_confined();

// A signal that ends the grade (SIGINT, SIGTERM, SIGHUP): every run going
// is stopped, its processes killed and its directory removed, and
// run_sandboxed() then throws SandboxInterrupted, as it does at once once
// this was called. Async-signal-safe: for a signal handler.
void interrupt_runs(int signal) noexcept;
// The signal interrupt_runs() was called with, or 0.
int runs_interrupted() noexcept;
struct SandboxInterrupted : std::runtime_error {
    SandboxInterrupted() : std::runtime_error("interrupted") {}
};

// Runs argv[0] (looked up in PATH) with stdin from `stdin_path` and stdout
// into `stdout_path` (created). Throws std::runtime_error when it cannot be
// started at all (no working directory, no fork).
SandboxRun run_sandboxed(const std::vector<std::string>& argv, const std::string& stdin_path,
                         const std::string& stdout_path, const SandboxLimits& limits);

}  // namespace simcheck
