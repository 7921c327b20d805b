#include "particlesim/exact_simulation.hpp"
#include "particlesim/saved_state.hpp"

#include "core/assert.hpp"
#include "core/box.hpp"
#include "core/crowded_grid.hpp"
#include "core/huge_page_allocator.hpp"
#include "core/physics.hpp"
#include "core/prefetch.hpp"
#include "core/uniform_grid.hpp"
#include "exact/cell_list.hpp"
#include "exact/exact_tuning.hpp"
#include "exact/ladder_calendar.hpp"
#include "exact/linked_calendar.hpp"
#include "input/options_check.hpp"
#include "input/scene_checks.hpp"
#include "io/number_format.hpp"
#include "search/path_lines.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace particlesim {

OverlappingStart::OverlappingStart(std::uint32_t first, std::uint32_t second)
    : std::invalid_argument("particles " + std::to_string(first) + " and " + std::to_string(second) +
                            " overlap; the exact engine needs a start where no two disks overlap"),
      first_(first),
      second_(second) {}

TooManyEvents::TooManyEvents(std::int64_t step, std::uint64_t events, double predicted)
    : std::runtime_error("step " + std::to_string(step) + ": the exact engine has processed " + std::to_string(events) +
                         " events in this step, against about " + format_brief(predicted) +
                         " predicted from the speeds and density; stopped rather than run on for hours (disks "
                         "trapped in a gap far narrower than their radius bounce without end)"),
      step_(step),
      events_(events),
      predicted_(predicted) {}

namespace {

// How restore() refuses a saved state, whichever check finds the damage.
constexpr const char* restore_refusal = "particlesim::ExactSimulation::restore: the saved state is damaged";

// The events a step may take before it counts as runaway (TooManyEvents).
double event_budget(const ExactOptions& options, double predicted, std::size_t count) {
    if (options.max_events_per_step) return static_cast<double>(*options.max_events_per_step);
    return exact_tuning::runaway_floor + exact_tuning::runaway_factor * (predicted + static_cast<double>(count));
}

// Cells at least a diameter wide, so that a contact is always between
// neighbouring cells. Wider cells mean fewer crossing events but more pair
// tests per event, so: about 4 particles per cell in a sparse box, and no
// wider than half a mean free path (1 / (4 r N / L^2)) in a dense one. Either
// way the cell count stays O(N) (the choice is measured in docs/benchmarks.md).
int cells_per_side_for(const World& world, std::size_t particle_count) {
    const double count = static_cast<double>(particle_count);
    const double by_count = std::ceil(std::sqrt(count / exact_tuning::particles_per_cell));
    // The mean free path is 1 / (4 r N / L^2).
    const double by_free_path =
        std::ceil(4.0 * world.radius * count / (exact_tuning::cell_in_free_paths * world.box_size));
    return UniformGrid::cells_per_side(world.box_size, 2.0 * world.radius, std::max(by_count, by_free_path));
}

// Per unit of speed, events a step with one cell and the lines' test (walls
// and both partners of each collision: each tests its new line against all
// N) against events with the cells (walls, collisions and crossings, each
// testing the disks of a few cells). Speeds cancel, so the choice depends
// on N, r and L alone, and a restored run makes the one its start made.
// The costs of an event each way are exact_tuning's; dense scenes' stale
// pair predictions make the lines dearer than this counts, hence the margin;
// and no more disks than were measured (the first predictions test all
// N^2 / 2 pairs).
bool lines_are_cheaper(const World& world, std::size_t particle_count, int cells_per_side) {
    using namespace exact_tuning;
    if (particle_count > lines_up_to) return false;
    const double count = static_cast<double>(particle_count);
    const double walls = count / world.box_size;
    const double pairs = 2.0 * std::sqrt(2.0) * count * count * world.radius / (world.box_size * world.box_size);
    const double crossings = count * cells_per_side / world.box_size;
    const double with_lines = (walls + 2.0 * pairs) * (line_event_ns + line_test_ns * count);
    const double with_cells = (walls + pairs + crossings) * cell_event_ns;
    return with_lines < lines_chosen_below * with_cells;
}

// The periodic box's `side` x `side` cells, or the refusal of a box or a
// side too small for them.
UniformGrid periodic_neighbour_grid(const World& world, int side) {
    const double reach = contact_reach(Box::of(world));
    const std::string at_least = std::to_string(periodic_cells_at_least);
    const std::string needs = "particlesim::ExactSimulation: a periodic box needs at least " + at_least +
                              " cells a side, each wider than a contact distance";
    if (!holds_contact_cells(world, periodic_cells_at_least)) {
        throw std::invalid_argument(needs + " (2r and a margin for rounding, " + format_short(reach) +
                                    "): L must exceed " + at_least + " x " + format_short(reach) + " = " +
                                    format_short(periodic_cells_at_least * reach) + ", not " +
                                    format_short(world.box_size));
    }
    if (side < periodic_cells_at_least || world.box_size / side < reach) {
        throw std::invalid_argument(needs + ": cells_per_side from " + at_least + " to " +
                                    std::to_string(static_cast<long long>(std::floor(world.box_size / reach))) +
                                    " here, not " + std::to_string(side));
    }
    return UniformGrid(world.box_size, side);
}

// Whether the lines of a sample of the particles (exact_tuning::lines_probed,
// spread over the indices) meet more than lines_crowd_from_near others on
// average: a row moving along itself, a cradle.
bool lines_crowd(const World& world, std::span<const Particle> particles) {
    using namespace exact_tuning;
    PathLines lines;
    lines.assign(particles, Box::of(world));
    const std::size_t probed = std::min<std::size_t>(lines_probed, particles.size());
    std::vector<std::uint32_t> near;
    std::size_t met = 0;
    for (std::size_t k = 0; k < probed; ++k) {
        near.clear();
        lines.gather_near(static_cast<std::uint32_t>(k * particles.size() / probed), near);
        met += near.size();
    }
    return static_cast<double>(met) > lines_crowd_from_near * static_cast<double>(probed);
}

// The side refined for a start that crowds the cells (exact_tuning's
// crowded_cell_mates): doubled while the disks' mean count of cell mates
// (the sum of each cell's count squared, over N) stays above it.
int refined_for_crowded_start(const World& world, std::span<const Particle> particles, int side) {
    using namespace exact_tuning;
    const double count = static_cast<double>(particles.size());
    const int finest =
        std::min(UniformGrid::cells_per_side(world.box_size, contact_reach(Box::of(world)), max_grid_cells),
                 static_cast<int>(std::sqrt(crowded_cells_per_particle * count)));
    return refined_for_crowding(
        world.box_size, static_cast<std::uint32_t>(particles.size()),
        [&](std::uint32_t k) { return particles[k].position; }, side, finest, crowded_cell_mates);
}

// The cells a side that the cost model alone chooses from N, r and L.
int modelled_cells_per_side(const World& world, std::size_t particle_count, Boundary boundary) {
    const int side = cells_per_side_for(world, particle_count);
    if (boundary == Boundary::periodic) return std::max(side, periodic_cells_at_least);
    return lines_are_cheaper(world, particle_count, side) ? 1 : side;
}

// The cells of a run from its start: the options' side, or the cost model's
// choice, lines only where they do not crowd. A restored run takes the side
// its state was saved with (ExactOptions::cells_per_side set by restore()).
UniformGrid neighbour_grid(const World& world, std::span<const Particle> particles, const ExactOptions& options) {
    std::optional<int> cells_per_side = options.cells_per_side;
    if (!cells_per_side) {
        cells_per_side = modelled_cells_per_side(world, particles.size(), options.boundary);
        if (*cells_per_side == 1 && lines_crowd(world, particles))
            cells_per_side = cells_per_side_for(world, particles.size());
        if (*cells_per_side > 1) cells_per_side = refined_for_crowded_start(world, particles, *cells_per_side);
    }
    if (options.boundary == Boundary::periodic) return periodic_neighbour_grid(world, *cells_per_side);
    return UniformGrid(world.box_size, *cells_per_side);
}

}  // namespace

// The engine's state. A particle's stored position is where it was at its
// own time stamp, the time of its last collision (or 0); it is moved only by
// its own collisions, so that every prediction reads an unchanged state.
//
// With a single cell (a sparse scene of few particles: neighbour_grid()),
// there are no crossings, and a particle's neighbours are the particles
// whose lines come near its own (PathLines, in float lanes): the same pairs
// get the same tests as with the cells, but far fewer events.
//
// Each particle keeps three predictions: its wall event, its next cell
// crossing, and the earliest pair event found for it; its queue entry is the
// first of the three. A pair prediction goes stale when the partner collides
// elsewhere first; that is noticed when the entry comes up, and the particle
// then predicts its pairs afresh. No collision is missed: a particle's pair
// prediction is never later than any valid pair event with a neighbour, and a
// collision partner is always a neighbour (cells are wider than a diameter).
class ExactSimulation::Implementation {
public:
    struct Crossing {
        double time = never;
        std::uint32_t cell = 0;  // the cell entered
    };
    // What an event reads of a particle first, and of each neighbour it
    // tests: its position and velocity at its own time stamp (the time of
    // its last collision, or 0), the stamp, the absolute time of its next
    // wall event and its version; kept in the cell list's record, with the
    // links that lead to the next particle of the cell: one 64-byte line.
    struct alignas(64) Body {
        Vec2 position = Vec2::Zero();
        Vec2 velocity = Vec2::Zero();
        double stamp = 0.0;
        double wall_time = never;
        // pc + wc (mod 2^32): changes exactly when the velocity does, at each
        // of the particle's collisions.
        std::uint32_t version = 0;
        // The cell list's links (BucketListsOf), which only it writes.
        std::uint32_t next = BucketLists::none;
        std::uint32_t previous = BucketLists::none;
        std::uint32_t bucket = 0;
    };
    static_assert(sizeof(Body) == 64);

    // The earliest pair event found for a particle: its time (`never`: none)
    // and partner; pair_event() makes the event.
    struct PairPrediction {
        double time = never;
        std::uint32_t partner = 0;
        std::uint32_t partner_version = 0;  // the partner's version when predicted
    };

    // What save() writes for a particle besides its state: its time stamp,
    // its cell and its three predictions.
    struct SavedPredictions {
        double stamp = 0.0;
        std::uint32_t cell = 0;
        double wall_time = never;
        Crossing crossing;
        PairPrediction pair;
        std::uint32_t pair_i = 0;  // the pair event's indices, as saved
        std::uint32_t pair_j = 0;
    };
    struct SavedRun {
        std::int64_t steps_done = 0;
        StepCounts totals;
        CollisionSums sums;  // zero in a version 1 state, which had none
        // The cells a side it ran with (version 3); in versions 1 and 2, the
        // cost model's choice from N, r and L, which restore() makes again.
        std::optional<int> cells_per_side;
        // Both grow with the input, whatever its header says.
        std::vector<Particle> particles;  // each at its own stamp
        std::vector<SavedPredictions> predictions;
    };

    // A scene to run from its start: every prediction made here.
    Implementation(const World& world, std::vector<Particle> particles, const ExactOptions& options)
        : Implementation(world, std::move(particles), options, Unpredicted{}) {
        for (std::uint32_t i = 0; i < count(); ++i) {
            cells_.insert(i, cells_.grid().cell_of(body(i).position));
        }
        reject_overlaps();
        make_lines();
        // Every wall time first: the pair predictions read them. A particle's
        // predictions read nothing another's change, so any order gives the
        // same ones; cell by cell, a large scene's neighbours are read from
        // the caches instead of memory.
        for (std::uint32_t i = 0; i < count(); ++i) predict_wall(i);
        cells_.for_each_by_cell([&](std::uint32_t i) {
            predict_crossing(i);
            predict_pairs(i);
            reschedule(i);
        });
    }

    // Continues from the state save() wrote (read by read_saved(), its
    // particles checked by require_valid_scene()); the queue is rebuilt from
    // the saved predictions.
    Implementation(const World& world, SavedRun saved, const ExactOptions& options)
        : Implementation(world, std::move(saved.particles), options, Unpredicted{}) {
        now_ = static_cast<double>(saved.steps_done);
        steps_done_ = saved.steps_done;
        totals_ = saved.totals;
        collision_sums_ = saved.sums;
        const std::uint64_t cells = cells_.grid().cell_count();
        const auto fail = [](const std::string& why) {
            throw std::invalid_argument(std::string(restore_refusal) + " (" + why + ")");
        };
        for (std::uint32_t i = 0; i < count(); ++i) {
            const SavedPredictions& in = saved.predictions[i];
            if (!(in.stamp >= 0.0 && in.stamp <= now_)) fail("a time stamp outside the run");
            // Every event up to the saved step has happened: a prediction
            // before it would send the clock back.
            if (!(in.wall_time >= now_ && in.crossing.time >= now_ && in.pair.time >= now_))
                fail("a predicted event before the saved step");
            if (in.cell >= cells || in.crossing.cell >= cells) fail("a cell outside the grid");
            if (in.pair_i >= count() || in.pair_j >= count() || in.pair.partner >= count())
                fail("a particle index outside the scene");
            if (in.pair.time != never && !(in.pair.partner != i && in.pair_i == std::min(i, in.pair.partner) &&
                                           in.pair_j == std::max(i, in.pair.partner)))
                fail("a pair prediction that does not name the particle and its partner");
            body(i).stamp = in.stamp;
            cells_.insert(i, in.cell);
            body(i).wall_time = in.wall_time;
            plans_[i].crossing = in.crossing;
            plans_[i].pair = in.pair;
        }
        reject_disks_out_of_place(fail);
        if (periodic_) {
            // The whole boxes crossed since each stored position: as many as
            // put its path now in the cell it was saved in.
            const UniformGrid& grid = cells_.grid();
            for (std::uint32_t i = 0; i < count(); ++i) {
                const Vec2 now_at = position_at(i, now_);
                const std::uint32_t cell = cells_.cell_of_particle(i);
                const double centres[2] = {(grid.column(cell) + 0.5) * grid.cell_size(),
                                           (grid.row(cell) + 0.5) * grid.cell_size()};
                for (int axis = 0; axis < 2; ++axis) {
                    plans_[i].images[axis] =
                        static_cast<std::int32_t>(std::round((now_at[axis] - centres[axis]) / world_.box_size));
                }
            }
        }
        for (std::uint32_t i = 0; i < count(); ++i) reschedule(i);
        make_lines();
        snapshot_current_ = false;
    }

    // `version` 1 has no collision sums; 2 has them after the counts; 3 also
    // the cells a side after them.
    static SavedRun read_saved(SavedStateReader& in, int version) {
        SavedRun run;
        const std::uint64_t count = in.count(0xfffffffeU);
        const double now = in.real();
        run.steps_done = static_cast<std::int64_t>(in.count(max_exact_steps));
        if (now != static_cast<double>(run.steps_done)) in.fail("time and step disagree");
        run.totals = read_counts(in);
        if (version >= 2) {
            run.sums.pair_virial = in.real();
            run.sums.wall_impulse = in.real();
            if (!std::isfinite(run.sums.pair_virial) || !std::isfinite(run.sums.wall_impulse))
                in.fail("collision sums that are not finite");
        }
        if (version >= 3) {
            const std::uint64_t side = in.count(max_grid_cells);
            if (side == 0) in.fail("no cells");
            run.cells_per_side = static_cast<int>(side);
        }
        for (std::uint64_t i = 0; i < count; ++i) {
            run.particles.push_back(read_particle(in));
            SavedPredictions p;
            p.stamp = in.real();
            p.cell = static_cast<std::uint32_t>(in.count(UINT32_MAX));
            p.wall_time = in.real();
            p.crossing.time = in.real();
            p.crossing.cell = static_cast<std::uint32_t>(in.count(UINT32_MAX));
            p.pair.time = in.real();
            p.pair_i = static_cast<std::uint32_t>(in.count(UINT32_MAX));
            p.pair_j = static_cast<std::uint32_t>(in.count(UINT32_MAX));
            p.pair.partner = static_cast<std::uint32_t>(in.count(UINT32_MAX));
            p.pair.partner_version = static_cast<std::uint32_t>(in.count(UINT32_MAX));
            run.predictions.push_back(p);
        }
        return run;
    }

    void save(std::ostream& out) const {
        save_number(out, std::uint64_t{count()});
        save_number(out, now_);
        save_number(out, static_cast<std::uint64_t>(steps_done_));
        save_counts(out, totals_);
        save_number(out, collision_sums_.pair_virial);
        save_number(out, collision_sums_.wall_impulse);
        save_number(out, static_cast<std::uint64_t>(cells_.grid().per_side()));
        out << '\n';
        for (std::uint32_t i = 0; i < count(); ++i) {
            save_particle(out, particle_at_stamp(i));
            save_number(out, body(i).stamp);
            save_number(out, std::uint64_t{cells_.cell_of_particle(i)});
            save_number(out, body(i).wall_time);
            save_number(out, plans_[i].crossing.time);
            save_number(out, std::uint64_t{plans_[i].crossing.cell});
            const Event pair = pair_event(i);
            save_number(out, pair.time);
            save_number(out, std::uint64_t{pair.i});
            save_number(out, std::uint64_t{pair.j});
            save_number(out, std::uint64_t{plans_[i].pair.partner});
            save_number(out, std::uint64_t{plans_[i].pair.partner_version});
            out << '\n';
        }
    }

    void step() {
        if (steps_done_ >= max_exact_steps) throw std::overflow_error("the exact engine's clock ends at 2^53 steps");
        const double end = static_cast<double>(steps_done_ + 1);
        move_lines_to_now();
        last_step_ = {};
        several_events_ = 0;
        if (look_ahead_) {
            run_events(ladder_queue_, end);
        } else {
            run_events(linked_queue_, end);
        }
        now_ = end;
        ++steps_done_;
        snapshot_current_ = false;
        totals_ += last_step_;
    }

    // The step's events, from the queue chosen at the start (compiled for
    // each, so that neither pays for the other's choice at every event).
    template <typename Queue>
    void run_events(Queue& queue, double end) {
        std::uint64_t events = 0;
        while (!queue.empty() && queue.earliest().time <= end) {
            if (static_cast<double>(++events) > event_budget_)
                throw TooManyEvents(steps_done_ + 1, events - 1, predicted_events_);
            ++events_processed_;
            const std::uint32_t owner = queue.earliest_owner();
            if constexpr (std::is_same_v<Queue, LadderCalendar>) prefetch_coming_events();
            const Event event = queue.earliest();
            if (event.kind == EventKind::pair && pair_partner_moved(owner)) {
                predict_pairs(owner);
                reschedule(queue, owner);
                continue;
            }
            PARTICLESIM_ASSERT(event.time >= now_, "the calendar hands out events in time order");
            if constexpr (validating) {
                if (events % 1024 == 1) require_earliest_in_calendar(queue, event);
            }
            now_ = event.time;
            switch (event.kind) {
            case EventKind::wall: collide_with_wall(queue, event.i); break;
            case EventKind::pair: collide_pair(queue, event.i, event.j); break;
            case EventKind::cell_crossing: cross_cell(queue, event.i, event.j); break;
            }
        }
    }

    // Made when asked for: a run whose states are read only at its end
    // (perf mode) does not pay for one at every step.
    const std::vector<Particle>& snapshot() {
        if (!snapshot_current_) take_snapshot();
        snapshot_current_ = true;
        return snapshot_;
    }
    const World& world() const { return world_; }
    std::int64_t steps_done() const { return steps_done_; }
    const StepCounts& last_step() const { return last_step_; }
    const StepCounts& totals() const { return totals_; }
    const CollisionSums& collision_sums() const { return collision_sums_; }
    std::uint64_t several_events() const { return several_events_; }
    std::uint64_t events_processed() const { return events_processed_; }
    int cells_per_side() const { return cells_.grid().per_side(); }

private:
    struct Unpredicted {};

    // Every member sized for the particles; no cell filled, nothing predicted.
    Implementation(const World& world, std::vector<Particle> particles, const ExactOptions& options, Unpredicted)
        : world_(world),
          box_(Box::of(world)),
          periodic_(options.boundary == Boundary::periodic),
          cells_(neighbour_grid(world, particles, options), particles.size()),
          plans_(particles.size()),
          snapshot_(std::move(particles)),
          gathered_(2 * count() + 1),
          look_ahead_(options.look_ahead.value_or(count() >= exact_tuning::look_ahead_from) && !by_lines()),
          linked_queue_(look_ahead_ ? 0 : count(), Event{never, EventKind::cell_crossing, 0, 0}),
          ladder_queue_(look_ahead_ ? count() : 0, Event{never, EventKind::cell_crossing, 0, 0}),
          predicted_events_(estimated_events_per_step(world, snapshot_)),
          event_budget_(event_budget(options, predicted_events_, count())) {
        for (std::uint32_t i = 0; i < count(); ++i) {
            const Particle& p = snapshot_[i];
            Body& b = body(i);
            b.position = p.position;
            b.velocity = p.velocity;
            b.version = static_cast<std::uint32_t>(p.particle_collisions + p.wall_collisions);
            plans_[i].particle_collisions = p.particle_collisions;
            plans_[i].wall_collisions = p.wall_collisions;
        }
    }

    std::uint32_t count() const { return static_cast<std::uint32_t>(plans_.size()); }

    Body& body(std::uint32_t i) { return cells_.record(i); }
    const Body& body(std::uint32_t i) const { return cells_.record(i); }

    // The particle as stored: at its own time stamp.
    Particle particle_at_stamp(std::uint32_t i) const {
        return Particle{body(i).position, body(i).velocity, plans_[i].particle_collisions, plans_[i].wall_collisions};
    }

    // The particle's pair prediction as an event, the pair's indices in order
    // ({never, pair, 0, 0} when there is none).
    Event pair_event(std::uint32_t i) const {
        const PairPrediction& pair = plans_[i].pair;
        if (pair.time == never) return Event{never, EventKind::pair, 0, 0};
        return Event{pair.time, EventKind::pair, std::min(i, pair.partner), std::max(i, pair.partner)};
    }

    // One cell: neighbours are found by the particles' lines (PathLines).
    bool by_lines() const { return cells_.grid().per_side() == 1; }

    std::uint32_t version(std::uint32_t i) const { return body(i).version; }
    bool pair_partner_moved(std::uint32_t i) const {
        return plans_[i].pair.partner_version != version(plans_[i].pair.partner);
    }

    Vec2 position_at(std::uint32_t i, double time) const {
        const Body& b = body(i);
        return b.position + b.velocity * (time - b.stamp);
    }

    template <typename Cells, typename Visit>
    static void for_each_neighbour(const Cells& cells, std::uint32_t i, bool periodic, Visit&& visit) {
        const std::uint32_t cell = cells.cell_of_particle(i);
        const int column = cells.grid().column(cell);
        const int row = cells.grid().row(cell);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const auto others = [&](std::uint32_t j) {
                    if (j != i) visit(j);
                };
                if (periodic) {
                    cells.for_each_in_wrapped(column + dx, row + dy, others);
                } else {
                    cells.for_each_in(column + dx, row + dy, others);
                }
            }
        }
    }

    // In a periodic box, a separation made the nearest image's. A particle's
    // stored position lies in [0, L) (wrapped at its collisions), but where it
    // is now may be boxes away from it: its path since.
    double nearest_image(double separation) const {
        if (std::abs(separation) <= 0.5 * world_.box_size) return separation;  // nearly every pair tested
        return separation - world_.box_size * std::round(separation / world_.box_size);
    }
    Vec2 nearest_image(const Vec2& separation) const {
        return Vec2(nearest_image(separation.x()), nearest_image(separation.y()));
    }

    // Names the overlapping pair (i, j) with the lowest i, then the first j
    // met: searched cell by cell first (fast), then, only if there is one,
    // in index order. With a single cell (the lines), in the cells the rule
    // would have chosen: one cell would compare all N^2 / 2 pairs.
    void reject_overlaps() const {
        if (!by_lines()) {
            reject_overlaps(cells_);
            return;
        }
        reject_overlaps(cells_holding([&](std::uint32_t i) { return body(i).position; }));
    }

    // Cells holding each disk at at(i), for a search of overlaps where the
    // engine's own cells are one (the lines) or not yet trusted (a saved
    // state): of the rule's size, or in a periodic box (never the lines) the
    // engine's own grid, which wraps.
    template <typename At>
    CellList cells_holding(At&& at) const {
        CellList cells(periodic_ ? cells_.grid() : UniformGrid(world_.box_size, cells_per_side_for(world_, count())),
                       count());
        for (std::uint32_t i = 0; i < count(); ++i) cells.insert(i, cells.grid().cell_of(at(i)));
        return cells;
    }

    // Whether disks at `a` and `b` (the nearest images in a periodic box) are
    // closer than `contact`; none is closer than a contact below 0.
    bool closer_than(const Vec2& a, const Vec2& b, double contact) const {
        Vec2 separation = b - a;
        if (periodic_) separation = nearest_image(separation);
        return contact > 0.0 && separation.squaredNorm() < contact * contact;
    }

    // Touching is allowed, and a contact is known only to its coordinates'
    // rounding: a start's disks overlap where they are closer than
    // disks_overlap()'s tolerance allows by more than 2^-51 L, a few units in
    // the last place of a coordinate (far below r unless L passes about
    // 1e11 r, where the engine's own printed states would otherwise be refused).
    template <typename Cells>
    void reject_overlaps(const Cells& cells) const {
        const double contact = std::sqrt(box_.contact_dist_sq * (1.0 - overlap_tolerance)) - 0x1p-51 * world_.box_size;
        const auto overlaps = [&](std::uint32_t i, std::uint32_t j) {
            return j > i && closer_than(body(i).position, body(j).position, contact);
        };
        bool found = false;
        cells.for_each_by_cell([&](std::uint32_t i) {
            if (!found)
                for_each_neighbour(cells, i, periodic_, [&](std::uint32_t j) { found = found || overlaps(i, j); });
        });
        if (!found) return;
        for (std::uint32_t i = 0; i < count(); ++i) {
            for_each_neighbour(cells, i, periodic_, [&](std::uint32_t j) {
                if (overlaps(i, j)) throw OverlappingStart(i, j);
            });
        }
    }

    // A saved state (damaged, or edited by hand) whose disks, moved to the
    // saved step, lie outside the cells saved for them (the engine would
    // never test them against their neighbours) or overlap. Both tolerances
    // are thousands of times the rounding of moving a disk from its own
    // stamp, and far below a cell or a radius.
    template <typename Fail>
    void reject_disks_out_of_place(Fail&& fail) const {
        constexpr double rounding = 1e-12;      // of the magnitudes a position is made from
        constexpr double cell_margin = 1e-9;    // of a cell's width
        constexpr double overlap_depth = 1e-6;  // of a radius, as at a start (disks_overlap())
        const UniformGrid& grid = cells_.grid();
        std::vector<Vec2> now_at(count());
        std::vector<double> carried(count());  // the magnitude whose rounding a position carries
        for (std::uint32_t i = 0; i < count(); ++i) {
            const Body& b = body(i);
            const Vec2 moved = position_at(i, now_);
            carried[i] = rounding * (b.position.cwiseAbs().maxCoeff() +
                                     b.velocity.cwiseAbs().maxCoeff() * (now_ - b.stamp) + world_.box_size);
            now_at[i] = periodic_ ? Vec2(wrap_into_periodic_box(moved.x(), world_.box_size),
                                         wrap_into_periodic_box(moved.y(), world_.box_size))
                                  : moved;
            if (by_lines()) continue;
            const std::uint32_t cell = cells_.cell_of_particle(i);
            const Vec2 centre((grid.column(cell) + 0.5) * grid.cell_size(), (grid.row(cell) + 0.5) * grid.cell_size());
            Vec2 from_centre = now_at[i] - centre;
            if (periodic_) from_centre = nearest_image(from_centre);
            if (from_centre.cwiseAbs().maxCoeff() > grid.cell_size() * (0.5 + cell_margin) + carried[i])
                fail("disk " + std::to_string(i) + " is not in the cell saved for it");
        }
        const CellList cells = cells_holding([&](std::uint32_t i) { return now_at[i]; });
        cells.for_each_by_cell([&](std::uint32_t i) {
            for_each_neighbour(cells, i, periodic_, [&](std::uint32_t j) {
                if (j < i) return;
                const double contact = 2.0 * world_.radius - overlap_depth * world_.radius - carried[i] - carried[j];
                if (closer_than(now_at[i], now_at[j], contact))
                    fail("disks " + std::to_string(i) + " and " + std::to_string(j) + " overlap at the saved step");
            });
        });
    }

    // In a large scene nearly every line an event reads is a miss to memory,
    // and each waits for the one before (the queue entry names the particle,
    // the particle its cell, the cell its members), so the event rate fell
    // with N. The queue already knows the next events, so each
    // event fetches, in four stages, what those a few buckets behind it will
    // read: their queue entries; their particles and pair partners; the
    // heads of the cells they will search; the first member of each of
    // those cells. A collision searches around both partners; a crossing
    // only the three cells that become neighbours, and it moves the particle
    // between two cells' lists. Each stage reads only what the stage before
    // fetched. Prefetches are hints: a queue that changes meanwhile costs a
    // wasted fetch, never a different event.
    void prefetch_coming_events() {
        ladder_queue_.for_each_coming(look_entries_, [&](std::uint32_t o) { ladder_queue_.prefetch_entry(o); });
        ladder_queue_.for_each_coming(look_particles_, [&](std::uint32_t o) {
            prefetch_particle(o);
            if (const std::uint32_t partner = pair_partner(o); partner != BucketLists::none) {
                ladder_queue_.prefetch_entry(partner);
                prefetch_particle(partner);
            }
        });
        ladder_queue_.for_each_coming(look_heads_, [&](std::uint32_t o) {
            const Event& event = ladder_queue_.entry(o);
            if (const std::optional<CellLine> line = crossing_line(event, o)) {
                cells_.prefetch_heads_of_three(line->middle, line->stride);
                cells_.prefetch_head(event.j);
                cells_.prefetch_head(cells_.cell_of_particle(o));
                cells_.prefetch_list_neighbours(o);
                return;
            }
            for_each_searched_cell(o, [&](std::uint32_t cell) { cells_.prefetch_heads_around(cell); });
        });
        ladder_queue_.for_each_coming(look_members_, [&](std::uint32_t o) {
            const auto fetch_member = [&](std::uint32_t first) {
                cells_.prefetch_links(first);  // the particle and its links; `none`: the spare slot
            };
            const Event& event = ladder_queue_.entry(o);
            if (const std::optional<CellLine> line = crossing_line(event, o)) {
                cells_.for_each_first_member_of_three(line->middle, line->stride, fetch_member);
                cells_.prefetch_links(cells_.first_member(event.j));
                return;
            }
            for_each_searched_cell(
                o, [&](std::uint32_t cell) { cells_.for_each_first_member_around(cell, fetch_member); });
        });
    }

    // Three cells in a line: `middle` and the cells `stride` either side.
    struct CellLine {
        std::int64_t middle;
        std::int64_t stride;
    };
    // For a crossing, the three cells that become neighbours (as
    // cross_cell() finds them): one further along the step from the cell
    // entered, and across it. In a periodic box a crossing at the grid's
    // edge, or across it, wraps: there the line misses (a wasted fetch).
    std::optional<CellLine> crossing_line(const Event& event, std::uint32_t owner) const {
        if (event.kind != EventKind::cell_crossing) return std::nullopt;
        const auto entered = static_cast<std::int64_t>(event.j);
        const std::int64_t step = entered - static_cast<std::int64_t>(cells_.cell_of_particle(owner));
        const bool along_row = step == 1 || step == -1;
        return CellLine{entered + step, along_row ? cells_.grid().per_side() : 1};
    }

    // The other particle of the owner's pair event, or none.
    std::uint32_t pair_partner(std::uint32_t owner) const {
        const Event& event = ladder_queue_.entry(owner);
        return event.kind == EventKind::pair ? event.i ^ event.j ^ owner
                                             : BucketLists::none;  // owner is one of the two
    }

    // visit(cell) for each cell around which the owner's wall or pair event
    // will search for partners: the owner's, and its pair partner's.
    template <typename Visit>
    void for_each_searched_cell(std::uint32_t owner, Visit&& visit) const {
        visit(cells_.cell_of_particle(owner));
        if (const std::uint32_t partner = pair_partner(owner); partner != BucketLists::none)
            visit(cells_.cell_of_particle(partner));
    }

    void prefetch_particle(std::uint32_t i) const {
        cells_.prefetch_links(i);  // its state and links
        prefetch(&plans_[i]);
    }

    // Rounding may put a prediction a hair before the present; time must
    // never go back.
    double not_before_now(double time) const { return std::max(time, now_); }

    // The calendar's earliest event comes before every other entry in the
    // rules' order (a check of O(N)).
    template <typename Queue>
    void require_earliest_in_calendar(const Queue& queue, const Event& earliest) const {
        for (std::uint32_t owner = 0; owner < count(); ++owner) {
            PARTICLESIM_ASSERT(!comes_before(queue.entry(owner), earliest), "the calendar's earliest entry is first");
        }
    }

    void predict_wall(std::uint32_t i) {
        if (periodic_) {
            body(i).wall_time = never;
            return;
        }
        Body& b = body(i);
        const WallHit hit = time_to_wall(b.position, b.velocity, box_);
        b.wall_time = hit.time == never ? never : not_before_now(b.stamp + hit.time);
    }

    // The next time the particle leaves its cell, and the cell it enters.
    void predict_crossing(std::uint32_t i) {
        const std::uint32_t cell = cells_.cell_of_particle(i);
        predict_crossing(i, cells_.grid().column(cell), cells_.grid().row(cell));
    }

    // The same for a particle in the cell at (column, row).
    void predict_crossing(std::uint32_t i, int column, int row) {
        const Body& p = body(i);
        const UniformGrid& grid = cells_.grid();
        // Both axes at once, each lane the time to the cell edge it moves
        // towards (`never` at the grid's edge or without motion), with
        // selects instead of branches on the velocity's signs, which are
        // random (as in time_to_wall()); the same IEEE operations as one
        // axis at a time.
        // In a periodic box the cell's frame is the stored position's moved
        // by the whole boxes crossed since (Plans::images).
        const TwoDoubles where = periodic_ ? TwoDoubles{p.position.x() - plans_[i].images[0] * world_.box_size,
                                                        p.position.y() - plans_[i].images[1] * world_.box_size}
                                           : TwoDoubles{p.position.x(), p.position.y()};
        const TwoDoubles speed{p.velocity.x(), p.velocity.y()};
        const TwoDoubles index{static_cast<double>(column), static_cast<double>(row)};
        const double last = static_cast<double>(grid.per_side() - 1);
        const TwoDoubles edge = (speed > 0.0 ? index + 1.0 : index) * grid.cell_size();
        const TwoMasks exits = periodic_ ? (speed > 0.0) | (speed < 0.0)
                                         : ((speed > 0.0) & (index < last)) | ((speed < 0.0) & (index > 0.0));
        const TwoDoubles to_edge = exits ? (edge - where) / speed : TwoDoubles{never, never};
        const double along_x = to_edge[0];
        const double along_y = to_edge[1];
        const double delay = std::min(along_x, along_y);
        if (delay == never) {
            plans_[i].crossing = {};
            return;
        }
        const int x_first = static_cast<int>(along_x <= along_y);
        column += x_first * (2 * static_cast<int>(p.velocity.x() > 0.0) - 1);
        row += (1 - x_first) * (2 * static_cast<int>(p.velocity.y() > 0.0) - 1);
        if (periodic_) {  // one step past an edge wraps to the other
            const int side = grid.per_side();
            column += column < 0 ? side : column >= side ? -side : 0;
            row += row < 0 ? side : row >= side ? -side : 0;
        }
        plans_[i].crossing = {not_before_now(p.stamp + delay), grid.cell_at(column, row)};
    }

    // Tests the pair (i, j) at the later of their stamps, and keeps a contact
    // as i's pair prediction if it comes first. contact_time() gives the same
    // bits for (i, j) and (j, i) (negating dp and dv changes no product), so i
    // comes first.
    void consider_pair(std::uint32_t i, std::uint32_t j) {
        ++last_step_.pair_tests;
        const double reference = std::max(body(i).stamp, body(j).stamp);
        Vec2 separation = position_at(j, reference) - position_at(i, reference);
        if (periodic_) separation = nearest_image(separation);
        const double delay = contact_time(separation, body(j).velocity - body(i).velocity, box_.contact_dist_sq);
        if (delay != never) keep_contact(i, j, reference + delay);
    }

    // consider_pair() for (i, j) and (i, k) at once, one pair in each lane:
    // the same operations on the same values, so the same bits.
    void consider_two_pairs(std::uint32_t i, std::uint32_t j, std::uint32_t k) {
        last_step_.pair_tests += 2;
        const Body& own = body(i);
        const Body& first = body(j);
        const Body& second = body(k);
        const TwoDoubles own_stamp{own.stamp, own.stamp};
        const TwoDoubles other_stamp{first.stamp, second.stamp};
        const TwoDoubles reference = own_stamp < other_stamp ? other_stamp : own_stamp;  // std::max
        const TwoDoubles own_since = reference - own_stamp;
        const TwoDoubles other_since = reference - other_stamp;
        const TwoDoubles own_x = own.position.x() + own.velocity.x() * own_since;
        const TwoDoubles own_y = own.position.y() + own.velocity.y() * own_since;
        const TwoDoubles other_vx{first.velocity.x(), second.velocity.x()};
        const TwoDoubles other_vy{first.velocity.y(), second.velocity.y()};
        const TwoDoubles other_x = TwoDoubles{first.position.x(), second.position.x()} + other_vx * other_since;
        const TwoDoubles other_y = TwoDoubles{first.position.y(), second.position.y()} + other_vy * other_since;
        TwoDoubles dx = other_x - own_x;
        TwoDoubles dy = other_y - own_y;
        if (periodic_) {
            // Nearly every pair is nearer than half a box on both axes: one test of all four.
            const double half = 0.5 * world_.box_size;
            const TwoMasks far = (dx > half) | (dx < -half) | (dy > half) | (dy < -half);
            if (far[0] != 0 || far[1] != 0) {
                for (int lane = 0; lane < 2; ++lane) {
                    dx[lane] = nearest_image(dx[lane]);
                    dy[lane] = nearest_image(dy[lane]);
                }
            }
        }
        const TwoDoubles delay =
            contact_times(dx, dy, other_vx - own.velocity.x(), other_vy - own.velocity.y(), box_.contact_dist_sq);
        if (delay[0] != never) keep_contact(i, j, reference[0] + delay[0]);
        if (delay[1] != never) keep_contact(i, k, reference[1] + delay[1]);
    }

    // Keeps the pair event of (i, j), a contact at `contact`, as i's pair
    // prediction if it comes first. Pair events at or after either
    // particle's wall event can never happen: the wall event comes first in
    // the order and changes a velocity. The event is built only for a
    // contact that comes in time: most pairs tested never meet.
    void keep_contact(std::uint32_t i, std::uint32_t j, double contact) {
        const double time = not_before_now(contact);
        if (!(time < body(i).wall_time && time < body(j).wall_time && time <= plans_[i].pair.time)) return;
        const Event event{time, EventKind::pair, std::min(i, j), std::max(i, j)};
        if (event < pair_event(i)) plans_[i].pair = {time, j, version(j)};
    }

    // consider_pair(i, j) for each of the n candidates j, two at a time. The
    // prediction kept is the earliest, whatever the order.
    void consider_pairs(std::uint32_t i, const std::uint32_t* candidates, std::size_t n) {
        std::size_t k = 0;
        for (; k + 1 < n; k += 2) consider_two_pairs(i, candidates[k], candidates[k + 1]);
        if (k < n) consider_pair(i, candidates[k]);
    }

    // The particles of the cell at (column, row), i excepted, after the n
    // in gathered_ (CellList::gather_in()); returns the new count.
    std::size_t gather_cell(int column, int row, std::uint32_t i, std::size_t n) {
        return periodic_ ? cells_.gather_in_wrapped(column, row, i, gathered_.data(), n)
                         : cells_.gather_in(column, row, i, gathered_.data(), n);
    }

    // The particles of the 3 x 3 cells around i's, i excepted, after the n
    // in gathered_; returns the new count.
    std::size_t gather_around(std::uint32_t i, std::size_t n) {
        const std::uint32_t cell = cells_.cell_of_particle(i);
        const int column = cells_.grid().column(cell);
        const int row = cells_.grid().row(cell);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) n = gather_cell(column + dx, row + dy, i, n);
        }
        return n;
    }

    void predict_pairs(std::uint32_t i) {
        plans_[i].pair = {};
        if (!by_lines()) {
            consider_pairs(i, gathered_.data(), gather_around(i, 0));
            return;
        }
        near_.clear();
        lines_.gather_near(i, near_);
        consider_pairs(i, near_.data(), near_.size());
    }

    // The lines' common time (the epoch) is the start of the current step,
    // so that no line's point lies far outside the box.
    void make_lines() {
        if (!by_lines()) return;
        std::vector<Particle> at_stamps;
        at_stamps.reserve(count());
        for (std::uint32_t i = 0; i < count(); ++i) at_stamps.push_back(particle_at_stamp(i));
        lines_.assign(at_stamps, box_);
        move_lines_to_now();
    }

    void move_lines_to_now() {
        if (!by_lines()) return;
        lines_epoch_ = now_;
        lines_.move_each([&](std::uint32_t i) { return position_at(i, lines_epoch_); });
    }

    // After a collision: the particle's new line, through where it would
    // have been at the epoch.
    void renew_line(std::uint32_t i) {
        if (by_lines()) lines_.set(i, position_at(i, lines_epoch_), body(i).velocity);
    }

    // Puts the first of the particle's three predictions in the queue.
    // At equal times the kinds decide (walls, then pairs, then crossings),
    // so three comparisons of times choose, and only the chosen event is
    // built: building all three on the stack and copying the first had its
    // loads wait for the stores of the parts.
    template <typename Queue>
    void reschedule(Queue& queue, std::uint32_t i) {
        const double wall_time = body(i).wall_time;
        const Crossing& crossing = plans_[i].crossing;
        const double pair_time = plans_[i].pair.time;
        if (pair_time < wall_time && pair_time <= crossing.time) {
            queue.replace(i, pair_event(i));
        } else if (crossing.time < wall_time) {
            queue.replace(i, Event{crossing.time, EventKind::cell_crossing, i, crossing.cell});
        } else {
            queue.replace(i, Event{wall_time, EventKind::wall, i, 0});
        }
    }
    // The same, outside the event loop.
    void reschedule(std::uint32_t i) {
        if (look_ahead_) {
            reschedule(ladder_queue_, i);
        } else {
            reschedule(linked_queue_, i);
        }
    }

    void note_event(std::uint32_t i) {
        const std::int64_t step = steps_done_;
        std::int64_t& mark = plans_[i].last_event_mark;
        if (mark >> 1 != step) {
            mark = 2 * step;
        } else if ((mark & 1) == 0) {
            mark |= 1;
            ++several_events_;
        }
    }

    template <typename Queue>
    void collide_with_wall(Queue& queue, std::uint32_t i) {
        Particle p = particle_at_stamp(i);
        // The same start state as the prediction, so the same hit.
        const WallHit hit = time_to_wall(p.position, p.velocity, box_);
        collision_sums_.wall_impulse +=
            2.0 * ((hit.on_x ? std::abs(p.velocity.x()) : 0.0) + (hit.on_y ? std::abs(p.velocity.y()) : 0.0));
        bounce_off_wall(p, hit, box_);
        Body& b = body(i);
        b.position = p.position;
        b.velocity = p.velocity;
        b.stamp = now_;
        ++b.version;
        plans_[i].wall_collisions = p.wall_collisions;
        renew_line(i);
        ++last_step_.wall_collisions;
        note_event(i);
        predict_wall(i);
        predict_crossing(i);
        predict_pairs(i);
        reschedule(queue, i);
    }

    template <typename Queue>
    void collide_pair(Queue& queue, std::uint32_t i, std::uint32_t j) {
        Body& a = body(i);
        Body& b = body(j);
        a.position = position_at(i, now_);
        b.position = position_at(j, now_);
        // In a periodic box, b's image next to a (each keeps its own position).
        if (!periodic_) {
            clamp_into_box(a.position, box_);
            clamp_into_box(b.position, box_);
        }
        // Both partners' candidates are gathered first: the reads need no
        // velocity, so they overlap the exchange's long chain of dependent
        // operations instead of waiting for it.
        const std::size_t around_i = by_lines() ? 0 : gather_around(i, 0);
        const std::size_t around_both = by_lines() ? 0 : gather_around(j, around_i);
        const Vec2 b_image = periodic_ ? a.position + nearest_image(b.position - a.position) : b.position;
        a.stamp = now_;
        b.stamp = now_;
        const Vec2 velocity_before = a.velocity;
        exchange_normal_velocities(a.position, b_image, a.velocity, b.velocity);
        collision_sums_.pair_virial += (a.velocity - velocity_before).dot(a.position - b_image);
        if (periodic_) {
            // Stored again in [0, L), measured from the box: the whole boxes
            // crossed since move into Plans::images.
            for (const std::uint32_t k : {i, j}) {
                Vec2& at = body(k).position;
                for (int axis = 0; axis < 2; ++axis) {
                    if (at[axis] >= 0.0 && at[axis] < world_.box_size) continue;  // nearly always
                    const double boxes = std::floor(at[axis] / world_.box_size);
                    at[axis] = wrap_into_periodic_box(at[axis], world_.box_size);
                    plans_[k].images[axis] -= static_cast<std::int32_t>(boxes);
                }
            }
        }
        renew_line(i);
        renew_line(j);
        ++plans_[i].particle_collisions;
        ++plans_[j].particle_collisions;
        ++a.version;
        ++b.version;
        ++last_step_.particle_collisions;
        note_event(i);
        note_event(j);
        // Both wall times before any pair prediction: the pruning reads them.
        predict_wall(i);
        predict_wall(j);
        for (const std::uint32_t k : {i, j}) {
            predict_crossing(k);
            if (by_lines()) {
                predict_pairs(k);
            } else {
                plans_[k].pair = {};
                const std::size_t first = k == i ? 0 : around_i;
                consider_pairs(k, gathered_.data() + first, (k == i ? around_i : around_both) - first);
            }
            reschedule(queue, k);
        }
    }

    // Only the cells that have just become neighbours need new predictions.
    template <typename Queue>
    void cross_cell(Queue& queue, std::uint32_t i, std::uint32_t cell) {
        if (periodic_) {
            cross_cell_periodic(queue, i, cell);
            return;
        }
        const std::uint32_t old_cell = cells_.cell_of_particle(i);
        cells_.move(i, cell);
        const UniformGrid& grid = cells_.grid();
        const int column = grid.column(cell);
        const int row = grid.row(cell);
        // The cell entered is the next one along one axis, so the step is
        // told by the indices alone (one division fewer). The three cells
        // that become neighbours lie one further along that axis and run
        // across the other. All in arithmetic: the axis and the direction
        // are random, and branches on them were mispredicted half the time.
        const int step_x = static_cast<int>(cell == old_cell + 1) - static_cast<int>(cell + 1 == old_cell);
        const int step_y = (1 - step_x * step_x) * (2 * static_cast<int>(cell > old_cell) - 1);
        meet_new_neighbours(queue, i, column, row, step_x, step_y);
    }

    // After a crossing into the cell at (column, row), one step (step_x,
    // step_y) along an axis: the pairs with the three cells that have become
    // neighbours, one further along that axis and across the other; the next
    // crossing; the queue entry.
    template <typename Queue>
    void meet_new_neighbours(Queue& queue, std::uint32_t i, int column, int row, int step_x, int step_y) {
        const int across_x = 1 - step_x * step_x;  // 1 when the step is along y
        const int across_y = 1 - across_x;
        std::size_t n = 0;
        for (int k = -1; k <= 1; ++k)
            n = gather_cell(column + step_x + across_x * k, row + step_y + across_y * k, i, n);
        consider_pairs(i, gathered_.data(), n);
        predict_crossing(i, column, row);
        reschedule(queue, i);
    }

    // The same in a periodic box, where a crossing may wrap around the box's
    // edge: the particle's path has then crossed one more box (Plans::images). Its
    // stored position stays: the physics never depends on when crossings
    // happen, so every cell count gives the same events.
    template <typename Queue>
    void cross_cell_periodic(Queue& queue, std::uint32_t i, std::uint32_t cell) {
        const UniformGrid& grid = cells_.grid();
        const std::uint32_t old_cell = cells_.cell_of_particle(i);
        const int old_column = grid.column(old_cell);
        const int old_row = grid.row(old_cell);
        cells_.move(i, cell);
        const int column = grid.column(cell);
        const int row = grid.row(cell);
        const auto step_of = [](int from, int to) {
            const int step = to - from;
            return step > 1 ? -1 : step < -1 ? 1 : step;  // a jump across the grid is one step the other way
        };
        const int step_x = step_of(old_column, column);
        const int step_y = step_of(old_row, row);
        if (column - old_column > 1) --plans_[i].images[0];
        if (column - old_column < -1) ++plans_[i].images[0];
        if (row - old_row > 1) --plans_[i].images[1];
        if (row - old_row < -1) ++plans_[i].images[1];
        meet_new_neighbours(queue, i, column, row, step_x, step_y);
    }

    void take_snapshot() {
        for (std::uint32_t i = 0; i < count(); ++i) {
            Particle& out = snapshot_[i];
            out = particle_at_stamp(i);
            out.position = position_at(i, now_);
            if (periodic_) {
                out.position = Vec2(wrap_into_periodic_box(out.position.x(), world_.box_size),
                                    wrap_into_periodic_box(out.position.y(), world_.box_size));
            } else {
                clamp_into_box(out.position, box_);
            }
        }
    }

    World world_;
    Box box_;
    bool periodic_;  // the box wraps: no walls, the nearest image meets
    CellListOf<Body> cells_;
    // The rest of what an event reads and writes of its particles, in one
    // 64-byte line: the crossing and pair predictions, the step of the
    // particle's last event (twice it, plus 1 once a second event in that
    // step was counted by note_event()), in a periodic box the whole boxes
    // its path has crossed since its stored position, along x and y (what
    // the cell it is in shows), and its collision counts.
    struct alignas(64) Plans {
        Crossing crossing;
        PairPrediction pair;
        std::int64_t last_event_mark = -2;
        std::array<std::int32_t, 2> images{0, 0};
        std::uint64_t particle_collisions = 0;
        std::uint64_t wall_collisions = 0;
    };
    static_assert(sizeof(Plans) == 64);
    HugePageVector<Plans> plans_;
    std::vector<Particle> snapshot_;  // the state at the last whole step, while snapshot_current_
    bool snapshot_current_ = true;    // the start's state is the particles given
    // With a single cell: every particle's line at lines_epoch_.
    PathLines lines_;
    double lines_epoch_ = 0.0;
    std::vector<std::uint32_t> near_;
    // The candidates of a search in the cells: room for every particle
    // twice and one more (a pair collision gathers both partners',
    // CellList::gather_in()).
    std::vector<std::uint32_t> gathered_;
    // A state that outgrows the caches: the queue in two tiers, and each
    // event prefetching for the events behind it (prefetch_coming_events());
    // else the linked buckets. The queue not chosen stays empty.
    bool look_ahead_;
    LinkedCalendar linked_queue_;
    LadderCalendar ladder_queue_;
    double now_ = 0.0;
    std::int64_t steps_done_ = 0;
    StepCounts last_step_;
    StepCounts totals_;
    CollisionSums collision_sums_;  // since the run started (saved and restored)
    std::uint64_t several_events_ = 0;
    std::uint64_t events_processed_ = 0;  // by this object, not saved: a measure of work
    double predicted_events_;             // per step
    double event_budget_;                 // per step
    // The prefetching's four stages, each a few buckets nearer than the last.
    LadderCalendar::LookAhead look_entries_{exact_tuning::look_entries_buckets, true};
    LadderCalendar::LookAhead look_particles_{exact_tuning::look_particles_buckets};
    LadderCalendar::LookAhead look_heads_{exact_tuning::look_heads_buckets};
    LadderCalendar::LookAhead look_members_{exact_tuning::look_members_buckets};
};

namespace {

void check_options(const ExactOptions& options) {
    const OptionsCheck check("particlesim::ExactOptions");
    check.known_boundary("boundary", options.boundary);
    if (options.cells_per_side) check.in_range("cells_per_side", *options.cells_per_side, 1, max_grid_cells);
    if (options.max_events_per_step && *options.max_events_per_step == 0)
        check.fail("max_events_per_step must be >= 1");
}

std::vector<Particle> checked(const World& world, std::vector<Particle> particles, const ExactOptions& options) {
    check_options(options);
    require_valid_scene("particlesim::ExactSimulation", world, particles,
                        options.boundary == Boundary::periodic ? CentresIn::periodic_box : CentresIn::walled_box);
    return particles;
}

}  // namespace

ExactSimulation::ExactSimulation(const World& world, std::vector<Particle> particles, const ExactOptions& options)
    : engine_(std::make_unique<Implementation>(world, checked(world, std::move(particles), options), options)) {}

ExactSimulation::ExactSimulation(std::unique_ptr<Implementation> engine) : engine_(std::move(engine)) {}

ExactSimulation ExactSimulation::restore(const World& world, std::istream& saved, const ExactOptions& options) {
    check_options(options);
    SavedStateReader reader(saved, restore_refusal);
    reader.expect("exact-engine-state");
    const std::string version = reader.word();
    if (version != "1" && version != "2" && version != "3") reader.fail("an unknown version");
    Implementation::SavedRun run = Implementation::read_saved(reader, version == "1" ? 1 : version == "2" ? 2 : 3);
    require_valid_scene("particlesim::ExactSimulation::restore", world, run.particles,
                        options.boundary == Boundary::periodic ? CentresIn::periodic_saved : CentresIn::walled_box);
    ExactOptions as_saved = options;
    if (run.cells_per_side) {
        if (options.cells_per_side && *options.cells_per_side != *run.cells_per_side) {
            throw std::invalid_argument("particlesim::ExactOptions: cells_per_side " +
                                        std::to_string(*options.cells_per_side) + ", but the state was saved with " +
                                        std::to_string(*run.cells_per_side));
        }
        as_saved.cells_per_side = run.cells_per_side;
    } else if (!options.cells_per_side) {
        // A version that does not save the side: the model's choice, as its start made it.
        as_saved.cells_per_side = modelled_cells_per_side(world, run.particles.size(), options.boundary);
    }
    return ExactSimulation(std::make_unique<Implementation>(world, std::move(run), as_saved));
}

void ExactSimulation::save(std::ostream& out) const {
    out << "exact-engine-state 3\n";
    engine_->save(out);
}

ExactSimulation::~ExactSimulation() = default;
ExactSimulation::ExactSimulation(ExactSimulation&&) noexcept = default;
ExactSimulation& ExactSimulation::operator=(ExactSimulation&&) noexcept = default;

void ExactSimulation::step() { engine_->step(); }
// Logically const: the state is made from the particles' records on demand.
std::span<const Particle> ExactSimulation::particles() const { return engine_->snapshot(); }
const World& ExactSimulation::world() const { return engine_->world(); }
std::int64_t ExactSimulation::steps_done() const { return engine_->steps_done(); }
const StepCounts& ExactSimulation::last_step() const { return engine_->last_step(); }
const StepCounts& ExactSimulation::totals() const { return engine_->totals(); }
const CollisionSums& ExactSimulation::collision_sums() const { return engine_->collision_sums(); }
std::uint64_t ExactSimulation::last_step_particles_with_several_events() const { return engine_->several_events(); }
std::uint64_t ExactSimulation::events_processed() const { return engine_->events_processed(); }
int ExactSimulation::cells_per_side() const { return engine_->cells_per_side(); }

double estimated_events_per_step(const World& world, std::span<const Particle> particles) {
    double speed_sum = 0.0;  // sum of |vx| + |vy|
    for (const Particle& p : particles) speed_sum += std::abs(p.velocity.x()) + std::abs(p.velocity.y());
    if (speed_sum == 0.0) return 0.0;
    const double span = world.upper() - world.lower();
    if (!(span > 0.0)) return never;  // a moving disk that fills the box bounces forever
    const double walls = speed_sum / span;
    // Ideal gas: collision length 4r per unit path, density of the others (N - 1) / L^2,
    // relative speeds about sqrt(2) times the speeds.
    const double density = static_cast<double>(particles.size() - 1) / (world.box_size * world.box_size);
    const double pairs = 0.5 * speed_sum * 4.0 * world.radius * density * std::sqrt(2.0);
    return walls + pairs;
}

void require_feasible_exact_run(const World& world, std::span<const Particle> particles, std::int64_t steps) {
    if (steps > max_exact_steps) {
        throw std::invalid_argument("S = " + std::to_string(steps) +
                                    " is beyond the exact engine's clock (at most 2^53 steps)");
    }
    const double events = estimated_events_per_step(world, particles) * static_cast<double>(steps);
    if (!(events <= max_estimated_run_events)) {
        throw std::invalid_argument("the exact engine would need about " + format_brief(events) +
                                    " events for this scene (limit " + format_brief(max_estimated_run_events) +
                                    "); use fewer steps or the step engine");
    }
}

}  // namespace particlesim
