#pragma once
// The stepped engine's tuning: every threshold that chooses how a step is
// computed, never what it computes (each value gives the same bytes; the
// tests force the other choices too). Measured on the 2-core benchmark
// machine (docs/benchmarks.md); figures that depend on the machine say so.

#include <cstddef>
#include <cstdint>

namespace particlesim::stepped_tuning {

// --- Which pair search `PairSearch::automatic` takes (stepped_simulation.cpp)

// Particles below which the brute force beats the grid (both cost 0.2 to
// 2 us a step at N = 4 and 16; the grid wins from N = 64).
inline constexpr std::size_t brute_force_below = 48;
// Otherwise the paths search or the grid, whichever a cost model of a
// micro-step finds cheaper (search_choice.cpp). Fitted to one thread's runs
// of both searches on the rules' random scene at the default scene's density
// and the gas at area fraction 0.3, 64 to 16384 particles: the grid within
// 13 % of every run, the paths search within 15 % from 1000 to 8000 disks
// (the close calls) and within 37 % elsewhere, where the margins are wide;
// nanoseconds of the benchmark machine (AVX2: eight float lanes), so only
// their ratios matter. The paths search: each new line ...
inline constexpr double paths_new_line_ns = 180.0;
// ... plus this for each line it is tested against (eight lanes) ...
inline constexpr double paths_line_test_ns = 0.16;
// ... or these where the processor tests sixteen lines at a time (AVX-512):
// fitted to both searches forced on an Intel host with AVX-512
// (search_choice_sizes_family.csv), where the model takes the faster on
// all 21 scenes (the grid at 8192 and 16384 disks at the default density
// and speeds, 1.32 and 2.08 times faster; 4000 in L = 20000 a tie), and on
// an AMD host's run before the grid placed its boxes as records
// (search_choice_grid_lines.csv) on 14 of 15, the miss 1.21 times.
inline constexpr double paths_new_line_sixteen_lanes_ns = 50.0;
inline constexpr double paths_line_test_sixteen_lanes_ns = 0.11;
// ... plus this times the fraction that pass (about 4r / L): their intervals.
inline constexpr double paths_near_line_ns = 100.0;
// The grid: each particle, plus this for each time slice it is binned in ...
inline constexpr double grid_particle_ns = 30.0;
inline constexpr double grid_particle_slice_ns = 60.0;
// ... or this where the grid scans sixteen boxes and lines at a time
// (AVX-512), fitted with the paths search's sixteen lanes above.
inline constexpr double grid_particle_slice_sixteen_lanes_ns = 27.0;
// Particles up to which the paths search may be chosen: its first
// micro-step tests all N^2 / 2 pairs.
inline constexpr std::size_t paths_up_to = 20000;
// The most pairs the paths search watches before it hands over to the grid
// for the rest of the run (the same candidates; docs/architecture.md,
// "Handing over to the grid"): a per particle and a floor. Where lines
// crowd together nearly every pair is watched and tested each micro-step:
// simgen's `line` (a row moving along itself) watches 132 a particle, and
// 5000 disks piled on one point all 12.5 M pairs (787 MB, 8 s a step
// against the grid's 6 MB and 0.1 s). The rules' random scenes watch 0.04
// (the default scene) to 0.22 a particle. Where automatic chose it, past 2
// a particle the watched pairs' tests cost about the grid's whole step
// (`simgen walls` and `line`: the grid 2 to 16 times faster); where it was
// asked for, only a bound on memory (32 bytes a watch).
inline constexpr std::size_t paths_watches_per_particle_chosen = 2;
inline constexpr std::size_t paths_watches_floor_chosen = 4096;
inline constexpr std::size_t paths_watches_per_particle_asked = 16;
inline constexpr std::size_t paths_watches_floor_asked = 65536;
// Line tests (new lines x particles) a micro-step must give each thread
// before the paths search shares them out: a second thread cost 1.19 times
// one's time at 1.1 M tests a micro-step (N = 2000) and 1.25 at 0.25 M (the
// default scene), and paid from about 5 M (N = 4000: 0.82).
inline constexpr std::int64_t paths_line_tests_per_thread = std::int64_t{1} << 21;
// The same for the first micro-step, whose lines are all new (N^2 tests):
// its region is the run's only shared one where the steps after it share
// none, and its second thread then spins beside them. Two threads took
// 1.07 times one thread's time at 4096 disks of the default density (all
// 16.7 M tests shared), 1.00 without the spinning (GOMP_SPINCOUNT=0).
inline constexpr std::int64_t paths_afresh_line_tests_per_thread = std::int64_t{1} << 24;

// Particles from which threads share a slice's binning and scan at all:
// below, the three regions a step gain nothing on a quiet machine (the gas
// at 4096: two threads 0.999 of one thread's time, the fastest of 31 runs)
// and lose where neighbours take the other core now and then (1.13, the
// median of the runs).
inline constexpr std::size_t grid_shared_from = 8192;

// --- Storage sorted by position (stepped/storage_order.*)

// Particles from which the storage is sorted by position: below, the state
// stays in the caches in any order ...
inline constexpr std::size_t sort_by_position_from = 65536;
// ... unless threads share the grid search's binning and the stages after
// it from here on: each takes a block of the storage, and in the scene's
// own order every block has particles in every cell, so that the threads
// write the same cache lines (the gas at 16384 particles: two threads took
// 1.06 to 1.12 times one thread's time unsorted, 0.86 sorted). The paths
// search keeps its lines by stored index, and would make them all afresh
// at every sort.
inline constexpr std::size_t sort_by_position_shared_from = grid_shared_from;
// Steps between sorts: faster particles scramble the order sooner, and each
// sort costs a pass over the particles (16 and 32 measured no different).
inline constexpr int sort_every_steps = 8;
// Cells of the sort's grid hold about this many particles: fine enough that
// a grid cell's particles sit together in memory, coarse enough that the
// cell counts stay small.
inline constexpr double sort_particles_per_cell = 2.0;
// Places a displaced particle may wait for its turn when a scene sorted a
// few steps ago is sorted again (particles: 48 bytes each). Its particles
// then move at most a few rows of cells in the order (a row holds about
// sqrt(2 N) particles), so this holds every particle displaced ahead of it.
inline constexpr std::size_t sort_window = 16384;
// Hops along a permutation cycle fetched ahead when moving particles.
inline constexpr int sort_fetch_ahead = 8;

// --- Threads (parallel/parallel.hpp, stepped/thread_choice.hpp)

// Particles up to which a step whose threads the user did not set times one
// thread against all now and then and runs the faster: a small scene's step
// (tens of microseconds) loses to a second core that something else holds.
inline constexpr std::size_t threads_by_trials_up_to = 20000;
// The trials: after `trial_warm_up_steps`, `trial_blocks` blocks of
// `trial_block_steps` on each count (the first step of a block, which pays
// for the switch, not counted); then the faster count runs `trial_run_steps`.
inline constexpr int trial_warm_up_steps = 8;
inline constexpr int trial_block_steps = 4;
inline constexpr int trial_blocks = 4;
inline constexpr int trial_run_steps = 240;
// Above threads_by_trials_up_to: a watch on all the threads lasts at least
// `contention_watch_steps` and `contention_watch_seconds`; the process's
// run-queue wait over it, above `contended_wait_share` of its wall time,
// starts a trial (the threads' waits summed: quiet, 0.018 to 0.028 of the
// wall time on the AMD host; beside one busy process on its two cores, 0.63
// to 0.72; run_queue_waits.csv). Such a trial runs `contended_trial_steps`
// on one thread (the first not counted) and sets their mean against the
// watch's. A watch spans seconds, not steps, because beside a busy process
// steps on two threads run unhindered for 0.2 to 1 s and then stall for the
// other process's turn: a few steps say little (thread_steps_loaded.csv).
inline constexpr int contention_watch_steps = 8;
inline constexpr double contention_watch_seconds = 0.5;
inline constexpr double contended_wait_share = 0.1;
inline constexpr int contended_trial_steps = 8;
// The share of one thread's step time that all the threads must beat in such
// a trial to run the stretch: a watch of 0.5 s can fall between two of the
// other process's turns (N = 32000 on the AMD host: the median step on two
// threads 0.85 of one thread's, and whole runs on two threads 1.09 and 1.11
// of one thread's time; thread_steps_loaded.csv, loaded_run_queue_waits.csv).
inline constexpr double contended_trial_margin = 0.8;

// --- Pairs at t = 0 (stepped/immediate_selection.cpp)

// The candidates at t = 0 a step keeps (a per particle and a floor) before
// the selection decides those pairs from the particles instead
// (immediate_selection.hpp): one pass over the particles and a grid of
// contact-wide cells, about what the rounds spend on N candidates. Only
// touching or overlapping disks make them: a few in a gas left overlapping
// by the steps before, up to k^2 / 2 for k disks piled on one another.
inline constexpr std::size_t immediate_candidates_per_particle = 1;
inline constexpr std::size_t immediate_candidates_floor = 4096;
// A first slice whose cells hold more pairs than this (a per particle and a
// floor; sum over cells of count^2 / 2) has the pairs at t = 0 decided
// before its scan (grid_search.cpp, process_slice()): the gas at area
// fraction 0.3 and the rules' random scenes hold a few pairs a particle
// (cells of about one to four boxes), a pile of k disks k^2 / 2 in one cell.
inline constexpr double crowded_cell_pairs_per_particle = 64.0;
inline constexpr double crowded_cell_pairs_floor = 1 << 16;
// ... and where, of this many neighbouring boxes of the fullest cell taken
// in pairs, more than one in this many meet at t = 0 (in a pile about one
// in two; disks flying apart from a pile recede, none).
inline constexpr std::uint32_t crowded_pairs_sampled = 64;
inline constexpr std::uint32_t crowded_pairs_at_zero_from = 8;

// --- Blocks of the stages (stepped/step_pipeline.cpp)

// Candidates a block of the selection's passes holds.
inline constexpr std::int64_t selection_block = 4096;
// Particles a block of the resolution lists at once, and how many listed
// pairs ahead their partners are fetched.
inline constexpr std::int64_t resolution_block = 1024;
inline constexpr std::size_t resolution_fetch_ahead = 16;
// Collided particles (two a pair, one a wall hit) a thread must have before
// the resolution takes a second one: its pass over the particles is light,
// and below this a second thread cost more than it saved.
inline constexpr std::int64_t resolution_collided_per_thread = 1024;

// --- The grid search (search/grid_search.cpp)

// A slice's typical path, in mean particle spacings: fewer, longer slices bin
// fewer boxes but test more pairs, and leave out the decided particles later
// (with the decisions between slices, 1.8 to 2.4 were the fastest at N =
// 8000 and 32000, 0.92 of 4/3's time; without them 4/3 had been).
inline constexpr double slice_sweep_in_spacings = 2.0;
// With a forced grid, a slice's typical path in cells: at most half a cell,
// so that most boxes fit their cell.
inline constexpr double slice_sweep_in_forced_cells = 0.5;
// The most slices a step is cut into.
inline constexpr int max_slices = 64;
// Slices from which the search lets the selection decide collisions between
// slices, and leaves the decided particles out of the later ones.
inline constexpr int decide_from_slices = 4;
// The most equal pieces in time a path whose box exceeds a cell is cut
// into, each binned as a box of its own: fast particles then cost a few more
// boxes instead of joining the large boxes, which meet each other in a
// quadratic loop. Longer paths stay large.
inline constexpr int max_pieces = 8;
// Particles below which threads take whole slices each, where a step has
// a slice a thread or more; from here on a step has one slice, which the
// threads share.
inline constexpr std::size_t slice_parallel_below = 50000;
// ... unless the particles are expected to collide this often in the first
// slice (its mean path through the others' density, 4r wide, ideal gas):
// a scene dense enough that the first slices decide most particles (the
// later ones leave them out). Then the slices are searched one after
// another, each shared by the threads: a thread a slice searches the second
// before the first's decisions, with nearly every path still in it. On
// simgen's `fast` family (30000 disks, area fraction 0.5, paths of several
// box sides a step), two threads taking a slice each make 2.5 times one
// thread's pair tests and take 1.4 to 1.7 times its time, 0.55 shared; on
// the gas at area fraction 0.3 and 30 to 60 r a step, 1.3 to 1.5 times,
// and shared 1.0.
// Sparse scenes (the rules' random scene at any speed) keep a thread a slice.
inline constexpr double slices_shared_from_first_slice_collisions = 0.75;
// Ranges of cells each worker sums when the threads share a slice's binning.
inline constexpr std::size_t cell_ranges_per_worker = 8;
// Boxes a cell from which a slice's scans test the particles' lines too:
// paths long against the spacing, whose boxes overlap far more often than
// the particles come near (docs/benchmarks.md). Below, boxes of about one
// a cell are filter enough.
inline constexpr double lines_from_boxes_per_cell = 2.0;
// Cells ahead in the row above whose motion states the scan fetches.
inline constexpr int scan_fetch_cells_ahead = 16;

}  // namespace particlesim::stepped_tuning
