#include "memory_held.hpp"

#include "ipc_objects.hpp"
#include "process_list.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <linux/sock_diag.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>

namespace simcheck {
namespace {

// Resident less shared (file pages and shared memory): what the process
// holds alone, its heap and stacks, which grow as it allocates.
std::int64_t private_resident(const char* pid) {
    FILE* file = std::fopen((std::string("/proc/") + pid + "/statm").c_str(), "re");
    if (!file) return 0;
    long long size = 0, resident = 0, shared = 0;
    const int read = std::fscanf(file, "%lld %lld %lld", &size, &resident, &shared);
    std::fclose(file);
    if (read != 3 || resident < shared) return 0;
    return (resident - shared) * static_cast<std::int64_t>(sysconf(_SC_PAGESIZE));
}

std::int64_t bytes_waiting(int descriptor, const struct stat& info) {
    if (S_ISFIFO(info.st_mode)) {
        // Each byte waiting may sit on a page of its own (a pipe in packet
        // mode, O_DIRECT, gives each write one), up to the pipe's capacity.
        int bytes = 0;
        const int capacity = fcntl(descriptor, F_GETPIPE_SZ);
        if (ioctl(descriptor, FIONREAD, &bytes) != 0 || bytes <= 0 || capacity <= 0) return 0;
        return std::min(std::int64_t{capacity}, std::int64_t{bytes} * sysconf(_SC_PAGESIZE));
    }
    std::uint32_t memory[SK_MEMINFO_VARS] = {};
    socklen_t size = sizeof memory;
    if (getsockopt(descriptor, SOL_SOCKET, SO_MEMINFO, memory, &size) != 0) return 0;
    return std::int64_t{memory[SK_MEMINFO_RMEM_ALLOC]} + memory[SK_MEMINFO_WMEM_ALLOC] + memory[SK_MEMINFO_WMEM_QUEUED];
}

// The pipes and sockets process `pid` holds open that none counted before
// (`counted`, by device and inode).
std::int64_t queued_in(const char* pid, std::set<std::pair<dev_t, ino_t>>& counted) {
    const std::string descriptors = std::string("/proc/") + pid + "/fd";
    DIR* listing = opendir(descriptors.c_str());
    if (!listing) return 0;
    const int process = static_cast<int>(syscall(SYS_pidfd_open, std::atoi(pid), 0));
    if (process < 0) {
        closedir(listing);
        return 0;
    }
    std::int64_t bytes = 0;
    while (const dirent* entry = readdir(listing)) {
        if (entry->d_name[0] < '0' || entry->d_name[0] > '9') continue;
        struct stat info {};
        // stat, not lstat: the open file itself.
        if (fstatat(dirfd(listing), entry->d_name, &info, 0) != 0) continue;
        if (!S_ISFIFO(info.st_mode) && !S_ISSOCK(info.st_mode)) continue;
        if (counted.count({info.st_dev, info.st_ino}) != 0) continue;
        const int copy = static_cast<int>(syscall(SYS_pidfd_getfd, process, std::atoi(entry->d_name), 0));
        if (copy < 0) continue;
        counted.insert({info.st_dev, info.st_ino});
        bytes += bytes_waiting(copy, info);
        close(copy);
    }
    close(process);
    closedir(listing);
    return bytes;
}

}  // namespace

MemoryHeld memory_held(uid_t user, pid_t group, bool ipc_too) {
    MemoryHeld held;
    std::set<std::pair<dev_t, ino_t>> counted;
    for_each_program_process(user, group, [&](const char* pid) {
        held.resident += private_resident(pid);
        held.queued += queued_in(pid, counted);
    });
    if (ipc_too) held.ipc = ipc_bytes_of(user);
    return held;
}

}  // namespace simcheck
