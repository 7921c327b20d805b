#include "search/grid_search.hpp"

#include "core/assert.hpp"
#include "core/lane_choice.hpp"
#include "core/prefetch.hpp"
#include "core/uniform_grid.hpp"
#include "parallel/parallel.hpp"
#include "search/box_records.hpp"
#include "search/float_bounds_array.hpp"
#include "search/grid_binning_lanes.hpp"
#include "search/path_lines.hpp"
#include "stepped/stepped_tuning.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace particlesim {

struct GridSearch::SliceWorkspace {
    std::vector<std::uint32_t> cell_of;  // by particle: its cell, or absent / large
    std::vector<std::uint32_t> cell_start;
    std::vector<std::uint32_t> cell_fill;  // per worker after the first: its count, then its next place, in each cell
    std::vector<std::uint32_t> by_cell;    // the particle of each box (or piece), sorted by cell
    FloatBoundsArray boxes_by_cell;        // those boxes, in the same order
    // Their particles' motion, in the same order; not copied where the scans
    // test lines (the few pairs that pass read the particles).
    std::vector<PairTestState> states_by_cell;
    // Whether the slice's scans test the particles' lines as well (then
    // boxes_by_cell holds them).
    bool lines = false;
    std::vector<std::uint32_t> large;        // particles whose path fits no cell, even in pieces
    std::vector<SweptBounds> large_boxes;    // their boxes, in the same order
    std::vector<std::uint32_t> large_start;  // per worker: its first place in `large`
    // The paths that fit no cell whole, each worker's listed from the first
    // particle of its block on, and how many of them each worker has.
    std::vector<std::uint32_t> long_paths;
    std::vector<std::uint32_t> long_path_count;
    std::vector<std::uint32_t> range_start;  // per range of cells: its first place in by_cell
    // Per cell, the lowest float min_x and min_y of its boxes (+inf when
    // empty): a box whose max_x (max_y) is below them meets none of them,
    // and the scan leaves the cell out.
    std::vector<float> cell_lowest_x, cell_lowest_y;
};

using namespace stepped_tuning;
using namespace grid_binning;

// The time span of one slice. A particle's path in it runs from `begin` to
// the particle's sweep end (its wall time or the step's end), if earlier.
// Outside the anonymous namespace: GridSearch::Binning holds one.
struct SliceSpan {
    double begin, end;

    [[nodiscard]] bool holds_path(double sweep_end) const { return sweep_end > 0.0 && !(sweep_end < begin); }
    [[nodiscard]] double path_end(double sweep_end) const { return std::min(end, sweep_end); }
};

namespace {

// Generous against rounding: the contact time and the swept boxes carry
// errors of a few ulps of the coordinates and velocities; 1e-8 relative is
// ten million times that, and still far below any cell size it could disturb.
constexpr double relative_margin = 1e-8;

// Boxes whose side is within 2^+-100 are put in float as they are; beyond,
// scaled into [1, 2) first (float spans only 1e-38 to 3e38).
constexpr int float_safe_exponent = 100;

// How far before the end of the slices searched the decisions stop, in
// steps: far beyond any rounding of a slice's edge or of a path's position
// there, and a thousandth of the shortest slice (1 / max_slices of the step).
constexpr double decision_margin = 0x1p-16;

// A box that fits a cell with this slack keeps its neighbours within one cell
// even after the rounding of the cell index computation.
constexpr double cell_fit_slack = 1.0 - 1e-6;

// A particle's path ends at its wall time or at the end of the step.
double sweep_end(const PairSearchInput& in, std::int64_t particle) {
    return std::min(in.duration, in.wall_time[particle]);
}

SliceSpan slice_span(const PairSearchInput& in, int slice, int slices) {
    const double begin = in.duration * slice / slices;
    const double end = slice + 1 == slices ? in.duration : in.duration * (slice + 1) / slices;
    return {begin, end};
}

bool fits_cell(const SweptBounds& box, double fit) {
    return box.max_x - box.min_x <= fit && box.max_y - box.min_y <= fit;
}

// Cells [x_first, x_last] x [y_first, y_last] of the grid.
struct CellRegion {
    int x_first, y_first, x_last, y_last;
};

// The cells whose fitting boxes can meet `box`: a fitting box that meets it
// has its lower corner at most one cell below or left of this box's lower
// corner.
CellRegion cells_reaching(const SweptBounds& box, const UniformGrid& grid) {
    return {std::max(grid.column_of(box.min_x) - 1, 0), std::max(grid.column_of(box.min_y) - 1, 0),
            grid.column_of(box.max_x), grid.column_of(box.max_y)};
}

// Always inlined: it runs for every binned box, and a call costs as much as it does.
[[gnu::always_inline]] inline FloatBounds float_bounds(const SweptBounds& box, double scale) {
    if (scale != 1.0) {  // the same way for every box of a step: predicted
        return {float_at_most(box.min_x * scale), float_at_most(box.min_y * scale), float_at_least(box.max_x * scale),
                float_at_least(box.max_y * scale)};
    }
    return {float_at_most(box.min_x), float_at_most(box.min_y), float_at_least(box.max_x), float_at_least(box.max_y)};
}

}  // namespace

int time_slices(double mean_sweep, double slice_sweep) {
    if (!(slice_sweep > 0.0)) return 1;
    return static_cast<int>(std::clamp(std::ceil(mean_sweep / slice_sweep), 1.0, double{max_slices}));
}

GridSearch::GridSearch(int lanes) : lanes_(chosen_lanes(lanes, supports_lanes, "GridSearch")) {}
GridSearch::~GridSearch() = default;
GridSearch::GridSearch(GridSearch&&) noexcept = default;
GridSearch& GridSearch::operator=(GridSearch&&) noexcept = default;

GridLayout GridSearch::choose_layout(const PairSearchInput& in, std::optional<int> forced_cells, int threads) {
    // The blocks' sums, measured here unless the step has them already.
    std::span<const BlockStart> blocks = in.blocks;
    if (blocks.empty()) {
        const auto count = static_cast<std::int64_t>(in.particles.size());
        const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
        block_starts_.resize(static_cast<std::size_t>((count + motion_block - 1) / motion_block));
        parallel_for_blocks(workers, count, motion_block,
                            [&](std::int64_t block, std::int64_t first, std::int64_t last) {
                                MotionSums measured;
                                for (std::int64_t i = first; i < last; ++i) {
                                    measured.add(in.particles[i].velocity, in.wall_time[i], in.duration);
                                }
                                block_starts_[block].motion = measured;
                            });
        blocks = block_starts_;
    }
    MotionSums motion;
    for (const BlockStart& block : blocks) motion.add(block.motion);
    const double length_sum = motion.length_sum;
    const double max_speed = motion.max_speed;
    const std::int64_t present = motion.present;

    const double box_size = in.box.side;
    GridLayout layout;
    layout.reach = in.box.lower + relative_margin * (box_size + max_speed * in.duration);
    // Floats keep 24 bits of any coordinate between 1e-30 and 1e30 of L: only
    // boxes beyond that are scaled.
    const int exponent = std::ilogb(box_size);
    layout.float_scale = std::abs(exponent) > float_safe_exponent ? std::ldexp(1.0, -exponent) : 1.0;
    // Lines scaled as PathLines scales them: positions lie in [0, L], and
    // max_speed bounds every velocity component.
    layout.line_position_scale = power_of_two_below(box_size);
    layout.line_velocity_scale = power_of_two_below(max_speed);
    layout.line_terms = line_test_terms(box_size * layout.line_position_scale, max_speed * layout.line_velocity_scale,
                                        contact_reach(in.box) * layout.line_position_scale);
    const double mean_sweep = length_sum / static_cast<double>(std::max<std::int64_t>(present, 1));
    const double diameter = 2.0 * layout.reach;
    const auto slices_for = [&](double slice_sweep) { return time_slices(mean_sweep, slice_sweep); };

    if (forced_cells) {
        layout.grid = UniformGrid(box_size, *forced_cells);
        layout.slices = slices_for(slice_sweep_in_forced_cells * (layout.grid.cell_size() - diameter));
    } else {
        // Cells at least a particle spacing wide and twice a typical slice
        // path, so that most swept boxes fit their cell; at most ~4 cells per
        // particle, so that memory stays O(N).
        const double area = in.area > 0.0 ? in.area : box_size * box_size;
        const double spacing = std::sqrt(area / static_cast<double>(std::max<std::int64_t>(present, 1)));
        layout.slices = slices_for(slice_sweep_in_spacings * spacing);
        layout.first_slice_collisions =
            mean_sweep / layout.slices * 4.0 * std::numbers::sqrt2 * layout.reach * static_cast<double>(present) / area;
        const double wanted = std::max(spacing, diameter + 2.0 * mean_sweep / layout.slices);
        const double max_side =
            std::floor(std::sqrt(4.0 * static_cast<double>(present) * (box_size * box_size / area))) + 1.0;
        layout.grid = UniformGrid(box_size, UniformGrid::cells_per_side(box_size, wanted, max_side));
    }
    return layout;
}

void GridSearch::find_pairs(const PairSearchInput& in, std::optional<int> forced_cells,
                            std::span<ThreadCandidates> buffers, SliceDecisions* decisions,
                            SliceDecisions* pairs_at_zero) {
    const int threads = static_cast<int>(buffers.size());
    layout_ = choose_layout(in, forced_cells, threads);

    const std::size_t count = in.particles.size();
    // Small scenes cut into a slice a thread or more: one thread a slice,
    // each with buffers of its own (fixed by the scene, so they are allocated
    // once). Large scenes, scenes of fewer slices than threads (a slow gas
    // has one), and scenes whose first slices decide most particles
    // (stepped_tuning): all threads share each slice, and one set of buffers
    // keeps the memory per particle low.
    const bool decided_early = layout_.slices >= decide_from_slices &&
                               layout_.first_slice_collisions > slices_shared_from_first_slice_collisions;
    const bool parallel_slices =
        threads >= 2 && count < slice_parallel_below && layout_.slices >= threads && !decided_early;
    const int workers = count < grid_shared_from
                            ? 1
                            : worker_count(buffers.size(), static_cast<std::int64_t>(count), min_particles_per_thread);
    // Grown, never shrunk: a step may use fewer threads than the one before.
    const std::size_t workspaces = parallel_slices ? static_cast<std::size_t>(threads) : 1;
    if (workspaces_.size() < workspaces) workspaces_.resize(workspaces);
    for (std::size_t k = 0; k < workspaces; ++k) prepare(workspaces_[k], count, parallel_slices ? 1 : workers);

    // Decisions pay where a step has enough slices for the decided
    // particles to leave out a good part of it.
    pairs_at_zero_ = pairs_at_zero != nullptr ? pairs_at_zero : decisions;
    if (layout_.slices < decide_from_slices) decisions = nullptr;
    if (parallel_slices && decisions != nullptr) {
        search_slices_deciding(in, buffers, *decisions);
    } else if (parallel_slices) {
        parallel_for_dynamic(
            std::min(threads, layout_.slices), layout_.slices, 1, [&](std::int64_t slice, std::size_t thread) {
                process_slice(in, static_cast<int>(slice), workspaces_[thread], buffers.subspan(thread, 1), 1, nullptr);
            });
    } else {
        for (int slice = 0; slice < layout_.slices; ++slice) {
            process_slice(in, slice, workspaces_[0], buffers, workers, decisions);
            const double before = decided_before(in, slice + 1);
            if (decisions != nullptr && before > 0.0) decisions->decide_before(before, buffers, threads);
        }
    }
}

// After the first `searched` slices, every candidate before the last one's
// end has been found: at its computed time a candidate's two disks are a
// contact distance apart, up to rounding far inside the boxes' margin (the
// contact time's residual), so their boxes of the slice holding that time
// overlap. The decisions stop decision_margin of the step short of that end,
// so that no rounding of a time at a slice's edge can decide a candidate
// that only a later slice finds. 0 when nothing can be decided yet, or when
// the caller decides the rest.
double GridSearch::decided_before(const PairSearchInput& in, int searched) const {
    if (searched < 1 || searched >= layout_.slices) return 0.0;
    return slice_span(in, searched - 1, layout_.slices).end - decision_margin * in.duration;
}

// Threads take whole slices as they come free, in time order, as without
// decisions; each slice's candidates go to a buffer of its own. After each
// slice, its thread hands the slices searched so far, from the first, to the
// decisions, unless another thread is deciding (that one searches no slice
// meanwhile, the others do): no thread ever waits for one the system has
// descheduled.
void GridSearch::search_slices_deciding(const PairSearchInput& in, std::span<ThreadCandidates> buffers,
                                        SliceDecisions& decisions) {
    const int slices = layout_.slices;
    if (slice_found_.size() < static_cast<std::size_t>(slices)) slice_found_.resize(static_cast<std::size_t>(slices));
    for (ThreadCandidates& found : slice_found_) {
        found.found.clear();
        found.pair_tests = 0;
    }
    slice_searched_.assign(static_cast<std::size_t>(slices), 0);
    std::mutex deciding;
    int handed_over = 0;  // slices whose candidates the decisions have; under `deciding`
    const auto searched_flag = [&](int slice) { return std::atomic_ref<std::uint8_t>(slice_searched_[slice]); };
    const int threads = static_cast<int>(buffers.size());
    parallel_for_dynamic(std::min(threads, slices), slices, 1, [&](std::int64_t slice, std::size_t thread) {
        process_slice(in, static_cast<int>(slice), workspaces_[thread], std::span(slice_found_).subspan(slice, 1), 1,
                      &decisions);
        searched_flag(static_cast<int>(slice)).store(1, std::memory_order_release);
        const std::unique_lock lock(deciding, std::try_to_lock);
        if (!lock.owns_lock()) return;
        int searched = handed_over;
        while (searched < slices && searched_flag(searched).load(std::memory_order_acquire) != 0) ++searched;
        const double before = decided_before(in, searched);
        if (before > 0.0) {
            decisions.decide_before(before, std::span(slice_found_).subspan(handed_over, searched - handed_over), 1);
            handed_over = searched;
        }
    });
    // The rest for the caller, spread over its buffers as the threads would have.
    for (int slice = 0; slice < slices; ++slice) {
        ThreadCandidates& into = buffers[static_cast<std::size_t>(slice) % buffers.size()];
        const ThreadCandidates& found = slice_found_[slice];
        into.found.insert(into.found.end(), found.found.begin(), found.found.end());
        into.pair_tests += found.pair_tests;
    }
}

void GridSearch::prepare(SliceWorkspace& ws, std::size_t count, int workers) const {
    const std::size_t cells = layout_.grid.cell_count();
    // Room for every particle's box, plus pieces of a few fast paths.
    const std::size_t boxes = count + count / 4 + 64;
    // A count that grows a little from step to step (a rank's particles and
    // ghosts) takes a little more at once: a vector grown by resize alone
    // would double, or move at every step.
    if (ws.cell_of.capacity() < count) {
        ws.cell_of.reserve(count + count / 64);
        ws.by_cell.reserve(boxes + boxes / 64);
        ws.boxes_by_cell.reserve(boxes + boxes / 64);
        ws.states_by_cell.reserve(boxes + boxes / 64);
    }
    ws.cell_of.resize(count);
    ws.by_cell.resize(boxes);
    ws.boxes_by_cell.resize(boxes);
    // The lines' rows, where a slice could bin enough boxes to test lines
    // (bin_slice() counts at most `boxes`): taken here, with the other
    // buffers, so that no later step allocates them; the dense gas, about a
    // box a cell, never takes them.
    if (static_cast<double>(boxes) >= lines_from_boxes_per_cell * static_cast<double>(cells))
        ws.boxes_by_cell.resize_lines();
    ws.states_by_cell.resize(boxes);
    ws.cell_start.resize(cells + 1);
    ws.cell_lowest_x.resize(cells);
    ws.cell_lowest_y.resize(cells);
    ws.cell_fill.resize(cells * static_cast<std::size_t>(workers - 1));  // counts of workers 1, 2, ...
    ws.large.reserve(count);
    ws.large_boxes.reserve(count);
    ws.large_start.resize(static_cast<std::size_t>(workers) + 1);
    ws.long_paths.resize(count);
    ws.long_path_count.resize(static_cast<std::size_t>(workers));
    ws.range_start.resize(cell_ranges_per_worker * static_cast<std::size_t>(workers) + 1);
}

void GridSearch::process_slice(const PairSearchInput& in, int slice, SliceWorkspace& ws,
                               std::span<ThreadCandidates> out, int threads, const SliceDecisions* decisions) const {
    bin_slice(in, slice, ws, threads, decisions);
    // Disks piled on one another: each of their k^2 / 2 pairs would be
    // tested (a pile of 20 000, 3.2 s a step). Decided first from the disks,
    // in memory and time about linear in N, the pairs at t = 0 take the
    // pile's disks out of the slice, which is binned again without them.
    // (Only the first slice: it is searched before any stage decides.
    // Candidates at t = 0 it finds for a disk left are ruled out.)
    if (slice == 0 && pairs_at_zero_ != nullptr && crowded(in, ws)) {
        pairs_at_zero_->decide_pairs_at_zero();
        bin_slice(in, slice, ws, threads, pairs_at_zero_);
    }
    test_small_pairs(in, ws, out, threads);
    test_large_pairs(in, ws, out, threads);
}

bool GridSearch::crowded(const PairSearchInput& in, const SliceWorkspace& ws) const {
    double mates = 0.0;  // pairs within a cell, about the scan's tests there
    std::size_t fullest = 0;
    for (std::size_t cell = 0; cell + 1 < ws.cell_start.size(); ++cell) {
        const std::uint32_t boxes = ws.cell_start[cell + 1] - ws.cell_start[cell];
        mates += static_cast<double>(boxes) * static_cast<double>(boxes);
        if (boxes > ws.cell_start[fullest + 1] - ws.cell_start[fullest]) fullest = cell;
    }
    const double particles = static_cast<double>(in.particles.size());
    if (!(0.5 * mates > crowded_cell_pairs_per_particle * particles + crowded_cell_pairs_floor)) return false;
    // Worth it where the crowd's pairs meet at t = 0: a pile. Disks that fly
    // apart from where they were piled overlap as much, but recede, and the
    // scan alone has less to do.
    const std::uint32_t first = ws.cell_start[fullest];
    const std::uint32_t sampled =
        std::min<std::uint32_t>(crowded_pairs_sampled, ws.cell_start[fullest + 1] - first - 1);
    std::uint32_t at_zero = 0;
    for (std::uint32_t k = first; k < first + sampled; ++k) {
        const Particle& a = in.particles[ws.by_cell[k]];
        const Particle& b = in.particles[ws.by_cell[k + 1]];
        at_zero += contact_time(b.position - a.position, b.velocity - a.velocity, in.box.contact_dist_sq) == 0.0;
    }
    return at_zero * crowded_pairs_at_zero_from > sampled;
}

int GridSearch::pieces_to_fit(const Particle& particle, double begin, double end, double fit) const {
    const double room = fit - 2.0 * layout_.reach;
    const double travel = std::max(std::abs(particle.velocity.x()), std::abs(particle.velocity.y())) * (end - begin);
    if (!(room > 0.0) || !(travel < room * max_pieces)) return 0;
    const int pieces = std::max(2, static_cast<int>(std::ceil(travel / room)));
    if (pieces > max_pieces) return 0;
    // The rounding of the piece ends may still push a box past the cell.
    for (int piece = 0; piece < pieces; ++piece) {
        if (!fits_cell(piece_bounds(particle, begin, end, piece, pieces), fit)) return 0;
    }
    return pieces;
}

// What the steps of binning one slice share. Each worker counts and then
// places a contiguous block of particles; worker 0 counts in cell_start
// itself, the others in cell_fill.
struct GridSearch::Binning {
    const GridSearch& search;
    const PairSearchInput& in;
    SliceWorkspace& ws;
    SliceSpan span;
    const SliceDecisions* decisions;  // its decided particles are left out; may be null
    const UniformGrid& grid;
    double fit;  // the largest box side that fits a cell
    int threads;
    std::int64_t count;  // particles
    std::int64_t cells;
    std::int64_t block;   // particles a worker
    std::int64_t ranges;  // of cells, for the passes over every cell
    int range_workers;    // threads for those passes

    [[nodiscard]] std::pair<std::int64_t, std::int64_t> block_of(std::int64_t worker) const {
        return std::pair{worker * block, std::min(count, (worker + 1) * block)};
    }
    [[nodiscard]] std::uint32_t* counts_of(std::int64_t worker) const {
        return worker == 0 ? ws.cell_start.data() : ws.cell_fill.data() + (worker - 1) * cells;
    }
    [[nodiscard]] std::uint32_t cell_of_box(const SweptBounds& box) const { return grid.cell_of(box.min_x, box.min_y); }
    [[nodiscard]] double path_end(std::int64_t i) const { return span.path_end(sweep_end(in, i)); }
    // Whether particle i has a path to bin in the slice: its path reaches
    // into it, and its collision is not decided.
    [[nodiscard]] bool binned(std::int64_t i) const {
        if (!span.holds_path(sweep_end(in, i))) return false;
        return decisions == nullptr || !decisions->decided(static_cast<std::uint32_t>(i));
    }
    // Particle i's path in the slice, and piece `piece` of `pieces` equal parts of it.
    [[nodiscard]] SweptBounds path_bounds(std::int64_t i) const {
        return search.swept_bounds(in.particles[i], span.begin, path_end(i));
    }
    [[nodiscard]] SweptBounds piece_bounds(std::int64_t i, int piece, int pieces) const {
        return search.piece_bounds(in.particles[i], span.begin, path_end(i), piece, pieces);
    }
    // body(range, first, last) over ranges of cells, on range_workers threads.
    template <typename Body>
    void for_each_range(Body&& body) const {
        parallel_for_ranges(range_workers, cells, ranges, std::forward<Body>(body));
    }
};

// Counting sort of the fitting boxes (and pieces) by cell, the large ones
// aside. (The order within a cell does not change the pairs tested.)
void GridSearch::bin_slice(const PairSearchInput& in, int slice, SliceWorkspace& ws, int threads,
                           const SliceDecisions* decisions) const {
    const auto count = static_cast<std::int64_t>(in.particles.size());
    const auto cells = static_cast<std::int64_t>(ws.cell_start.size()) - 1;
    const Binning binning{*this,
                          in,
                          ws,
                          slice_span(in, slice, layout_.slices),
                          decisions,
                          layout_.grid,
                          layout_.grid.cell_size() * cell_fit_slack,
                          threads,
                          count,
                          cells,
                          (count + threads - 1) / threads,
                          static_cast<std::int64_t>(ws.range_start.size()) - 1,
                          worker_count(static_cast<std::size_t>(threads), cells, min_particles_per_thread)};
    // Pieces that would not fit the buffers (many fast particles): the slice
    // is counted again with the long paths large instead.
    std::size_t boxes = count_boxes(binning, true);
    if (boxes > ws.by_cell.size()) boxes = count_boxes(binning, false);
    ws.lines = static_cast<double>(boxes) >= lines_from_boxes_per_cell * static_cast<double>(cells);
    PARTICLESIM_ASSERT(!ws.lines || ws.boxes_by_cell.holds_lines(), "prepare() sized the lines' rows");
    sum_cell_places(binning);
    place_boxes(binning);
    close_cell_starts(binning);
    if (ws.lines) {
        // Blocks of records on the slice's workers (sixteen records a whole number of times each).
        constexpr std::int64_t records_block = 4096;
        const std::array<float*, 8> rows = ws.boxes_by_cell.rows();
        const auto* records = reinterpret_cast<const std::byte*>(ws.states_by_cell.data());
        parallel_for_blocks(threads, ws.cell_start[cells], records_block,
                            [&](std::int64_t, std::int64_t first, std::int64_t last) {
                                std::array<float*, 8> block_rows = rows;
                                for (float*& row : block_rows) row += first;
                                records_to_rows(records + first * std::int64_t{sizeof(BoxRecord)},
                                                static_cast<std::uint32_t>(last - first), block_rows, lanes_);
                            });
    }
    if (ws.lines) find_cell_lowest(binning);
}

void GridSearch::find_cell_lowest(const Binning& binning) const {
    SliceWorkspace& ws = binning.ws;
    const std::array<float*, 8> rows = ws.boxes_by_cell.rows();
    const float* min_x = rows[0];
    const float* min_y = rows[1];
    binning.for_each_range([&](std::int64_t, std::int64_t first, std::int64_t last) {
        for (std::int64_t cell = first; cell < last; ++cell) {
            float lowest_x = std::numeric_limits<float>::infinity();
            float lowest_y = lowest_x;
            for (std::uint32_t k = ws.cell_start[cell]; k < ws.cell_start[cell + 1]; ++k) {
                lowest_x = std::min(lowest_x, min_x[k]);
                lowest_y = std::min(lowest_y, min_y[k]);
            }
            ws.cell_lowest_x[cell] = lowest_x;
            ws.cell_lowest_y[cell] = lowest_y;
        }
    });
}

// Counts each worker's boxes by cell and its large boxes; returns the boxes to place.
std::size_t GridSearch::count_boxes(const Binning& binning, bool cut_into_pieces) const {
    const PairSearchInput& in = binning.in;
    SliceWorkspace& ws = binning.ws;
    const SliceSpan span = binning.span;
    // Long paths, in a loop of their own (as in the placement).
    const auto count_pieces = [&](std::span<const std::uint32_t> long_paths, std::uint32_t* counts,
                                  std::size_t& counted, std::uint32_t& large) {
        for (const std::uint32_t i : long_paths) {
            const int pieces = pieces_to_fit(in.particles[i], span.begin, binning.path_end(i), binning.fit);
            ws.cell_of[i] = large_marker - static_cast<std::uint32_t>(pieces);
            for (int piece = 0; piece < pieces; ++piece)
                ++counts[binning.cell_of_box(binning.piece_bounds(i, piece, pieces))];
            counted += static_cast<std::size_t>(pieces);
            large -= pieces > 0 ? 1U : 0U;
        }
    };
    std::atomic<std::size_t> boxes{0};
    parallel_for(binning.threads, binning.threads, [&](std::int64_t worker, std::size_t) {
        std::uint32_t* counts = binning.counts_of(worker);
        std::fill(counts, counts + binning.cells, 0U);
        const auto [first, last] = binning.block_of(worker);
        CountTally tally;
        tally.long_paths = ws.long_paths.data() + first;
        const auto count_one = [&](std::int64_t i) {
            if (!binning.binned(i)) {
                ws.cell_of[i] = absent_marker;
                return;
            }
            const SweptBounds box = binning.path_bounds(i);
            const bool fits = fits_cell(box, binning.fit);
            const std::uint32_t cell = binning.cell_of_box(box);
            ws.cell_of[i] = fits ? cell : large_marker;
            counts[cell] += fits ? 1U : 0U;
            tally.counted += fits ? 1U : 0U;
            tally.long_paths[tally.large] = static_cast<std::uint32_t>(i);  // kept only if long
            tally.large += fits ? 0U : 1U;
        };
#if defined(__x86_64__)
        if (lanes_ >= 8) {  // the lanes of AVX-512, or else of AVX2
            const CountInput input{in.particles.data(), in.wall_time.data(), binning.decisions,
                                   in.duration,         span.begin,          span.end,
                                   layout_.reach,       binning.fit,         &binning.grid};
            if (lanes_ == 16) {
                count_paths_eight(input, first, last, ws.cell_of.data(), counts, tally, count_one);
            } else {
                count_paths_four(input, first, last, ws.cell_of.data(), counts, tally, count_one);
            }
        } else
#endif
        {
            for (std::int64_t i = first; i < last; ++i) count_one(i);
        }
        ws.long_path_count[worker] = tally.large;
        if (cut_into_pieces) count_pieces(std::span(tally.long_paths, tally.large), counts, tally.counted, tally.large);
        boxes += tally.counted;
        ws.large_start[worker + 1] = tally.large;
    });
    return boxes.load();
}

// Turns the counts into each worker's first place in each cell, and the
// large boxes' counts into their places.
void GridSearch::sum_cell_places(const Binning& binning) const {
    SliceWorkspace& ws = binning.ws;
    const int threads = binning.threads;
    const std::int64_t cells = binning.cells;
    // Each worker's first place in each cell, cell by cell, from `placed`.
    const auto place_cells = [&](std::int64_t first, std::int64_t last, std::uint32_t placed) {
        for (std::int64_t cell = first; cell < last; ++cell) {
            for (std::int64_t worker = 0; worker < threads; ++worker) {
                std::uint32_t& next = binning.counts_of(worker)[cell];
                placed += std::exchange(next, placed);
            }
        }
    };
    // On a large grid, in ranges of cells on every thread (a serial pass
    // would leave the others waiting): each range sums its boxes, then
    // places them from where the ranges before it end.
    if (binning.range_workers == 1) {
        place_cells(0, cells, 0);
    } else {
        std::fill(ws.range_start.begin(), ws.range_start.end(), 0U);  // a range past the end is not visited
        binning.for_each_range([&](std::int64_t range, std::int64_t first, std::int64_t last) {
            std::uint32_t boxes = 0;
            for (std::int64_t worker = 0; worker < threads; ++worker) {
                const std::uint32_t* counts = binning.counts_of(worker);
                for (std::int64_t cell = first; cell < last; ++cell) boxes += counts[cell];
            }
            ws.range_start[range + 1] = boxes;
        });
        std::partial_sum(ws.range_start.begin(), ws.range_start.end(), ws.range_start.begin());
        binning.for_each_range([&](std::int64_t range, std::int64_t first, std::int64_t last) {
            place_cells(first, last, ws.range_start[range]);
        });
    }
    ws.large_start[0] = 0;
    std::partial_sum(ws.large_start.begin(), ws.large_start.end(), ws.large_start.begin());
    ws.large.resize(ws.large_start[threads]);
    ws.large_boxes.resize(ws.large_start[threads]);
}

// Places each worker's boxes at its places in cell order (bounds in float,
// and either the motion states copied beside them or, where the scans test
// lines, the lines: so few boxes pass the lines' test that those read their
// particles' states where they are), and its large boxes in its share.
void GridSearch::place_boxes(const Binning& binning) const {
    const PairSearchInput& in = binning.in;
    SliceWorkspace& ws = binning.ws;
    parallel_for(binning.threads, binning.threads, [&](std::int64_t worker, std::size_t) {
        std::uint32_t* next = binning.counts_of(worker);
        const auto [first, last] = binning.block_of(worker);
        const bool lines = ws.lines;
        // Stores particle i's box at the worker's next place in `cell`: its
        // float bounds, and its line where the scans test lines, else its
        // motion state. (Through pointers held here: the vectors' would be
        // read again at every store.)
        std::uint32_t* by_cell = ws.by_cell.data();
        PairTestState* states = ws.states_by_cell.data();
        FloatBoundsArray& boxes = ws.boxes_by_cell;
        const Particle* particles = in.particles.data();
        const auto store = [=, &boxes](std::uint32_t i, std::uint32_t cell, const BoxRecord& record) {
            const std::uint32_t at = next[cell]++;
            by_cell[at] = i;
            if (lines) {
                // One aligned 32-byte store into the states' room (box_records.hpp).
                std::memcpy(static_cast<void*>(states + at), &record, sizeof record);
            } else {
                boxes.set(at, record.bounds);
                states[at] = {particles[i].position, particles[i].velocity};
            }
        };
        const auto place = [&](std::int64_t i, std::uint32_t cell, const SweptBounds& box) {
            // The line is the same for the whole slice.
            store(static_cast<std::uint32_t>(i), cell,
                  BoxRecord{float_bounds(box, layout_.float_scale), lines ? float_line(in.particles[i]) : FloatLine{}});
        };
        // The pieces in a loop of their own: the main loop stays short enough
        // for the processor to overlap the cache misses of many particles.
        const std::uint32_t* marks = ws.cell_of.data();
        const auto place_one = [&](std::int64_t i) {
            const std::uint32_t mark = marks[i];
            if (mark < first_piece_marker) place(i, mark, binning.path_bounds(i));
        };
#if defined(__x86_64__)
        if (lanes_ >= 8) {
            const CountInput input{in.particles.data(), in.wall_time.data(), binning.decisions,
                                   in.duration,         binning.span.begin,  binning.span.end,
                                   layout_.reach,       binning.fit,         &binning.grid};
            const PlaceInput placing{layout_.float_scale, layout_.line_position_scale, layout_.line_velocity_scale,
                                     lines};
            // The lanes' boxes (and lines), each in the cell the count marked.
            const auto store_marked = [&](std::uint32_t i, const BoxRecord& record) { store(i, marks[i], record); };
            if (lanes_ == 16) {
                place_paths_eight(input, placing, first, last, marks, store_marked, place_one);
            } else {
                place_paths_four(input, placing, first, last, marks, store_marked, place_one);
            }
        } else
#endif
        {
            for (std::int64_t i = first; i < last; ++i) place_one(i);
        }
        std::uint32_t next_large = ws.large_start[worker];
        // The long paths only: the count listed them.
        for (const std::uint32_t i : std::span(ws.long_paths.data() + first, ws.long_path_count[worker])) {
            const std::uint32_t mark = ws.cell_of[i];
            if (mark == large_marker) {
                ws.large[next_large] = i;
                ws.large_boxes[next_large] = binning.path_bounds(i);
                ++next_large;
                continue;
            }
            const int pieces = static_cast<int>(large_marker - mark);
            for (int piece = 0; piece < pieces; ++piece) {
                const SweptBounds box = binning.piece_bounds(i, piece, pieces);
                place(i, binning.cell_of_box(box), box);
            }
        }
    });
}

// The last worker's next place in a cell is now where the next cell starts.
// A lone worker's places are cell_start itself: from the top down, that
// overwrites only what is spent.
void GridSearch::close_cell_starts(const Binning& binning) const {
    SliceWorkspace& ws = binning.ws;
    const std::int64_t cells = binning.cells;
    const std::uint32_t* ends = binning.counts_of(binning.threads - 1);
    if (binning.threads == 1) {
        for (std::int64_t cell = cells - 1; cell >= 0; --cell) ws.cell_start[cell + 1] = ends[cell];
    } else {
        binning.for_each_range([&](std::int64_t, std::int64_t first, std::int64_t last) {
            std::copy(ends + first, ends + last, ws.cell_start.begin() + first + 1);
        });
    }
    ws.cell_start[0] = 0;
}

namespace {

// The pairs that pass a scan's line test, each tested a few passes later:
// their particles are read where they are stored, a miss to memory in a
// large scene, fetched as the pair passes. (The candidates' order does not
// change the step: the selection orders them.)
class DeferredPairTests {
public:
    DeferredPairTests(const PairSearchInput& in, ThreadCandidates& out) : in_(in), out_(out) {}

    void add(std::uint32_t i, std::uint32_t j) {
        for (const std::uint32_t particle : {i, j}) {
            prefetch(&in_.particles[particle].position);  // with the velocity, 32 bytes that may span two lines
            prefetch(&in_.particles[particle].velocity);
        }
        Pair& slot = waiting_[added_ % depth];
        if (added_ >= depth) test_pair(in_, slot.i, slot.j, out_);
        slot = {i, j};
        ++added_;
    }
    // Tests those still waiting.
    void finish() {
        for (std::size_t k = added_ > depth ? added_ - depth : 0; k < added_; ++k) {
            test_pair(in_, waiting_[k % depth].i, waiting_[k % depth].j, out_);
        }
        added_ = 0;
    }

private:
    static constexpr std::size_t depth = 8;
    struct Pair {
        std::uint32_t i, j;
    };
    const PairSearchInput& in_;
    ThreadCandidates& out_;
    std::array<Pair, depth> waiting_{};
    std::size_t added_ = 0;
};

// Tests particle `a` (box `box`, state `state`) against the boxes stored at
// positions [first, last) of the cell order whose float bounds meet its own.
// With `with_lines`, only those whose lines also pass the line test against
// `line`, handed to `out` (DeferredPairTests: `state` is not read); else
// tested at once into `out` (ThreadCandidates).
template <std::uint32_t block_groups, std::uint32_t group_lanes = FloatBoundsArray::lanes, bool with_lines = false,
          typename Out>
[[gnu::always_inline]] inline void test_against_range(const PairSearchInput& in, const GridSearch::SliceWorkspace& ws,
                                                      std::uint32_t a, const FloatBounds& box, const FloatLine& line,
                                                      const LineTerms& terms, const PairTestState& state,
                                                      std::uint32_t first, std::uint32_t last, Out& out) {
    const auto test = [&](std::uint32_t m) {
        const std::uint32_t b = ws.by_cell[m];
        if (b == a) return;  // another piece of the same path
        if constexpr (with_lines) {
            out.add(std::min(a, b), std::max(a, b));
        } else {
            const PairTestState& other = ws.states_by_cell[m];
            if (a < b) {
                test_pair(state, other, a, b, in, out);
            } else {
                test_pair(other, state, b, a, in, out);
            }
        }
    };
    ws.boxes_by_cell.for_each_close<block_groups, group_lanes, with_lines>(first, last, box, line, terms, test);
}

// The row above is first read here, and only at hits, a pattern the
// processor's prefetchers miss: its motion states are fetched this many
// cells ahead (docs/benchmarks.md).

// The half stencil of every cell in row `cy`: the rest of the cell and the
// cell to the east (adjacent in the cell order, so one range), then the
// three cells above (one range), scanned in blocks of `block_groups` groups.
template <std::uint32_t block_groups, std::uint32_t group_lanes, bool with_lines>
[[gnu::always_inline]] inline void scan_row(const PairSearchInput& in, const GridSearch::SliceWorkspace& ws, int side,
                                            std::int64_t cy, const LineTerms& terms, ThreadCandidates& found) {
    const std::uint32_t* start = ws.cell_start.data();
    const std::uint32_t* ids = ws.by_cell.data();
    const FloatBoundsArray& boxes = ws.boxes_by_cell;
    const PairTestState* states = ws.states_by_cell.data();
    const std::int64_t row = cy * side;
    const std::uint32_t boxes_binned = start[static_cast<std::int64_t>(side) * side];
    DeferredPairTests deferred(in, found);  // with lines
    auto& tests = [&]() -> auto& {
        if constexpr (with_lines) {
            return deferred;
        } else {
            return found;
        }
    }
    ();
    // (Kept only where the scans test lines: find_cell_lowest().)
    constexpr float nowhere = std::numeric_limits<float>::infinity();
    const float* lowest_x = ws.cell_lowest_x.data();
    const float* lowest_y = ws.cell_lowest_y.data();
    for (int cx = 0; cx < side; ++cx) {
        const std::int64_t cell = row + cx;
        const std::uint32_t first = start[cell];
        const std::uint32_t last = start[cell + 1];
        if (!with_lines && cy + 1 < side) {
            const std::uint32_t ahead = start[row + side + std::min(cx + scan_fetch_cells_ahead, side)];
            prefetch(states + ahead);
            prefetch(states + std::min(ahead + 1, boxes_binned));
        }
        if (first == last) continue;
        // Where a box's far edges fall short of every box of the cell to the
        // east, of the cells above, or of the one above to the east, it
        // leaves them out of its ranges: the same pairs, fewer blocks (with
        // lines: cells of several boxes, about a third of which reach up or
        // to the east).
        const bool east = cx + 1 < side;
        const std::uint32_t east_last = start[cell + (east ? 2 : 1)];
        const float east_lowest_x = with_lines && east ? lowest_x[cell + 1] : nowhere;
        std::uint32_t above_first = 0;
        std::uint32_t above_last = 0;
        std::uint32_t north_last = 0;  // the above range without the cell to the east
        float above_lowest_y = nowhere;
        float north_east_lowest_x = nowhere;
        if (cy + 1 < side) {
            const std::int64_t north = row + side + cx;
            above_first = start[north - (cx > 0 ? 1 : 0)];
            north_last = start[north + 1];
            above_last = start[north + (east ? 2 : 1)];
            if (with_lines) {
                above_lowest_y = std::min(lowest_y[north], cx > 0 ? lowest_y[north - 1] : nowhere);
                if (east) {
                    above_lowest_y = std::min(above_lowest_y, lowest_y[north + 1]);
                    north_east_lowest_x = lowest_x[north + 1];
                }
            }
        }
        for (std::uint32_t k = first; k < last; ++k) {
            const FloatLine line = with_lines ? boxes.line(k) : FloatLine{};
            const PairTestState state = with_lines ? PairTestState{} : states[k];  // not copied where lines are tested
            const FloatBounds box = boxes[k];
            if constexpr (!with_lines) {  // about a box a cell: the whole stencil, without branches
                test_against_range<block_groups, group_lanes, with_lines>(in, ws, ids[k], box, line, terms, state,
                                                                          k + 1, east_last, tests);
                test_against_range<block_groups, group_lanes, with_lines>(in, ws, ids[k], box, line, terms, state,
                                                                          above_first, above_last, tests);
                continue;
            }
            const std::uint32_t near_last = box.max_x >= east_lowest_x ? east_last : last;
            test_against_range<block_groups, group_lanes, with_lines>(in, ws, ids[k], box, line, terms, state, k + 1,
                                                                      near_last, tests);
            if (box.max_y >= above_lowest_y) {
                const std::uint32_t far_last = box.max_x >= north_east_lowest_x ? above_last : north_last;
                test_against_range<block_groups, group_lanes, with_lines>(in, ws, ids[k], box, line, terms, state,
                                                                          above_first, far_last, tests);
            }
        }
    }
    if constexpr (with_lines) deferred.finish();
}

// One row in blocks of `block_groups` groups of four boxes, or (x86-64) of
// eight or sixteen, compiled for AVX2 or AVX-512: chosen at run time, so that
// one build runs on every x86-64 processor. Lanes only filter boxes; every
// pair test is the same double arithmetic (no fused multiply-add), so results
// do not change.
template <std::uint32_t block_groups, bool with_lines>
void scan_row_four(const PairSearchInput& in, const GridSearch::SliceWorkspace& ws, int side, std::int64_t cy,
                   const LineTerms& terms, ThreadCandidates& found) {
    scan_row<block_groups, FloatBoundsArray::lanes, with_lines>(in, ws, side, cy, terms, found);
}

#if defined(__x86_64__)
template <std::uint32_t block_groups, bool with_lines>
[[gnu::target("avx2")]] void scan_row_eight(const PairSearchInput& in, const GridSearch::SliceWorkspace& ws, int side,
                                            std::int64_t cy, const LineTerms& terms, ThreadCandidates& found) {
    scan_row<block_groups, FloatBoundsArray::wide_lanes, with_lines>(in, ws, side, cy, terms, found);
}

template <std::uint32_t block_groups, bool with_lines>
[[gnu::target("avx512f,fma")]] void scan_row_sixteen(const PairSearchInput& in, const GridSearch::SliceWorkspace& ws,
                                                     int side, std::int64_t cy, const LineTerms& terms,
                                                     ThreadCandidates& found) {
    scan_row<block_groups, FloatBoundsArray::widest_lanes, with_lines>(in, ws, side, cy, terms, found);
}

bool cpu_supports_lanes(int lanes) {
    static const bool sixteen = [] {
        __builtin_cpu_init();  // in case this first runs before the library's constructors
        return __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("fma") != 0;
    }();
    static const bool eight = __builtin_cpu_supports("avx2") != 0;
    return lanes == 4 || (lanes == 8 && eight) || (lanes == 16 && sixteen);
}
#endif

}  // namespace

bool GridSearch::supports_lanes(int lanes) {
#if defined(__x86_64__)
    return cpu_supports_lanes(lanes);
#else
    return lanes == 4;
#endif
}

void GridSearch::test_small_pairs(const PairSearchInput& in, const SliceWorkspace& ws, std::span<ThreadCandidates> out,
                                  int threads) const {
    const int side = layout_.grid.per_side();
    const auto scan = [&](auto scan_one_row) {
        parallel_for_in_shares(threads, side, 4, [&](std::int64_t cy, std::size_t thread) {
            scan_one_row(in, ws, side, cy, layout_.line_terms, out[thread]);
        });
    };
    // A range that fits one block is scanned without a mispredicted exit
    // from a loop over its groups: blocks of two groups suit cells of a few
    // boxes (sparse scenes), each group as wide as the processor's lanes,
    // with the lines tested too; one group of four boxes alone suits cells
    // of about one box (dense scenes, whose short paths' boxes are filter
    // enough), where more lanes only add work (docs/benchmarks.md).
    if (!ws.lines) {
        scan(scan_row_four<1, false>);
        return;
    }
    switch (lanes_) {
#if defined(__x86_64__)
    case 16: scan(scan_row_sixteen<2, true>); return;
    case 8: scan(scan_row_eight<2, true>); return;
#endif
    default: scan(scan_row_four<2, true>); return;
    }
}

void GridSearch::test_large_pairs(const PairSearchInput& in, const SliceWorkspace& ws, std::span<ThreadCandidates> out,
                                  int threads) const {
    const UniformGrid& grid = layout_.grid;
    const int side = grid.per_side();
    const auto large_count = static_cast<std::int64_t>(ws.large.size());

    parallel_for_dynamic(large_count > 1 ? threads : 1, large_count, 1, [&](std::int64_t k, std::size_t thread) {
        ThreadCandidates& found = out[thread];
        const std::uint32_t a = ws.large[k];
        const SweptBounds& box = ws.large_boxes[k];
        const FloatBounds bounds = float_bounds(box, layout_.float_scale);
        const PairTestState state = pair_test_state(in, a);
        const FloatLine line = float_line(in.particles[a]);
        const CellRegion region = cells_reaching(box, grid);
        DeferredPairTests deferred(in, found);
        for (int cy = region.y_first; cy <= region.y_last; ++cy) {
            const auto row = static_cast<std::size_t>(cy) * side;
            const std::uint32_t first = ws.cell_start[row + region.x_first];
            const std::uint32_t last = ws.cell_start[row + region.x_last + 1];
            if (ws.lines) {
                test_against_range<1, FloatBoundsArray::lanes, true>(in, ws, a, bounds, line, layout_.line_terms, state,
                                                                     first, last, deferred);
            } else {
                test_against_range<1>(in, ws, a, bounds, line, layout_.line_terms, state, first, last, found);
            }
        }
        deferred.finish();
        for (std::int64_t other = k + 1; other < large_count; ++other) {
            const std::uint32_t b = ws.large[other];
            if (box.overlaps(ws.large_boxes[other])) test_pair(in, std::min(a, b), std::max(a, b), found);
        }
    });
}

}  // namespace particlesim
