#include "particlesim/exact_simulation.hpp"

#include "cell_list.hpp"
#include "event_queue.hpp"
#include "particlesim/box.hpp"
#include "particlesim/physics.hpp"
#include "scene_checks.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace particlesim {

OverlappingStart::OverlappingStart(std::uint32_t first, std::uint32_t second)
    : std::invalid_argument("particles " + std::to_string(first) + " and " + std::to_string(second) +
                            " overlap; the exact engine needs a start where no two disks overlap"),
      first_(first), second_(second) {}

namespace {

// Cells a little wider than a diameter, so that rounding at a cell border
// cannot hide a contact; and no more cells than about 4 per particle, so
// that memory stays O(N) in a huge box.
int cells_per_side_for(const SimParams& params, std::size_t particle_count) {
    const double by_diameter = std::floor(params.box_size / (2.0 * params.radius * (1.0 + 1e-6)));
    const double by_count = 2.0 * std::ceil(std::sqrt(static_cast<double>(particle_count)));
    return static_cast<int>(std::max(1.0, std::min(by_diameter, by_count)));
}

}  // namespace

// The engine's state. A particle's stored position is where it was at its
// own time stamp, the time of its last collision (or 0); it is moved only by
// its own collisions, so that every prediction reads an unchanged state.
class ExactSimulation::Engine {
public:
    Engine(const SimParams& params, std::vector<Particle> particles, const ExactOptions& options)
        : params_(params), box_(Box::of(params)), particles_(std::move(particles)),
          cells_(options.cells_per_side > 0 ? options.cells_per_side : cells_per_side_for(params, particles_.size()),
                 params.box_size, particles_.size()),
          stamp_(particles_.size(), 0.0), wall_time_(particles_.size(), never),
          last_event_step_(particles_.size(), -1), last_repeat_step_(particles_.size(), -1), snapshot_(particles_) {
        for (std::uint32_t i = 0; i < count(); ++i) {
            const Vec2& p = particles_[i].position;
            cells_.insert(i, cells_.cell_at(cells_.column_of(p.x()), cells_.column_of(p.y())));
        }
        reject_overlaps();
        for (std::uint32_t i = 0; i < count(); ++i) predict_wall(i);
        for (std::uint32_t i = 0; i < count(); ++i) {
            predict_crossing(i);
            for_each_neighbour(i, [&](std::uint32_t j) {
                if (j > i) predict_pair(i, j);
            });
        }
    }

    void step() {
        const double end = static_cast<double>(steps_done_ + 1);
        last_step_ = {};
        several_events_ = 0;
        while (!queue_.empty() && queue_.earliest().time <= end) {
            const Event event = queue_.pop();
            if (is_stale(event)) continue;
            now_ = event.time;
            switch (event.kind) {
            case EventKind::wall: collide_with_wall(event.i); break;
            case EventKind::pair: collide_pair(event.i, event.j); break;
            case EventKind::cell_crossing: cross_cell(event.i, event.j); break;
            }
            queue_.sweep_if_grown([this](const Event& e) { return is_stale(e); });
        }
        now_ = end;
        ++steps_done_;
        take_snapshot();
        totals_ += last_step_;
    }

    const std::vector<Particle>& snapshot() const { return snapshot_; }
    std::int64_t steps_done() const { return steps_done_; }
    const StepCounts& last_step() const { return last_step_; }
    const StepCounts& totals() const { return totals_; }
    std::uint64_t several_events() const { return several_events_; }
    int cells_per_side() const { return cells_.side(); }

private:
    std::uint32_t count() const { return static_cast<std::uint32_t>(particles_.size()); }

    // Changes exactly when the velocity does: at each of the particle's collisions.
    std::uint32_t version(std::uint32_t i) const {
        return static_cast<std::uint32_t>(particles_[i].particle_collisions + particles_[i].wall_collisions);
    }
    bool is_stale(const Event& e) const {
        return e.version_i != version(e.i) || (e.kind == EventKind::pair && e.version_j != version(e.j));
    }

    Vec2 position_at(std::uint32_t i, double time) const {
        return particles_[i].position + particles_[i].velocity * (time - stamp_[i]);
    }

    template <typename Visit>
    void for_each_neighbour(std::uint32_t i, Visit&& visit) const {
        const std::uint32_t cell = cells_.cell_of_particle(i);
        const int column = cells_.column(cell);
        const int row = cells_.row(cell);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                cells_.for_each_in(column + dx, row + dy, [&](std::uint32_t j) {
                    if (j != i) visit(j);
                });
            }
        }
    }

    void reject_overlaps() const {
        for (std::uint32_t i = 0; i < count(); ++i) {
            for_each_neighbour(i, [&](std::uint32_t j) {
                const Vec2 d = particles_[j].position - particles_[i].position;
                if (j > i && d.dot(d) < box_.contact_dist_sq) throw OverlappingStart(i, j);
            });
        }
    }

    void push(EventKind kind, double time, std::uint32_t i, std::uint32_t j) {
        // Rounding may put a prediction a hair before the present; the queue
        // must never go back in time.
        const double at = std::max(time, now_);
        const std::uint32_t version_j = kind == EventKind::pair ? version(j) : 0;
        queue_.push({at, kind, i, j, version(i), version_j});
        ++last_step_.candidates;
    }

    void predict_wall(std::uint32_t i) {
        const WallHit hit = time_to_wall(particles_[i].position, particles_[i].velocity, box_);
        wall_time_[i] = hit.time == never ? never : std::max(stamp_[i] + hit.time, now_);
        if (hit.time != never) push(EventKind::wall, wall_time_[i], i, 0);
    }

    // Pair events at or after either particle's next wall event can never
    // happen: the wall event comes first in the order and changes a velocity.
    void predict_pair(std::uint32_t a, std::uint32_t b) {
        const std::uint32_t i = std::min(a, b);
        const std::uint32_t j = std::max(a, b);
        ++last_step_.pair_tests;
        const double reference = std::max(stamp_[i], stamp_[j]);
        const double delay = contact_time(position_at(j, reference) - position_at(i, reference),
                                          particles_[j].velocity - particles_[i].velocity, box_.contact_dist_sq);
        if (delay == never) return;
        const double time = std::max(reference + delay, now_);
        if (time < wall_time_[i] && time < wall_time_[j]) push(EventKind::pair, time, i, j);
    }

    // The next time the particle leaves its cell, and the cell it enters.
    void predict_crossing(std::uint32_t i) {
        const Particle& p = particles_[i];
        const std::uint32_t cell = cells_.cell_of_particle(i);
        int column = cells_.column(cell);
        int row = cells_.row(cell);
        const auto exit_delay = [&](double position, double velocity, int index) {
            if (velocity > 0.0 && index + 1 < cells_.side()) return ((index + 1) * cells_.cell_size() - position) / velocity;
            if (velocity < 0.0 && index > 0) return (index * cells_.cell_size() - position) / velocity;
            return never;
        };
        const double along_x = exit_delay(p.position.x(), p.velocity.x(), column);
        const double along_y = exit_delay(p.position.y(), p.velocity.y(), row);
        const double delay = std::min(along_x, along_y);
        if (delay == never) return;
        if (along_x <= along_y) {
            column += p.velocity.x() > 0.0 ? 1 : -1;
        } else {
            row += p.velocity.y() > 0.0 ? 1 : -1;
        }
        push(EventKind::cell_crossing, stamp_[i] + delay, i, cells_.cell_at(column, row));
    }

    // Everything about a particle whose velocity has just changed.
    void predict_after_collision(std::uint32_t i) {
        predict_wall(i);
        predict_crossing(i);
        for_each_neighbour(i, [&](std::uint32_t j) { predict_pair(i, j); });
    }

    void note_event(std::uint32_t i) {
        const std::int64_t step = steps_done_;
        if (last_event_step_[i] != step) {
            last_event_step_[i] = step;
        } else if (last_repeat_step_[i] != step) {
            last_repeat_step_[i] = step;
            ++several_events_;
        }
    }

    void collide_with_wall(std::uint32_t i) {
        Particle& p = particles_[i];
        // The same start state as the prediction, so the same hit.
        const WallHit hit = time_to_wall(p.position, p.velocity, box_);
        bounce_off_wall(p, hit, box_);
        stamp_[i] = now_;
        ++last_step_.wall_collisions;
        note_event(i);
        predict_after_collision(i);
    }

    void collide_pair(std::uint32_t i, std::uint32_t j) {
        Particle& a = particles_[i];
        Particle& b = particles_[j];
        a.position = position_at(i, now_);
        b.position = position_at(j, now_);
        clamp_into_box(a.position, box_);
        clamp_into_box(b.position, box_);
        stamp_[i] = now_;
        stamp_[j] = now_;
        exchange_normal_velocities(a.position, b.position, a.velocity, b.velocity);
        ++a.particle_collisions;
        ++b.particle_collisions;
        ++last_step_.particle_collisions;
        note_event(i);
        note_event(j);
        // j's old wall event is stale, so j's new one must be known before i
        // predicts its pairs (the pruning reads it).
        predict_wall(j);
        predict_after_collision(i);
        predict_crossing(j);
        for_each_neighbour(j, [&](std::uint32_t k) {
            if (k != i) predict_pair(j, k);
        });
    }

    // Only the cells that have just become neighbours need new predictions.
    void cross_cell(std::uint32_t i, std::uint32_t cell) {
        const std::uint32_t old_cell = cells_.cell_of_particle(i);
        cells_.move(i, cell);
        const int column = cells_.column(cell);
        const int row = cells_.row(cell);
        const int step_x = column - cells_.column(old_cell);
        const int step_y = row - cells_.row(old_cell);
        for (int k = -1; k <= 1; ++k) {
            const int new_column = step_x != 0 ? column + step_x : column + k;
            const int new_row = step_x != 0 ? row + k : row + step_y;
            cells_.for_each_in(new_column, new_row, [&](std::uint32_t j) {
                if (j != i) predict_pair(i, j);
            });
        }
        predict_crossing(i);
    }

    void take_snapshot() {
        for (std::uint32_t i = 0; i < count(); ++i) {
            Particle& out = snapshot_[i];
            out = particles_[i];
            out.position = position_at(i, now_);
            clamp_into_box(out.position, box_);
        }
    }

    SimParams params_;
    Box box_;
    std::vector<Particle> particles_;  // each at its own stamp_
    CellList cells_;
    std::vector<double> stamp_;
    std::vector<double> wall_time_;  // absolute time of the particle's next wall event
    std::vector<std::int64_t> last_event_step_;
    std::vector<std::int64_t> last_repeat_step_;
    std::vector<Particle> snapshot_;  // the state at the last whole step
    EventQueue queue_;
    double now_ = 0.0;
    std::int64_t steps_done_ = 0;
    StepCounts last_step_;
    StepCounts totals_;
    std::uint64_t several_events_ = 0;
};

namespace {

std::vector<Particle> checked(const SimParams& params, std::vector<Particle> particles) {
    require_valid_scene("particlesim::ExactSimulation", params, particles);
    return particles;
}

}  // namespace

ExactSimulation::ExactSimulation(const SimParams& params, std::vector<Particle> particles, const ExactOptions& options) {
    if (options.cells_per_side < 0) throw std::invalid_argument("particlesim::ExactSimulation: cells_per_side must be >= 0");
    engine_ = std::make_unique<Engine>(params, checked(params, std::move(particles)), options);
}

ExactSimulation::~ExactSimulation() = default;
ExactSimulation::ExactSimulation(ExactSimulation&&) noexcept = default;
ExactSimulation& ExactSimulation::operator=(ExactSimulation&&) noexcept = default;

void ExactSimulation::step() { engine_->step(); }
std::span<const Particle> ExactSimulation::particles() const { return engine_->snapshot(); }
std::int64_t ExactSimulation::steps_done() const { return engine_->steps_done(); }
const StepCounts& ExactSimulation::last_step() const { return engine_->last_step(); }
const StepCounts& ExactSimulation::totals() const { return engine_->totals(); }
std::uint64_t ExactSimulation::last_step_particles_with_several_events() const { return engine_->several_events(); }
int ExactSimulation::cells_per_side() const { return engine_->cells_per_side(); }

double estimated_events_per_step(const SimParams& params, std::span<const Particle> particles) {
    double speed_sum = 0.0;  // sum of |vx| + |vy|
    for (const Particle& p : particles) speed_sum += std::abs(p.velocity.x()) + std::abs(p.velocity.y());
    if (speed_sum == 0.0) return 0.0;
    const double span = params.upper() - params.lower();
    if (!(span > 0.0)) return never;  // a moving disk that fills the box bounces forever
    const double walls = speed_sum / span;
    // Ideal gas: collision length 4r per unit path, density N / L^2,
    // relative speeds about sqrt(2) times the speeds.
    const double density = static_cast<double>(particles.size()) / (params.box_size * params.box_size);
    const double pairs = 0.5 * speed_sum * 4.0 * params.radius * density * std::sqrt(2.0);
    return walls + pairs;
}

}  // namespace particlesim
