#pragma once
// The grader gives each program a mount namespace, a network namespace, an
// IPC namespace and a PID namespace of its own: run by root, with CAP_SYS_ADMIN; run by
// another user, inside a user namespace whose only user is the grader's
// own. In the PID namespace, with a /proc of its own, the program sees and
// signals its own processes alone (namespace_init.hpp). In the mount
// namespace, the grader's files that a program must not read are hidden:
// each expected output of the suite reads as empty (/dev/null bound over
// it), and the directories holding other runs' outputs are empty and
// read-only (a tmpfs over each), so a program cannot copy the answers it
// is graded against. Every file but the scratch places (scratch_places.hpp) is
// read-only there too, so a program cannot change the suite, the grader's
// files or anyone's that its user may write. In the network namespace,
// only loopback exists (brought up, for programs that talk to themselves,
// as mpirun does): no network. In the IPC namespace, the System V objects
// it makes go with its last process (ipc_objects.hpp).
//
// Where the kernel refuses (a container without CAP_SYS_ADMIN, or whose
// seccomp filter forbids unshare; unprivileged user namespaces turned
// off), programs run without it, and the report says so. A kernel before
// Linux 5.12 cannot make a tree of mounts read-only (mount_setattr): the
// rest holds, and the report says that too. Where the kernel cannot
// mount the PID namespace's /proc (a container whose /proc has masked
// paths), programs run without a PID namespace.

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace simcheck {

// Whether namespaces can be made: a trial child could make them (asked once).
bool can_isolate();
// Whether files can be made read-only in them too (asked with can_isolate()).
bool can_make_read_only();
// Whether a PID namespace can be made too, with a /proc of its own (asked
// with can_isolate()).
bool can_give_own_processes();

// Why namespaces cannot be made here, as far as the kernel's settings
// tell (the setting named, where one refuses them): for the grader's
// warning.
std::string namespaces_refused_because();

// Like fork(), but the child is the first process (PID 1) of a new PID
// namespace, and of a new user namespace where isolate() would enter one:
// isolate(read_only, true) then finishes what it starts. 0 in the child,
// the child's pid here, -1 on failure. The child may call only
// async-signal-safe functions.
pid_t fork_into_pid_namespace();

// Whether an isolated program also gets a user namespace of its own (this
// process is not root). RLIMIT_NPROC is counted per user namespace: there
// it counts the program's tasks alone.
bool isolates_in_user_namespace();

// What the System V objects of an IPC namespace may hold together, as its
// sysctls say it (kernel.shmall, the pages of shared memory; kernel.msgmni
// and kernel.msgmnb, the queues and the bytes a queue), written as text
// before any fork: the child may not allocate.
struct IpcMemoryCap {
    explicit IpcMemoryCap(std::int64_t bytes);  // 0 or less: the kernel's defaults kept
    char shared_pages[24] = "";
    char queues[24] = "";
};

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
    // enters new mount, network and IPC namespaces, hides the paths, makes every
    // file but the scratch places read-only (if `read_only`), and brings
    // loopback up. `own_processes`: the child of fork_into_pid_namespace(),
    // which also gets a /proc of its PID namespace. `ipc`: the cap on its
    // IPC namespace's objects, where the kernel lets the namespace's owner
    // set it (Linux 5.x and later; else its defaults stay). False if any
    // other step fails.
    [[nodiscard]] bool isolate(bool read_only, bool own_processes, const IpcMemoryCap* ipc = nullptr) const;

private:
    std::vector<std::string> files_, directories_;
    std::vector<std::string> writable_;  // scratch_places()
    std::vector<std::string> read_only_directories_;
};

}  // namespace simcheck
