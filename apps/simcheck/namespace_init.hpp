#pragma once
// The first process of a graded program's PID namespace (isolation.hpp)
// is not the program but a small init of the grader's: the kernel ignores
// a signal that a namespace's init has no handler for, so a program there
// as PID 1 could not be ended by its own abort() (SIGABRT) or `kill $$`,
// and a crash would be reported as another signal. The init starts the
// program as PID 2 and waits for it; when it ends, the init counts the
// processes it left running (in the namespace, wherever they went: a
// setsid, a daemon's double fork, runs side by side), tells the grader
// both through a pipe, kills them and ends.

namespace simcheck {

// What the init tells the grader: the program's wait status (as waitpid
// gives it) and how many of its processes were still running, all killed.
struct ProgramEnd {
    int wait_status = 0;
    int left_running = 0;
};

// In the child of fork_into_pid_namespace(), isolated, between fork and
// exec (async-signal-safe calls only): starts the program's process and
// returns in it; this process stays the init, writes a ProgramEnd to
// `report` once the program ends, and never returns. The program's
// process gets no descriptor above 2 from here (the caller closes them);
// the init keeps only `report`.
void split_off_program(int report);

}  // namespace simcheck
