#pragma once
// The places any program may expect to write besides its working
// directory: /tmp, /var/tmp, /dev/shm and $TMPDIR (MPI's runtime keeps its
// files and shared memory there). An isolated program may write
// nowhere else (isolation.hpp); a user of its own leaves nothing in them
// (own_user.hpp).

#include <string>
#include <vector>

namespace simcheck {

// Those of them that are directories, each once (a place named twice
// through a link is listed once), by canonical path, sorted: a place comes
// before the places inside it.
std::vector<std::string> scratch_places();

}  // namespace simcheck
