#include "particlesim/stepped_simulation.hpp"
#include "particlesim/saved_state.hpp"

#include "core/assert.hpp"
#include "core/box.hpp"
#include "core/collision.hpp"
#include "input/scene_checks.hpp"
#include "input/stepped_options_check.hpp"
#include "parallel/parallel.hpp"
#include "parallel/run_queue_wait.hpp"
#include "particlesim/exact_simulation.hpp"
#include "search/brute_force_search.hpp"
#include "search/grid_search.hpp"
#include "search/pair_search.hpp"
#include "search/path_search.hpp"
#include "stepped/early_selection.hpp"
#include "stepped/search_choice.hpp"
#include "stepped/step_pipeline.hpp"
#include "stepped/stepped_state.hpp"
#include "stepped/stepped_tuning.hpp"
#include "stepped/storage_order.hpp"
#include "stepped/thread_choice.hpp"

#include <chrono>

namespace particlesim {

namespace {

using namespace stepped_tuning;

const SteppedOptions& checked(const SteppedOptions& options) {
    require_valid_stepped_options(options);
    return options;
}

}  // namespace

// The particles and every buffer the step pipeline reuses, sized once so that
// a step allocates nothing.
class SteppedSimulation::Implementation {
public:
    Implementation(const World& world, std::vector<Particle> particles, const SteppedOptions& options)
        : world_(world), box_(Box::of(world)), options_(checked(options)), particles_(std::move(particles)) {
        require_valid_scene("particlesim::SteppedSimulation", world_, particles_);
        const std::size_t count = particles_.size();
        threads_ = options_.threads.value_or(default_thread_count());
        thread_choice_ =
            ThreadChoice(threads_, options_.threads                   ? ThreadPolicy::all
                                   : count <= threads_by_trials_up_to ? ThreadPolicy::trials
                                                                      : ThreadPolicy::trials_when_contended);
        search_ = options_.pair_search;
        if (search_ == PairSearch::automatic) search_ = automatic_search(world_, particles_, options_.substeps);
        paths_watch_limit_ = options_.pair_search == PairSearch::automatic
                                 ? paths_watches_per_particle_chosen * count + paths_watches_floor_chosen
                                 : paths_watches_per_particle_asked * count + paths_watches_floor_asked;
        const bool threads_share_grid = search_ == PairSearch::grid && threads_ >= 2;
        const bool sorted =
            count >= sort_by_position_from || (threads_share_grid && count >= sort_by_position_shared_from);
        sort_every_ = options_.sort_by_position_every.value_or(sorted ? sort_every_steps : 0);
        // Where the sort pays for the threads alone, a state read back in the
        // user's order (print mode reads every step) waits for the next
        // sort: sorting every step would cost more than the threads gain.
        sort_after_reads_ = options_.sort_by_position_every.has_value() || count >= sort_by_position_from;
        if (sort_every_ > 0) storage_order_.reserve(count);
        particle_time_.resize(count);
        partner_.assign(count, no_collision);
        start_.resize(count);
        start_.with_motion = search_ == PairSearch::grid;
        selection_ = SelectionScratch(count);
        // Room for a busy step from the start, so that steps rarely need to grow it.
        candidates_.reserve(2 * count + 64);
        ready_.reserve(count + 64);
        // Reserved, not touched: only scenes whose grid runs stages fill it.
        if (search_ == PairSearch::grid) stage_time_.reserve(count);
        thread_candidates_.resize(static_cast<std::size_t>(threads_));
        for (ThreadCandidates& thread : thread_candidates_) {
            thread.found.reserve(count / static_cast<std::size_t>(threads_) + 64);
        }
    }

    // A saved run's step count and totals (its particles came to the constructor).
    void continue_from(std::int64_t steps_done, const StepCounts& totals) {
        steps_done_ = steps_done;
        totals_ = totals;
    }

    void step() {
        last_step_ = {};
        const bool read_back = sort_after_reads_ && storage_order_.is_user_order();
        if (sort_every_ > 0 && (read_back || steps_done_ % sort_every_ == 0)) {
            storage_order_.sort_by_position(particles_, box_);
            particles_reordered();
            PARTICLESIM_ASSERT(storage_order_.is_permutation(), "the storage order is a permutation of the particles");
        }
        // 1.0 / 1 is exactly 1.0: one substep is the plain step rules, bit for bit.
        const double duration = 1.0 / options_.substeps;
        const int threads = thread_choice_.threads();
        const auto begin = std::chrono::steady_clock::now();
        for (int micro = 0; micro < options_.substeps; ++micro) micro_step(duration, threads);
        thread_choice_.record(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
        if (thread_choice_.reading_due()) thread_choice_.read_waits(process_run_queue_wait_seconds());
        if constexpr (validating) require_inside_box();
        totals_ += last_step_;
        ++steps_done_;
    }

    // The particles in the user's order: puts the stored ones back in it
    // (the next step sorts them again), which changes no result.
    std::span<const Particle> put_in_user_order() {
        if (!storage_order_.is_user_order()) {
            storage_order_.restore_user_order(particles_);
            particles_reordered();
        }
        return particles_;
    }
    const World& world() const { return world_; }
    std::int64_t steps_done() const { return steps_done_; }
    const StepCounts& last_step() const { return last_step_; }
    const StepCounts& totals() const { return totals_; }
    PairSearch pair_search() const { return search_; }
    int threads() const { return threads_; }
    std::int64_t steps_on_one_thread() const { return thread_choice_.steps_on_one_thread(); }

private:
    // The paths search declined, its lines crowded together
    // (paths_watch_limit_): the grid, which finds the same candidates,
    // takes over for the rest of the run. Its steps read the blocks' motion.
    void hand_over_to_grid() {
        search_ = PairSearch::grid;
        start_.with_motion = true;
        stage_time_.reserve(particles_.size());
    }

    // What is kept by stored index and must be measured or made afresh once
    // the particles change places.
    void particles_reordered() {
        paths_.forget();
        start_.measured = false;
    }

    void require_inside_box() const {
        for (const Particle& p : particles_) {
            PARTICLESIM_ASSERT(p.position.x() >= box_.lower && p.position.x() <= box_.upper &&
                                   p.position.y() >= box_.lower && p.position.y() <= box_.upper,
                               "every particle is inside [r, L - r] after a step");
        }
    }

    // The step start the previous step's free flight measured equals one measured afresh.
    void require_measured_start_is_current(double duration, int threads) {
        std::vector<double>& wall_time = validation_.wall_time;
        StepStart& fresh = validation_.start;
        wall_time.resize(particles_.size());
        fresh.with_motion = start_.with_motion;
        fresh.resize(particles_.size());
        measure_step_start(particles_, box_, duration, wall_time, fresh, threads);
        PARTICLESIM_ASSERT(std::equal(wall_time.begin(), wall_time.end(), particle_time_.begin()),
                           "the measured wall times are those of the particles as they are");
        for (std::size_t b = 0; b < fresh.blocks.size(); ++b) {
            const BlockStart& now = fresh.blocks[b];
            const BlockStart& kept = start_.blocks[b];
            PARTICLESIM_ASSERT(now.wall_candidates == kept.wall_candidates &&
                                   now.motion.present == kept.motion.present &&
                                   (!start_.with_motion || (now.motion.length_sum == kept.motion.length_sum &&
                                                            now.motion.max_speed == kept.motion.max_speed)),
                               "the measured blocks are those of the particles as they are");
        }
    }

    void micro_step(double duration, int threads) {
        candidates_.clear();
        for (ThreadCandidates& thread : thread_candidates_) {
            thread.found.clear();
            thread.pair_tests = 0;
        }
        immediate_.reset(immediate_candidates_per_particle * particles_.size() + immediate_candidates_floor);
        const std::span<ThreadCandidates> found =
            std::span(thread_candidates_).first(static_cast<std::size_t>(threads));
        // particle_time_ holds each particle's first wall time up to the search ...
        const std::span<double> wall_time = particle_time_;
        if (!start_.measured) {
            measure_step_start(particles_, box_, duration, wall_time, start_, threads);
        } else if constexpr (validating) {
            require_measured_start_is_current(duration, threads);
        }
        gather_wall_candidates(wall_time, duration, start_, candidates_, threads);
        const PairSearchInput input{
            particles_,
            wall_time,
            box_,
            duration,
            start_.with_motion ? std::span<const BlockStart>(start_.blocks) : std::span<const BlockStart>(),
            0.0,
            &immediate_};
        // ... then, from the selection on (which the grid search may run in
        // stages between its slices, keeping their times aside until it is
        // over), the time of its accepted collision ...
        const std::span<double> collision_time = particle_time_;
        const CandidateOrder order(storage_order_.user_index());
        EarlySelection selection(input, candidates_, ready_, order, partner_, collision_time, stage_time_, selection_,
                                 threads);
        if (search_ == PairSearch::brute_force) {
            find_pairs_brute_force(input, found);
        } else if (search_ == PairSearch::paths && !paths_.find_pairs(input, found, paths_watch_limit_)) {
            hand_over_to_grid();  // this micro-step too
        }
        if (search_ == PairSearch::grid) grid_.find_pairs(input, options_.grid_cells, found, &selection);
        const StepCounts accepted = selection.decide_rest(found);
        resolve_collisions(particles_, partner_, collision_time, accepted, box_, duration, threads);
        // ... and the next step's first wall time again, measured as the free flight moves the particles.
        advance_free_particles(particles_, partner_, box_, duration, particle_time_, start_, threads);

        for (const ThreadCandidates& thread : thread_candidates_) last_step_.pair_tests += thread.pair_tests;
        last_step_.particle_collisions += accepted.particle_collisions;
        last_step_.wall_collisions += accepted.wall_collisions;
    }

    World world_;
    Box box_;
    SteppedOptions options_;
    PairSearch search_ = PairSearch::grid;  // never automatic
    int threads_ = 1;                       // the most a step uses
    ThreadChoice thread_choice_{1, ThreadPolicy::all};
    int sort_every_ = 0;             // steps; 0: never
    bool sort_after_reads_ = false;  // sort again at the first step after particles() (else on schedule only)
    std::vector<Particle> particles_;
    StorageOrder storage_order_;

    // By particle, one array for two times in turn (8 bytes a particle
    // fewer): up to the search, its first wall time; from the selection on,
    // the time of its accepted collision. micro_step() names each use.
    std::vector<double> particle_time_;
    StepStart start_;  // the wall times' blocks, measured by the previous step's advance when it could
    std::vector<std::uint32_t> partner_;  // by particle: its partner, no_collision or wall_collision
    SelectionScratch selection_;
    std::vector<Collision> candidates_;
    std::vector<Collision> ready_;    // EarlySelection's
    std::vector<double> stage_time_;  // EarlySelection's: sized on its first stage
    std::vector<ThreadCandidates> thread_candidates_;
    ImmediateCandidateBudget immediate_;
    GridSearch grid_;
    PathSearch paths_;
    std::size_t paths_watch_limit_ = 0;  // the most pairs it may watch (stepped_tuning's paths_watches_*)
    struct {                             // scratch of the invariant checks (PARTICLESIM_VALIDATE), reused
        std::vector<double> wall_time;
        StepStart start;
    } validation_;

    std::int64_t steps_done_ = 0;
    StepCounts last_step_;
    StepCounts totals_;
};

SteppedSimulation::SteppedSimulation(const World& world, std::vector<Particle> particles, const SteppedOptions& options)
    : engine_(std::make_unique<Implementation>(world, std::move(particles), options)) {}

SteppedSimulation SteppedSimulation::restore(const World& world, std::istream& saved, const SteppedOptions& options) {
    SteppedState state =
        read_stepped_state(saved, "particlesim::SteppedSimulation::restore: the saved state is damaged");
    SteppedSimulation simulation(world, std::move(state.particles), options);
    simulation.engine_->continue_from(state.steps_done, state.totals);
    return simulation;
}

void SteppedSimulation::save(std::ostream& out) const {
    const std::span<const Particle> particles = this->particles();
    write_stepped_state_head(out, particles.size(), steps_done(), totals());
    for (const Particle& p : particles) write_stepped_state_particle(out, p);
}

SteppedSimulation::~SteppedSimulation() = default;
SteppedSimulation::SteppedSimulation(SteppedSimulation&&) noexcept = default;
SteppedSimulation& SteppedSimulation::operator=(SteppedSimulation&&) noexcept = default;

void SteppedSimulation::step() { engine_->step(); }
// Logically const: putting the stored particles back in the user's order
// changes no result (and the pointer does not make the engine const).
std::span<const Particle> SteppedSimulation::particles() const { return engine_->put_in_user_order(); }
const World& SteppedSimulation::world() const { return engine_->world(); }
std::int64_t SteppedSimulation::steps_done() const { return engine_->steps_done(); }
const StepCounts& SteppedSimulation::last_step() const { return engine_->last_step(); }
const StepCounts& SteppedSimulation::totals() const { return engine_->totals(); }
PairSearch SteppedSimulation::pair_search() const { return engine_->pair_search(); }
int SteppedSimulation::threads() const { return engine_->threads(); }
std::int64_t SteppedSimulation::steps_on_one_thread() const { return engine_->steps_on_one_thread(); }

const char* pair_search_name(PairSearch search) {
    switch (search) {
    case PairSearch::automatic: return "auto";
    case PairSearch::brute_force: return "brute";
    case PairSearch::grid: return "grid";
    case PairSearch::paths: return "paths";
    }
    return "?";
}

}  // namespace particlesim
