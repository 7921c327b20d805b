#include "files_held.hpp"

#include "scratch_places.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

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

}  // namespace

std::int64_t bytes_held(uid_t user, const std::string& directory) {
    if (user == 0) return bytes_below(directory);
    // Its working directory is its own too, in one of the places.
    std::int64_t bytes = 0;
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
