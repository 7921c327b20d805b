#include "particlesim/simulation.hpp"

#include "particlesim/brute_force_search.hpp"
#include "particlesim/grid_search.hpp"
#include "particlesim/step_pipeline.hpp"
#include "scene_checks.hpp"

#include <omp.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace particlesim {

namespace {

// Below this many particles the brute-force search is the faster one.
constexpr std::size_t brute_force_is_faster_below = 48;

// Automatic sorting by position: from this many particles on (below, they
// stay in the caches in any order), every this many steps (particles fast
// enough to scramble the order in fewer steps gain nothing from it, and lose
// one pass over the particles in this many steps).
constexpr std::size_t sort_by_position_from = 65536;
constexpr int automatic_sort_every = 8;

}  // namespace

Simulation::Simulation(const SimParams& params, std::vector<Particle> particles, const SimOptions& options)
    : params_(params), box_(Box::of(params)), options_(options), particles_(std::move(particles)) {
    require_valid_scene("particlesim::Simulation", params_, particles_);
    if (options_.threads < 0) throw std::invalid_argument("particlesim::Simulation: threads must be >= 0");
    if (options_.grid_cells < 0) throw std::invalid_argument("particlesim::Simulation: grid_cells must be >= 0");
    if (options_.substeps < 1) throw std::invalid_argument("particlesim::Simulation: substeps must be >= 1");
    if (options_.sort_by_position_every < SimOptions::automatic_sorting) {
        throw std::invalid_argument("particlesim::Simulation: sort_by_position_every must be >= 0 (or automatic)");
    }
    sort_every_ = options_.sort_by_position_every;
    if (sort_every_ == SimOptions::automatic_sorting) {
        sort_every_ = particles_.size() >= sort_by_position_from ? automatic_sort_every : 0;
    }
    if (sort_every_ > 0) storage_order_.reserve(particles_.size());
    threads_ = options_.threads > 0 ? options_.threads : omp_get_max_threads();
    wall_time_.resize(particles_.size());
    collision_of_.resize(particles_.size());
    // Room for a busy step from the start, so that steps rarely need to grow it.
    const std::size_t count = particles_.size();
    candidates_.reserve(2 * count + 64);
    accepted_.reserve(count);
    thread_candidates_.resize(static_cast<std::size_t>(threads_));
    for (ThreadCandidates& thread : thread_candidates_) thread.found.reserve(count / static_cast<std::size_t>(threads_) + 64);
    grid_ = std::make_unique<GridSearch>();
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

void Simulation::find_pair_candidates(const PairSearchInput& input) {
    Broadphase search = options_.broadphase;
    if (options_.grid_cells > 0) search = Broadphase::grid;
    if (search == Broadphase::automatic) {
        search = particles_.size() < brute_force_is_faster_below ? Broadphase::brute : Broadphase::grid;
    }
    last_broadphase_ = search;
    if (search == Broadphase::brute) {
        find_pairs_brute_force(input, thread_candidates_);
    } else {
        grid_->find_pairs(input, options_.grid_cells, thread_candidates_);
    }
}

std::span<const Particle> Simulation::particles() const {
    storage_order_.restore_user_order(particles_);
    return particles_;
}

void Simulation::step() {
    last_step_ = {};
    if (sort_every_ > 0 && (storage_order_.is_user_order() || steps_done_ % sort_every_ == 0)) {
        storage_order_.sort_by_position(particles_, box_);
    }
    // 1.0 / 1 is exactly 1.0: one substep is the plain step rules, bit for bit.
    const double duration = 1.0 / options_.substeps;
    for (int micro = 0; micro < options_.substeps; ++micro) micro_step(duration);
    totals_ += last_step_;
    ++steps_done_;
}

void Simulation::micro_step(double duration) {
    candidates_.clear();
    for (ThreadCandidates& thread : thread_candidates_) {
        thread.found.clear();
        thread.pair_tests = 0;
    }
    detect_wall_candidates(particles_, box_, duration, wall_time_, candidates_, threads_);
    find_pair_candidates({particles_, wall_time_, box_, duration});
    order_candidates(candidates_, thread_candidates_, merge_scratch_, storage_order_.user_index(),
                     storage_order_.stored_index(), threads_);
    select_collisions(candidates_, collision_of_, accepted_);
    resolve_collisions(particles_, collision_of_, accepted_, box_, duration, threads_);
    advance_free_particles(particles_, collision_of_, box_, duration, threads_);

    for (const ThreadCandidates& thread : thread_candidates_) last_step_.pair_tests += thread.pair_tests;
    last_step_.candidates += candidates_.size();
    for (const Collision& c : accepted_) {
        if (c.kind == CollisionKind::pair) {
            ++last_step_.particle_collisions;
        } else {
            ++last_step_.wall_collisions;
        }
    }
}

}  // namespace particlesim
