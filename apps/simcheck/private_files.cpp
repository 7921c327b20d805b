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

}  // namespace

bool lies_within(const fs::path& path, const fs::path& directory) {
    std::error_code error;
    const fs::path inside = fs::weakly_canonical(path, error);
    fs::path outer = fs::weakly_canonical(directory, error);
    if (!outer.has_filename()) outer = outer.parent_path();  // "dir/" names dir
    return std::mismatch(outer.begin(), outer.end(), inside.begin(), inside.end()).first == outer.end();
}

std::vector<std::string> private_entries(const std::vector<std::string>& needed) {
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
        if (std::none_of(needed.begin(), needed.end(), [&](const std::string& k) { return lies_within(k, entry); }))
            hidden.push_back(entry.string());
    }
    std::sort(hidden.begin(), hidden.end());
    hidden.erase(std::unique(hidden.begin(), hidden.end()), hidden.end());
    return hidden;
}

}  // namespace simcheck
