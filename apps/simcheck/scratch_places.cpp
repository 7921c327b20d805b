#include "scratch_places.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace simcheck {

std::vector<std::string> scratch_places() {
    namespace fs = std::filesystem;
    std::vector<std::string> named{"/tmp", "/var/tmp", "/dev/shm"};
    if (const char* tmpdir = std::getenv("TMPDIR"); tmpdir && *tmpdir) named.emplace_back(tmpdir);
    std::vector<std::string> places;
    for (const std::string& place : named) {
        std::error_code error;
        const fs::path canonical = fs::canonical(place, error);
        if (!error && fs::is_directory(canonical, error)) places.push_back(canonical.string());
    }
    std::sort(places.begin(), places.end());
    places.erase(std::unique(places.begin(), places.end()), places.end());
    return places;
}

}  // namespace simcheck
