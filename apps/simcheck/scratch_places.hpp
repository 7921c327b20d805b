#pragma once
// The places any program may expect to write besides its working
// directory: /tmp, /var/tmp, /dev/shm and $TMPDIR (MPI's runtime keeps its
// files and shared memory there). An isolated program may write
// nowhere else (isolation.hpp); a user of its own leaves nothing in them
// (own_user.hpp).

#include <sys/stat.h>
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace simcheck {

// Those of them that are directories, each once (a place named twice
// through a link is listed once), by canonical path, sorted: a place comes
// before the places inside it.
std::vector<std::string> scratch_places();

// visit(path, info) for each entry of the scratch places that `user` owns,
// by lstat (a link is an entry itself, never followed).
template <typename Visit>
void for_each_entry_owned_by(uid_t user, Visit&& visit) {
    for (const std::string& place : scratch_places()) {
        std::error_code error;
        for (std::filesystem::directory_iterator entry(place, error), end; !error && entry != end;
             entry.increment(error)) {
            struct stat info {};
            if (lstat(entry->path().c_str(), &info) == 0 && info.st_uid == user) visit(entry->path(), info);
        }
    }
}

}  // namespace simcheck
