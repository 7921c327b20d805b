#pragma once
// The wall candidates of a block of particles, eight particles at a time in
// AVX-512 lanes: their wall times compared with the step's end, those at or
// before it compressed together with their indices and written as whole
// Collision records, three vectors for eight. One at a time (the portable
// form, and a block's last few particles), every particle's record is
// written and only a hit's kept; a quarter of a sparse scene's particles
// hit a wall in a step.

#include "core/collision.hpp"

#include <cstddef>
#include <cstdint>

namespace particlesim {

// Writes Collision::wall(wall_time[i], i) for each particle i of [first,
// last) whose wall time is at most `duration`, in index order, to
// out[0], out[1], ... while fewer than `room` are written, and never past
// out[room - 1]. Returns the particle it stopped at (last, or the first
// not examined) and the records written; without the lanes, {first, 0}.
struct WallCandidatesWritten {
    std::int64_t next;
    std::size_t written;
};
WallCandidatesWritten write_wall_candidates_in_lanes(const double* wall_time, double duration, std::int64_t first,
                                                     std::int64_t last, Collision* out, std::size_t room);

}  // namespace particlesim
