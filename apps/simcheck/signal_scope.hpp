#pragma once
// A graded program may signal only its own processes: Landlock's signal
// scope (Linux 6.12, Landlock ABI 6) puts it and everything it starts in a
// domain of their own, whose processes cannot signal any process outside
// it. Run by a user other than root, the program runs as that user, and
// without this a kill(-1, SIGKILL) in it (or `pkill -u $USER`) would end
// every process of the user: the grader, the user's shells, their desktop.
// Unprivileged, and independent of the namespaces (isolation.hpp): it holds
// also where they cannot be made. The same domain keeps the program from
// abstract Unix sockets outside it.

namespace simcheck {

// Whether the kernel has Landlock with signal scoping (asked once).
bool can_confine_signals();

// In a child between fork and exec (async-signal-safe calls only), last
// before exec: sets no_new_privs (which Landlock needs) and enters a
// domain of its own. False if any step fails.
bool confine_signals();

}  // namespace simcheck
