#pragma once
// The exact engine's tuning: thresholds that choose how events are found,
// never which events happen (every value gives the same events; the tests
// force the other choices too). Measured on the 2-core benchmark machine
// (docs/benchmarks.md); figures that depend on the machine say so.

#include <cstdint>

namespace particlesim::exact_tuning {

// --- Runaway steps (TooManyEvents)

// Events a step may take beyond the prediction before it counts as runaway:
// floor + factor x (predicted events + particles). Generous (dense clusters
// collide far more often than an ideal gas), yet reached within about a
// second.
inline constexpr double runaway_floor = 1e6;
inline constexpr double runaway_factor = 100.0;

// --- Neighbour cells

// Cells are at least a diameter wide; in a sparse box about this many
// particles share one.
inline constexpr double particles_per_cell = 4.0;
// In a dense box a cell is no wider than this fraction of the mean free path.
inline constexpr double cell_in_free_paths = 0.5;

// --- One cell and the particles' lines instead of cells (sparse scenes)

// A cost model of one event, fitted to runs of both ways from 500 to 16 000
// disks, sparse to dense. Machine dependent (nanoseconds of the benchmark
// machine, AVX-512): only their ratios matter.
inline constexpr double line_event_ns = 200.0;       // an event with the lines ...
inline constexpr double line_test_ns = 0.06;         // ... plus this a line tested
inline constexpr double cell_event_ns = 110.0;       // an event with the cells
inline constexpr double lines_chosen_below = 0.8;    // lines' cost / cells' cost; the margin covers stale predictions
inline constexpr std::uint32_t lines_up_to = 20000;  // particles: the first predictions test all N^2 / 2 pairs
// ... unless the lines crowd together, which the model (spread lines) does
// not see: then each prediction tests nearly every disk exactly. Lines of
// the start's particles probed (evenly spread over the indices), and the
// cells taken where the probed lines meet more than this many others on
// average (a cell search tests about 36 disks): simgen's `line` and
// `cradle` at 20000 disks take 1.64 s and 5.15 s for 10 steps by the
// lines, 0.13 s and 0.65 s by 64 x 64 cells.
inline constexpr std::uint32_t lines_probed = 64;
inline constexpr double lines_crowd_from_near = 32.0;

// A start that fills the cells unevenly (rows and walls lined with touching
// disks, dense clusters in an empty box) gives a disk far more cell mates
// than the model's even spread (about 5 at 4 a cell): its grid is refined,
// the side doubled, while a disk shares its cell with more than this many
// on average, up to this many cells a disk (and cells a contact distance
// wide, max_grid_cells a side). simgen's `cradle` at 20000 disks took 0.60 s
// for 10 steps by the model's 71 x 71 cells, 0.055 s by 1024 x 1024.
inline constexpr double crowded_cell_mates = 16.0;
inline constexpr double crowded_cells_per_particle = 64.0;

// --- The look ahead along the queue

// Particles from which each event prefetches what the next events will
// read, and the queue is the two-tier calendar: below, the state mostly fits
// in the caches, and the prefetching's own work, and the two tiers' (stale
// listings, bins spread into buckets), cost more than they save. On the gas
// (`particlesim_bench exact_queue`, both forced, 7 rounds): 1.29 times the
// linked buckets' time at 8192 disks, 1.07 at 24 576, 0.99 at 28 672, 0.97
// at 32 768 and 0.70 at 49 152; beside a busy process 1.03 at 28 672 and
// 0.97 at 32 768. (Since a particle's state shares a line with its cell
// links, the linked buckets keep up to larger sizes: 20 480 before.)
inline constexpr std::uint32_t look_ahead_from = 32768;
// The four stages' distances in calendar buckets: entries and links, then
// particles, then partners and cell heads, then the cells' first members
// ((16, 12, 8, 4) to (4, 3, 2, 1) measured within noise of one another).
inline constexpr std::uint32_t look_entries_buckets = 8;
inline constexpr std::uint32_t look_particles_buckets = 6;
inline constexpr std::uint32_t look_heads_buckets = 4;
inline constexpr std::uint32_t look_members_buckets = 2;

}  // namespace particlesim::exact_tuning
