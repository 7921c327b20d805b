#include "isolation.hpp"

#include "scratch_places.hpp"

#include <fcntl.h>
#include <net/if.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

namespace simcheck {

namespace {

// Loopback down is how a new network namespace starts.
bool bring_loopback_up() {
    const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return false;
    ifreq request{};
    std::memcpy(request.ifr_name, "lo", 3);
    bool up = ioctl(fd, SIOCGIFFLAGS, &request) == 0;
    if (up) {
        request.ifr_flags = static_cast<short>(request.ifr_flags | IFF_UP);
        up = ioctl(fd, SIOCSIFFLAGS, &request) == 0;
    }
    close(fd);
    return up;
}

// Writes all of `text` to `path` (async-signal-safe).
bool write_whole(const char* path, const char* text, std::size_t length) {
    const int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool written = write(fd, text, length) == static_cast<ssize_t>(length);
    close(fd);
    return written;
}

// Writes "ID ID 1\n", an id mapped onto itself, to a map of /proc/self
// (async-signal-safe: to_chars does not allocate).
bool map_onto_itself(const char* path, unsigned id) {
    char line[32];
    char* end = std::to_chars(line, line + 10, id).ptr;
    *end++ = ' ';
    end = std::to_chars(end, end + 10, id).ptr;
    constexpr char count[] = " 1\n";
    end = std::copy(count, count + 3, end);
    return write_whole(path, line, static_cast<std::size_t>(end - line));
}

// A user namespace whose only user and group are this process's own, so
// that a user other than root may make the mount and network namespaces.
// The program keeps no capability in it: its user is not the namespace's
// root, so exec drops them. `made`: the namespace is there already
// (fork_into_pid_namespace()), its ids not yet mapped.
bool enter_user_namespace(bool made) {
    const uid_t user = geteuid();
    const gid_t group = getegid();
    constexpr char deny[] = "deny";
    return (made || unshare(CLONE_NEWUSER) == 0) && write_whole("/proc/self/setgroups", deny, sizeof deny - 1) &&
           map_onto_itself("/proc/self/uid_map", user) && map_onto_itself("/proc/self/gid_map", group);
}

// mount_setattr(2) (Linux 5.12), called raw: glibc wraps it only from 2.36.
struct MountAttributes {
    std::uint64_t set = 0, clear = 0, propagation = 0, user_namespace_fd = 0;
};
constexpr std::uint64_t mount_read_only = 0x1;  // MOUNT_ATTR_RDONLY
constexpr unsigned at_recursive = 0x8000;       // AT_RECURSIVE

bool set_mount_attributes(const char* path, unsigned flags, const MountAttributes& attributes) {
#ifdef SYS_mount_setattr
    return syscall(SYS_mount_setattr, AT_FDCWD, path, flags, &attributes, sizeof attributes) == 0;
#else
    (void)path, (void)flags, (void)attributes;
    return false;
#endif
}

// Whether a child can isolate itself, with or without read-only files, in
// a PID namespace of its own or not.
bool trial_isolates(bool read_only, bool own_processes) {
    const HiddenPaths nothing_hidden;  // made before the fork: it allocates
    const pid_t trial = own_processes ? fork_into_pid_namespace() : fork();
    if (trial == 0) _exit(nothing_hidden.isolate(read_only, own_processes) ? 0 : 1);
    int status = 0;
    return trial > 0 && waitpid(trial, &status, 0) == trial && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

struct Support {
    bool namespaces = false, read_only = false, own_processes = false;
};

const Support& support() {
    static const Support found = [] {
        Support s;
        s.read_only = trial_isolates(true, false);
        s.namespaces = s.read_only || trial_isolates(false, false);
        s.own_processes = s.namespaces && trial_isolates(s.read_only, true);
        return s;
    }();
    return found;
}

}  // namespace

bool can_isolate() { return support().namespaces; }

bool can_make_read_only() { return support().read_only; }

bool can_give_own_processes() { return support().own_processes; }

std::string namespaces_refused_because() {
    if (!isolates_in_user_namespace()) return "run by root without CAP_SYS_ADMIN, or unshare refused";
    const auto setting = [](const char* path) {
        std::string value;
        std::getline(std::ifstream(path), value);
        return value;
    };
    if (setting("/proc/sys/user/max_user_namespaces") == "0")
        return "user namespaces turned off: user.max_user_namespaces = 0";
    if (setting("/proc/sys/kernel/unprivileged_userns_clone") == "0")
        return "unprivileged user namespaces turned off: kernel.unprivileged_userns_clone = 0";
    // Ubuntu from 23.10: the namespace is made, but without capabilities in it.
    if (setting("/proc/sys/kernel/apparmor_restrict_unprivileged_userns") == "1")
        return "AppArmor leaves unprivileged user namespaces without capabilities: "
               "kernel.apparmor_restrict_unprivileged_userns = 1";
    return "unshare refused";
}

pid_t fork_into_pid_namespace() {
    // Raw clone(2), like fork() but for its flags: the child may call only
    // async-signal-safe functions, as after fork() in a threaded process.
    // With CLONE_NEWUSER in the same call a user other than root may make
    // the PID namespace, which the user namespace then owns.
    unsigned long flags = CLONE_NEWPID | SIGCHLD;
    if (isolates_in_user_namespace()) flags |= CLONE_NEWUSER;
    return static_cast<pid_t>(syscall(SYS_clone, flags, nullptr, nullptr, nullptr, nullptr));
}

HiddenPaths::HiddenPaths() : writable_(scratch_places()) {}

HiddenPaths::HiddenPaths(const std::vector<std::string>& paths, const std::vector<std::string>& read_only_directories)
    : writable_(scratch_places()) {
    for (const std::string& directory : read_only_directories) {
        struct stat info {};
        if (stat(directory.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) read_only_directories_.push_back(directory);
    }
    for (const std::string& path : paths) {
        struct stat info {};
        if (stat(path.c_str(), &info) != 0) continue;
        if (S_ISREG(info.st_mode)) files_.push_back(path);
        if (S_ISDIR(info.st_mode)) directories_.push_back(path);
    }
}

bool isolates_in_user_namespace() { return geteuid() != 0; }

IpcMemoryCap::IpcMemoryCap(std::int64_t bytes) {
    if (bytes <= 0) return;
    // Queues of the kernel's default size (16 KiB), as many as fit, and no more than its default count.
    constexpr std::int64_t queue_bytes = 16384, default_queues = 32000;
    std::snprintf(shared_pages, sizeof shared_pages, "%lld",
                  static_cast<long long>(std::max<std::int64_t>(1, bytes / sysconf(_SC_PAGESIZE))));
    std::snprintf(queues, sizeof queues, "%lld",
                  static_cast<long long>(std::clamp<std::int64_t>(bytes / queue_bytes, 1, default_queues)));
}

bool HiddenPaths::isolate(bool read_only, bool own_processes, const IpcMemoryCap* ipc) const {
    const bool own_user_namespace = isolates_in_user_namespace();
    if (own_user_namespace && !enter_user_namespace(own_processes)) return false;
    // An IPC namespace too: the System V shared memory, semaphores and queues
    // it makes go with its last process (ipc_objects.hpp).
    if (unshare(CLONE_NEWNS | CLONE_NEWNET | CLONE_NEWIPC) != 0) return false;
    if (ipc && ipc->shared_pages[0] != '\0') {
        // The IPC namespace's own settings (before /proc is made read-only), so that what it holds stays below the
        // program's memory cap: without them a namespace may hold 16 EiB of shared memory and 500 MB of messages.
        [[maybe_unused]] const bool capped =
            write_whole("/proc/sys/kernel/shmall", ipc->shared_pages, std::strlen(ipc->shared_pages)) &&
            write_whole("/proc/sys/kernel/msgmnb", "16384", 5) &&
            write_whole("/proc/sys/kernel/msgmni", ipc->queues, std::strlen(ipc->queues));
    }
    // Nothing mounted here reaches the grader's namespace.
    if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return false;
    if (read_only) {
        // Each scratch place a mount of its own (sorted: a place before those
        // inside it), so that it can stay writable below while the rest is
        // made read-only; the hidden paths inside are mounted on top of it.
        for (const std::string& place : writable_) {
            if (mount(place.c_str(), place.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return false;
        }
        // The directories kept read-only too, on top of the scratch places'
        // (where they lie in one): the read-only flag made below stays on
        // them when the scratch places' own is cleared.
        for (const std::string& directory : read_only_directories_) {
            if (mount(directory.c_str(), directory.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return false;
        }
    }
    // c_str() only reads: nothing is allocated here.
    for (const std::string& directory : directories_) {
        if (mount("simcheck-hidden", directory.c_str(), "tmpfs", MS_RDONLY | MS_NOSUID | MS_NODEV | MS_NOEXEC,
                  "size=4k,mode=0555") != 0)
            return false;
    }
    for (const std::string& file : files_) {
        if (mount("/dev/null", file.c_str(), nullptr, MS_BIND, nullptr) != 0) return false;
    }
    // A /proc of the PID namespace: it lists the program's processes alone,
    // so no other process's command line, environment or open files are
    // there to read. Made before the tree is made read-only, as /proc was.
    if (own_processes && mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr) != 0) return false;
    // Every file read-only but in the scratch places: the program cannot
    // change the grader's files, the suite, or other programs. Device files
    // (/dev/null, a terminal) are still written: a read-only mount does not
    // stop that.
    if (read_only) {
        MountAttributes all_read_only;
        all_read_only.set = mount_read_only;
        if (!set_mount_attributes("/", at_recursive, all_read_only)) return false;
        MountAttributes writable;
        writable.clear = mount_read_only;
        // Refused only where the place was read-only for the grader too (a
        // read-only mount inherited into a user namespace is locked).
        for (const std::string& place : writable_) set_mount_attributes(place.c_str(), 0, writable);
    }
    // No set-user-ID program gains a user (root's programs: own_user.cpp).
    if (own_user_namespace && prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
    return bring_loopback_up();
}

}  // namespace simcheck
