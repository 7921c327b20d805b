#include "files_held.hpp"

#include "process_list.hpp"
#include "scratch_places.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string_view>
#include <system_error>
#include <utility>

namespace simcheck {
namespace {

namespace fs = std::filesystem;

// Every entry at least a page: an empty file still takes an inode (memory,
// in /dev/shm), so a million of them count 4 GB.
constexpr std::int64_t least_per_entry = 4096;

std::int64_t allocated(const struct stat& info) {
    return std::max(static_cast<std::int64_t>(info.st_blocks) * 512, least_per_entry);
}

// Everything below the open directory `directory` (closed here), by
// descriptors relative to it: no path is built, so a tree nested
// thousands deep costs neither memory nor PATH_MAX, and each level holds
// one descriptor (recursion at most max_files_depth deep).
void add_below(int directory, int depth, FilesHeld& held) {
    DIR* listing = fdopendir(directory);
    if (!listing) {
        close(directory);
        return;
    }
    while (const dirent* entry = readdir(listing)) {
        const std::string_view name = entry->d_name;
        if (name == "." || name == "..") continue;
        struct stat info {};
        if (fstatat(dirfd(listing), entry->d_name, &info, AT_SYMLINK_NOFOLLOW) != 0) continue;
        held.bytes += allocated(info);
        if (!S_ISDIR(info.st_mode)) continue;
        if (depth == max_files_depth) {
            held.too_deep = true;
            continue;
        }
        const int below = openat(dirfd(listing), entry->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (below >= 0) add_below(below, depth + 1, held);
    }
    closedir(listing);
}

// `name` in the open directory `parent` (or a path, with AT_FDCWD) and, if
// it is a directory (not a link to one), everything below it.
void add_entry(int parent, const char* name, FilesHeld& held) {
    struct stat info {};
    if (fstatat(parent, name, &info, AT_SYMLINK_NOFOLLOW) != 0) return;
    held.bytes += allocated(info);
    if (!S_ISDIR(info.st_mode)) return;
    const int directory = openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (directory >= 0) add_below(directory, 1, held);
}

// The files that the program's processes hold open and no directory names:
// each counted once, however many descriptors reach it.
std::int64_t bytes_open_unnamed(uid_t user, pid_t group) {
    std::set<std::pair<dev_t, ino_t>> counted;
    std::int64_t bytes = 0;
    for_each_program_process(user, group, [&](const char* pid) {
        const fs::path descriptors = fs::path("/proc") / pid / "fd";
        std::error_code error;
        for (fs::directory_iterator entry(descriptors, error), end; !error && entry != end; entry.increment(error)) {
            struct stat info {};
            // stat, not lstat: the open file itself.
            if (stat(entry->path().c_str(), &info) != 0 || !S_ISREG(info.st_mode) || info.st_nlink != 0) continue;
            if (counted.insert({info.st_dev, info.st_ino}).second) bytes += allocated(info);
        }
    });
    return bytes;
}

}  // namespace

FilesHeld files_held(uid_t user, pid_t group, const std::string& directory) {
    FilesHeld held;
    held.bytes = bytes_open_unnamed(user, group);
    if (user == 0) {
        add_entry(AT_FDCWD, directory.c_str(), held);
        return held;
    }
    // Its working directory is its own too, in one of the places.
    for_each_entry_owned_by(
        user, [&](const fs::path& entry, const struct stat&) { add_entry(AT_FDCWD, entry.c_str(), held); });
    return held;
}

}  // namespace simcheck
