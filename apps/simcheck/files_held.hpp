#pragma once
// The bytes a graded program's files hold on disk (or in memory, in
// /dev/shm). RLIMIT_FSIZE caps each file, not how many: a program writing
// a thousand files of a megabyte each would fill the disk, or the memory
// behind /dev/shm, within its time limit. The grader measures these bytes
// while the program runs and stops it once they pass its cap.

#include <sys/types.h>

#include <cstdint>
#include <string>

namespace simcheck {

// How deep below its working directory, or below an entry of its own in a
// scratch place, the walk goes: each level holds a descriptor while it is
// walked. No simulation nests its files this deep.
constexpr int max_files_depth = 64;

struct FilesHeld {
    std::int64_t bytes = 0;
    bool too_deep = false;  // directories nested deeper than max_files_depth, not walked
};

// The bytes allocated to the files under `directory` (the program's
// working directory), and, for a user of its own (`user` not 0), to every
// entry it owns in the scratch places (scratch_places.hpp), whole; and to
// the files its processes hold open that no directory names (a memfd, an
// unlinked temporary), which hold memory or disk as long as they are
// open: its processes are its user's, or, without one, its process group
// `group`'s. Links are not followed; a file that goes while it is measured
// counts nothing. Allocated, not apparent: a sparse file counts what it
// holds; but every entry at least 4 KiB, so that a flood of empty files
// counts too.
FilesHeld files_held(uid_t user, pid_t group, const std::string& directory);

}  // namespace simcheck
