#include "files_held.hpp"

#include "process_list.hpp"
#include "scratch_places.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <system_error>
#include <utility>

namespace simcheck {
namespace {

namespace fs = std::filesystem;

// Every entry at least a page: an empty file still takes an inode (memory,
// in /dev/shm), so a million of them count 4 GB.
constexpr std::int64_t least_per_entry = 4096;

std::int64_t allocated(const fs::path& path) {
    struct stat info {};
    if (lstat(path.c_str(), &info) != 0) return 0;
    return std::max(static_cast<std::int64_t>(info.st_blocks) * 512, least_per_entry);
}

// `path` and, if it is a directory (not a link to one), everything below it.
std::int64_t bytes_below(const fs::path& path) {
    std::int64_t bytes = allocated(path);
    std::error_code error;
    if (!fs::is_directory(fs::symlink_status(path, error))) return bytes;
    for (fs::recursive_directory_iterator entry(path, fs::directory_options::skip_permission_denied, error), end;
         !error && entry != end; entry.increment(error))
        bytes += allocated(entry->path());
    return bytes;
}

// The files that the program's processes hold open and no directory names:
// each counted once, however many descriptors reach it.
std::int64_t bytes_open_unnamed(uid_t user, pid_t group) {
    std::set<std::pair<dev_t, ino_t>> counted;
    std::int64_t bytes = 0;
    for_each_process([&](const char* pid) {
        if (user != 0) {
            if (process_owner(pid) != user) return;
        } else {
            ProcessStat stat;
            if (!read_process_stat(pid, stat) || stat.group != group) return;
        }
        const fs::path descriptors = fs::path("/proc") / pid / "fd";
        std::error_code error;
        for (fs::directory_iterator entry(descriptors, error), end; !error && entry != end; entry.increment(error)) {
            struct stat info {};
            // stat, not lstat: the open file itself.
            if (stat(entry->path().c_str(), &info) != 0 || !S_ISREG(info.st_mode) || info.st_nlink != 0) continue;
            if (counted.insert({info.st_dev, info.st_ino}).second)
                bytes += std::max(static_cast<std::int64_t>(info.st_blocks) * 512, least_per_entry);
        }
    });
    return bytes;
}

}  // namespace

std::int64_t bytes_held(uid_t user, pid_t group, const std::string& directory) {
    if (user == 0) return bytes_below(directory) + bytes_open_unnamed(user, group);
    // Its working directory is its own too, in one of the places.
    std::int64_t bytes = bytes_open_unnamed(user, group);
    for (const std::string& place : scratch_places()) {
        std::error_code error;
        for (fs::directory_iterator entry(place, error), end; !error && entry != end; entry.increment(error)) {
            struct stat info {};
            if (lstat(entry->path().c_str(), &info) == 0 && info.st_uid == user) bytes += bytes_below(entry->path());
        }
    }
    return bytes;
}

}  // namespace simcheck
