#pragma once
// Each graded program runs in a Landlock domain of its own, which it and
// everything it starts inherit. Landlock needs no privilege and no
// namespace, so it holds also where namespaces cannot be made
// (isolation.hpp): unprivileged user namespaces turned off, or without
// capabilities as Ubuntu's AppArmor leaves them.
//
// - Signals (Landlock ABI 6, Linux 6.12): the domain's processes may
//   signal one another and no process outside it. Run by a user other
//   than root, the program runs as that user, and without this a
//   kill(-1, SIGKILL) in it (or `pkill -u $USER`) would end every process
//   of the user: the grader, the user's shells, their desktop. The domain
//   also keeps it from abstract Unix sockets outside it.
// - Writes (ABI 3, Linux 6.2): files may be made, changed and removed only
//   beneath the scratch places (scratch_places.hpp); devices and /proc
//   may still be written (/dev/null, a terminal, /proc/self).

#include <string>
#include <vector>

namespace simcheck {

// What this kernel's Landlock does (asked once).
bool landlock_scopes_signals();
bool landlock_limits_writes();

class LandlockDomain {
public:
    // The scratch places found now, and what this kernel's Landlock can do:
    // asked before any fork, as the child may not allocate or lock.
    LandlockDomain();

    // In a child between fork and exec (async-signal-safe calls only), last
    // before exec: sets no_new_privs (which Landlock needs) and enters a
    // domain with what this kernel can do. False if any step fails.
    [[nodiscard]] bool enter() const;

private:
    std::vector<std::string> writable_;
    long abi_;  // Landlock's ABI version, below 1 without it
};

}  // namespace simcheck
