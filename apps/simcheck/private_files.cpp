#include "private_files.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace simcheck {
namespace {

namespace fs = std::filesystem;

bool others_may_read(const fs::path& path) {
    struct stat info {};
    return lstat(path.c_str(), &info) == 0 && (S_ISLNK(info.st_mode) || (info.st_mode & S_IROTH) != 0);
}

// Whether `path` is `needed` or lies above it (hiding it would hide what is needed).
bool holds(const fs::path& path, const fs::path& needed) {
    return std::mismatch(path.begin(), path.end(), needed.begin(), needed.end()).first == path.end();
}

}  // namespace

std::vector<std::string> private_entries(const std::vector<std::string>& needed) {
    std::vector<fs::path> kept;
    for (const std::string& path : needed) {
        std::error_code error;
        const fs::path resolved = fs::weakly_canonical(path, error);
        if (!error) kept.push_back(resolved);
    }
    std::vector<fs::path> places{"/etc", "/etc/ssh", "/etc/ssl", "/root"};
    if (const char* home = std::getenv("HOME"); home && *home) places.emplace_back(home);
    std::vector<fs::path> entries;
    std::error_code error;
    for (fs::directory_iterator home(fs::path("/home"), error), end; !error && home != end; home.increment(error)) {
        // A home that others may not read is hidden whole; else what in it they may not read.
        if (others_may_read(home->path())) {
            places.push_back(home->path());
        } else {
            entries.push_back(home->path());
        }
    }
    for (const fs::path& place : places) {
        std::error_code listing_error;
        const fs::path resolved = fs::weakly_canonical(place, listing_error);
        if (listing_error || resolved == "/" || !fs::is_directory(resolved, listing_error)) continue;
        for (fs::directory_iterator entry(resolved, listing_error), end; !listing_error && entry != end;
             entry.increment(listing_error)) {
            if (!others_may_read(entry->path())) entries.push_back(entry->path());
        }
    }
    std::vector<std::string> hidden;
    for (const fs::path& entry : entries) {
        if (std::none_of(kept.begin(), kept.end(), [&](const fs::path& k) { return holds(entry, k); }))
            hidden.push_back(entry.string());
    }
    std::sort(hidden.begin(), hidden.end());
    hidden.erase(std::unique(hidden.begin(), hidden.end()), hidden.end());
    return hidden;
}

}  // namespace simcheck
