#pragma once
// The grader gives each program a mount namespace and a network namespace
// of its own: run by root, with CAP_SYS_ADMIN; run by another user, inside
// a user namespace whose only user is the grader's own. In the first, the
// grader's files that a program must not read are hidden: each expected
// output of the suite reads as empty (/dev/null bound over it), and the
// directories holding other runs' outputs are empty and read-only (a
// tmpfs over each), so a program cannot copy the answers it is graded
// against. Every file but the scratch places (scratch_places.hpp) is
// read-only there too, so a program cannot change the suite, the grader's
// files or anyone's that its user may write. In the network namespace,
// only loopback exists (brought up, for programs that talk to themselves,
// as mpirun does): no network.
//
// Where the kernel refuses (a container without CAP_SYS_ADMIN, or whose
// seccomp filter forbids unshare; unprivileged user namespaces turned
// off), programs run without it, and the report says so. A kernel before
// Linux 5.12 cannot make a tree of mounts read-only (mount_setattr): the
// rest holds, and the report says that too.

#include <string>
#include <vector>

namespace simcheck {

// Whether namespaces can be made: a trial child could make them (asked once).
bool can_isolate();
// Whether files can be made read-only in them too (asked with can_isolate()).
bool can_make_read_only();

// Whether an isolated program also gets a user namespace of its own (this
// process is not root). RLIMIT_NPROC is counted per user namespace: there
// it counts the program's tasks alone.
bool isolates_in_user_namespace();

// The paths to hide, sorted into files and directories once, before any
// fork: the child may not allocate.
class HiddenPaths {
public:
    // Nothing hidden.
    HiddenPaths();
    // Files and directories; anything else (gone, a device) is left alone.
    // `read_only_directories` stay read-only even inside a scratch place (the
    // suite in /tmp, which the next grade reads), where files are read-only.
    explicit HiddenPaths(const std::vector<std::string>& paths,
                         const std::vector<std::string>& read_only_directories = {});

    // In a child between fork and exec (async-signal-safe calls only):
    // enters new mount and network namespaces, hides the paths, makes every
    // file but the scratch places read-only (if `read_only`), and brings
    // loopback up. False if any step fails.
    [[nodiscard]] bool isolate(bool read_only) const;

private:
    std::vector<std::string> files_, directories_;
    std::vector<std::string> writable_;  // scratch_places()
    std::vector<std::string> read_only_directories_;
};

}  // namespace simcheck
