// The distributed engine against the one-process engine, bit for bit after
// every step, run under mpirun with 1, 2, 3, 4, 5 and 8 ranks (one CTest
// test each): random scenes of every regime, and scenes made to break a
// decomposition (a cradle over every cut, head-on pairs and exact ties at
// any cut, disks crossing several strips a step, empty strips, fewer disks
// than ranks, no disks), substeps, two threads a rank, cuts that move, and
// a state saved on 3 ranks continued on all of them. Rank 0 compares; every
// rank runs every case in the same order (the engine's calls are collective).

#include "check.hpp"
#include "random_scenes.hpp"

#include "particlesim/distributed_simulation.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <mpi.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

int rank_here() {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
}

int ranks_here() {
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    return ranks;
}

bool same_bits(const Particle& a, const Particle& b) {
    const double da[4] = {a.position.x(), a.position.y(), a.velocity.x(), a.velocity.y()};
    const double db[4] = {b.position.x(), b.position.y(), b.velocity.x(), b.velocity.y()};
    return std::memcmp(da, db, sizeof da) == 0 && a.particle_collisions == b.particle_collisions &&
           a.wall_collisions == b.wall_collisions;
}

std::vector<Particle> gathered(const DistributedSimulation& engine, std::size_t part_size) {
    std::vector<Particle> all;
    engine.gather(
        [&](std::size_t first, std::span<const Particle> part) {
            CHECK_EQ(first, all.size());
            all.insert(all.end(), part.begin(), part.end());
        },
        part_size);
    return all;
}

// On rank 0: the first step and particle where the two runs differ, or -1.
struct Difference {
    std::int64_t step = -1;
    std::size_t particle = 0;
};

// Runs `scene` on every rank of `comm` and (on rank 0) in one process,
// comparing the particles and the counts after every step.
Difference compare_runs(const World& world, const std::vector<Particle>& particles, std::int64_t steps,
                        const SteppedOptions& options = {}) {
    const bool root = rank_here() == 0;
    DistributedSimulation distributed(MPI_COMM_WORLD, world, root ? particles : std::vector<Particle>{}, options);
    SteppedOptions one_process = options;
    one_process.threads = 1;
    std::optional<SteppedSimulation> reference;
    if (root) reference.emplace(world, particles, one_process);
    Difference difference;
    for (std::int64_t step = 1; step <= steps; ++step) {
        distributed.step();
        if (root) reference->step();
        // Small parts now and then: the gather's parts must join up.
        const std::vector<Particle> got = gathered(distributed, step % 3 == 0 ? 7 : std::size_t{1} << 16);
        if (!root || difference.step >= 0) continue;
        const std::span<const Particle> expected = reference->particles();
        if (got.size() != expected.size() ||
            distributed.totals().particle_collisions != reference->totals().particle_collisions ||
            distributed.totals().wall_collisions != reference->totals().wall_collisions) {
            difference = {step, got.size()};
            continue;
        }
        for (std::size_t i = 0; i < got.size(); ++i) {
            if (!same_bits(got[i], expected[i])) {
                difference = {step, i};
                break;
            }
        }
    }
    return difference;
}

void check_same(const std::string& name, const World& world, const std::vector<Particle>& particles, std::int64_t steps,
                const SteppedOptions& options = {}) {
    const check::Context context(name + " on " + std::to_string(ranks_here()) + " ranks");
    const Difference difference = compare_runs(world, particles, steps, options);
    CHECK_EQ(difference.step, std::int64_t{-1});
    if (difference.step >= 0 && rank_here() == 0) {
        std::fprintf(stderr, "    first difference: step %lld, particle %zu\n", static_cast<long long>(difference.step),
                     difference.particle);
    }
}

void random_scenes_of_every_regime() {
    // More ranks than this machine's cores wait on each other at every
    // exchange: fewer scenes there (still every regime: k mod 5).
    const bool oversubscribed = ranks_here() > 2;
    const std::uint64_t scenes = oversubscribed ? 5 : 40;
    for (std::uint64_t k = 0; k < scenes; ++k) {
        const NamedScene scene = random_scenes::make(k);
        check_same("random scene " + std::to_string(k), scene.world, scene.particles, scene.steps);
    }
    const std::uint64_t clustered = oversubscribed ? 3 : 6;
    for (std::uint64_t k = 0; k < clustered; ++k) {
        const NamedScene scene = random_scenes::make_clustered(k);
        check_same("clustered scene " + std::to_string(k), scene.world, scene.particles, scene.steps);
    }
}

// A row of touching disks across the whole box, the first one moving:
// the momentum runs along the row through every cut, one link a step.
void a_cradle_over_every_cut() {
    const World world{200.0, 1.0};
    std::vector<Particle> row;
    for (int k = 0; k < 99; ++k) {
        Particle p;
        p.position = Vec2(1.0 + 2.0 * k + 0.0001 * k, 100.0);
        row.push_back(p);
    }
    row.front().velocity = Vec2(1.5, 0.0);
    check_same("cradle", world, row, 120);
}

// Head-on pairs at every x, all meeting at the same instant (exact ties
// among pairs, and between pairs and walls), with third disks that tie
// with them; whatever the cuts, some pairs straddle them.
void head_on_pairs_and_ties_at_any_cut() {
    const World world{100.0, 1.0};
    std::vector<Particle> particles;
    for (int k = 0; k < 24; ++k) {
        const double x = 3.0 + 4.0 * k;
        for (const double y : {10.0, 30.0, 50.0}) {
            Particle a, b;
            a.position = Vec2(x - 1.5, y);
            a.velocity = Vec2(1.0, 0.0);
            b.position = Vec2(x + 1.5, y);
            b.velocity = Vec2(-1.0, 0.0);
            particles.push_back(a);
            particles.push_back(b);
            Particle c;  // from above, arriving at the same time as the pair meets
            c.position = Vec2(x, y + 3.0);
            c.velocity = Vec2(0.0, -1.0);
            particles.push_back(c);
        }
    }
    check_same("head-on pairs and ties", world, particles, 40);
}

// Disks many strips wide per step, in a small crowded box.
void disks_crossing_several_strips() {
    const World world{60.0, 1.0};
    std::vector<Particle> particles = make_random_particles(150, world, {7, SpeedRange{20.0, 180.0}});
    check_same("fast disks", world, particles, 30);
}

void empty_strips_and_few_disks() {
    const World world{400.0, 1.0};
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{7}}) {
        const std::vector<Particle> particles = make_random_particles(count, world, {count, SpeedRange{1.0, 50.0}});
        check_same(std::to_string(count) + " disks", world, particles, 25);
    }
    // Everything in one narrow column: most strips start empty.
    std::vector<Particle> column;
    for (int k = 0; k < 60; ++k) {
        Particle p;
        p.position = Vec2(200.0 + 0.5 * (k % 3), 5.0 + 6.0 * k);
        p.velocity = Vec2(k % 2 == 0 ? 3.0 : -2.5, 0.7 * (k % 5));
        column.push_back(p);
    }
    check_same("one column", world, column, 40);
}

void substeps_and_two_threads_a_rank() {
    const World world{120.0, 1.0};
    const std::vector<Particle> particles = make_random_particles(500, world, {11, SpeedRange{0.5, 6.0}});
    SteppedOptions substeps;
    substeps.substeps = 3;
    check_same("3 substeps", world, particles, 20, substeps);
    SteppedOptions threads;
    threads.threads = 2;
    check_same("two threads a rank", world, particles, 20, threads);
    SteppedOptions brute;
    brute.pair_search = PairSearch::brute_force;
    check_same("brute force", world, particles, 10, brute);
}

// Every disk drifts right: the cuts must follow, or one rank ends with all.
void cuts_follow_the_disks() {
    const World world{400.0, 1.0};
    std::vector<Particle> particles;
    for (int k = 0; k < 3000; ++k) {
        Particle p;
        p.position = Vec2(2.0 + (k % 60) * 2.2, 2.0 + (k / 60) * 7.0);
        p.velocity = Vec2(4.0, 0.01 * (k % 7) - 0.03);
        particles.push_back(p);
    }
    check_same("drifting right", world, particles, 60);
    const bool root = rank_here() == 0;
    DistributedSimulation engine(MPI_COMM_WORLD, world, root ? particles : std::vector<Particle>{});
    // By step 49 every disk has left the first cuts' strips behind (all of
    // them would be the last rank's); the cuts moved before that step.
    for (int step = 0; step < 49; ++step) engine.step();
    std::uint64_t most = engine.owned_count();
    MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
    const double crossing_in_a_step = 100.0;
    if (ranks_here() > 1) CHECK(static_cast<double>(most) <= 1.1 * 3000.0 / ranks_here() + 64.0 + crossing_in_a_step);
}

// Saved on the first three ranks (or fewer), continued on all of them and
// in one process: the same as one run.
void saved_on_three_ranks_continued_on_all() {
    const World world{150.0, 1.0};
    const std::vector<Particle> particles = make_random_particles(600, world, {5, SpeedRange{0.5, 8.0}});
    const int rank = rank_here();
    MPI_Comm first_three = MPI_COMM_NULL;
    MPI_Comm_split(MPI_COMM_WORLD, rank < 3 ? 0 : MPI_UNDEFINED, rank, &first_three);
    std::string saved;
    if (first_three != MPI_COMM_NULL) {
        DistributedSimulation part(first_three, world, rank == 0 ? particles : std::vector<Particle>{});
        for (int step = 0; step < 15; ++step) part.step();
        part.save([&](std::string_view text) { saved += text; });
        MPI_Comm_free(&first_three);
    }
    std::istringstream text(saved);
    DistributedSimulation continued =
        DistributedSimulation::restore(MPI_COMM_WORLD, world, rank == 0 ? &text : nullptr);
    for (int step = 0; step < 15; ++step) continued.step();
    const std::vector<Particle> got = gathered(continued, 1000);
    if (rank != 0) return;
    SteppedSimulation reference(world, particles);
    for (int step = 0; step < 30; ++step) reference.step();
    CHECK_EQ(continued.steps_done(), std::int64_t{30});
    CHECK_EQ(continued.totals().particle_collisions, reference.totals().particle_collisions);
    bool same = got.size() == reference.particles().size();
    for (std::size_t i = 0; same && i < got.size(); ++i) same = same_bits(got[i], reference.particles()[i]);
    CHECK(same);
    // The saved text is the one-process engine's.
    std::istringstream again(saved);
    SteppedSimulation restored = SteppedSimulation::restore(world, again);
    CHECK_EQ(restored.steps_done(), std::int64_t{15});
}

void a_bad_scene_is_refused_on_every_rank() {
    const World world{10.0, 1.0};
    Particle outside;
    outside.position = Vec2(0.5, 5.0);  // below r
    bool refused = false;
    try {
        DistributedSimulation engine(MPI_COMM_WORLD, world,
                                     rank_here() == 0 ? std::vector{outside} : std::vector<Particle>{});
    } catch (const std::invalid_argument&) {
        refused = true;
    }
    int all_refused = refused ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &all_refused, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    CHECK_EQ(all_refused, 1);
}

// What SteppedSimulation refuses in its options, on every rank, with its
// message; and options bad on one rank only still refuse on all, with that
// rank's message.
void bad_options_are_refused_on_every_rank() {
    const World world{10.0, 1.0};
    const auto refusal = [&](const SteppedOptions& options, bool restoring) {
        std::string message;
        try {
            const std::vector<Particle> none;
            if (restoring) {
                std::istringstream saved("stepped-engine-state 1 0 0 0 0 0 ");
                DistributedSimulation::restore(MPI_COMM_WORLD, world, rank_here() == 0 ? &saved : nullptr, options);
            } else {
                DistributedSimulation engine(MPI_COMM_WORLD, world, none, options);
            }
        } catch (const std::invalid_argument& e) {
            message = e.what();
        }
        int all_refused = message.empty() ? 0 : 1;
        MPI_Allreduce(MPI_IN_PLACE, &all_refused, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
        CHECK_EQ(all_refused, message.empty() ? 0 : 1);
        return message;
    };
    const auto stepped_refusal = [&](const SteppedOptions& options) {
        try {
            SteppedSimulation(world, {}, options);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::vector<SteppedOptions> bad{{.threads = 0},
                                          {.threads = -4},
                                          {.substeps = 0},
                                          {.sort_by_position_every = -1},
                                          {.pair_search = PairSearch::grid, .grid_cells = 0},
                                          {.pair_search = PairSearch::brute_force, .grid_cells = 3},
                                          {.pair_search = static_cast<PairSearch>(9)}};
    for (const SteppedOptions& options : bad) {
        for (const bool restoring : {false, true}) {
            const check::Context context("bad options #", &options - bad.data(), restoring ? ", restoring" : "");
            const std::string message = refusal(options, restoring);
            CHECK(!message.empty());
            CHECK_EQ(message, stepped_refusal(options));
        }
    }
    CHECK_EQ(refusal({}, false), "");
    CHECK_EQ(refusal({}, true), "");
    // Threads refused on the last rank only.
    const int ranks = [] {
        int count = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &count);
        return count;
    }();
    SteppedOptions on_last_rank;
    if (rank_here() == ranks - 1) on_last_rank.threads = 0;
    CHECK_EQ(refusal(on_last_rank, false), "particlesim::SteppedOptions: threads must be in [1, 1024], not 0");
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int status = check::run(argc, argv, "test_distributed_engine",
                            {{"random scenes of every regime", random_scenes_of_every_regime},
                             {"a cradle over every cut", a_cradle_over_every_cut},
                             {"head-on pairs and ties at any cut", head_on_pairs_and_ties_at_any_cut},
                             {"disks crossing several strips", disks_crossing_several_strips},
                             {"empty strips and few disks", empty_strips_and_few_disks},
                             {"substeps and two threads a rank", substeps_and_two_threads_a_rank},
                             {"cuts follow the disks", cuts_follow_the_disks},
                             {"saved on three ranks, continued on all", saved_on_three_ranks_continued_on_all},
                             {"a bad scene is refused on every rank", a_bad_scene_is_refused_on_every_rank},
                             {"bad options are refused on every rank", bad_options_are_refused_on_every_rank}});
    // Any rank's failure fails the test.
    MPI_Allreduce(MPI_IN_PLACE, &status, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    MPI_Finalize();
    return status;
}
