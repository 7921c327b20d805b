// Every parallel stage of a step on two threads against one: the grid search
// with a slice per thread (also deciding collisions in stages as the slices
// are searched) and with one slice shared, the paths search, the
// brute force, the selection, the resolution, the free flight and the storage
// sort, on scenes just large enough for each to share its work. The final
// states must be the same bits. Small on purpose: the suite also runs it
// under ThreadSanitizer (scripts/tsan-parallel.sh), which checks that no two
// threads of a stage touch the same memory without order.

#include "check.hpp"
#include "state_hash.hpp"

#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include "parallel/parallel.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

struct StageScene {
    std::string name;
    World world;
    std::size_t count;
    std::int64_t steps;
    SteppedOptions options;  // threads set below
    std::optional<SpeedRange> speeds;
    std::size_t piled = 0;  // of the particles, moved onto one point (within 1e-6)
};

std::uint64_t final_hash(const StageScene& scene, const std::vector<Particle>& start, int threads) {
    SteppedOptions options = scene.options;
    options.threads = threads;
    SteppedSimulation simulation(scene.world, start, options);
    run(simulation, scene.steps);
    return state_hash::hash(simulation.particles());
}

void two_threads_give_one_threads_bits() {
    // Area fraction 0.3, speeds 0.1 to 1 r a step: thousands of collisions
    // and candidates a step, so the selection's passes are shared too.
    const SpeedRange slow{0.1, 1.0};
    const std::vector<StageScene> scenes{
        {"grid, one slice shared", World{306.0, 1.0}, 9000, 4, {.pair_search = PairSearch::grid}, slow},
        {"grid, one slice shared, storage sorted every step",
         World{720.0, 1.0},
         50000,
         2,
         {.pair_search = PairSearch::grid, .sort_by_position_every = 1},
         slow},
        // The rules' speeds in a sparse box: 6 slices, taken by the threads
        // as they come free, with the selection run in stages between them
        // by whichever thread finishes one.
        {"grid, slices decided in stages",
         World{20000.0, 1.0},
         4000,
         3,
         {.pair_search = PairSearch::grid},
         std::nullopt},
        // The same with 300 disks piled on one point: more candidates at
        // t = 0 than the search keeps, so the first stage decides those
        // pairs from the disks while the other thread searches.
        {"grid, slices decided in stages, a pile",
         World{20000.0, 1.0},
         4000,
         3,
         {.pair_search = PairSearch::grid},
         std::nullopt,
         300},
        // The rules' density and speeds from 50 000 disks: each slice shared
        // by the threads, its scans testing lines, its box records turned
        // into rows in blocks on both threads.
        {"grid, shared slices with lines",
         World{20000.0 * std::sqrt(65.536), 1.0},
         65536,
         2,
         {.pair_search = PairSearch::grid},
         SpeedRange{2500.0, 5000.0}},
        {"paths search", World{20000.0, 1.0}, 6000, 6, {.pair_search = PairSearch::paths}, std::nullopt},
        {"brute force", World{250.0, 1.0}, 3000, 2, {.pair_search = PairSearch::brute_force}, slow},
    };
    for (const StageScene& scene : scenes) {
        check::Context context(scene.name);
        RandomSceneOptions random{.seed = 5};
        random.speeds = scene.speeds;
        std::vector<Particle> start = make_random_particles(scene.count, scene.world, random);
        for (std::size_t k = 0; k < scene.piled; ++k) {
            const double offset = 1e-6 * std::sin(static_cast<double>(k));
            start[k].position = Vec2(10000.0 + offset, 10000.0 - offset);
        }
        const std::uint64_t regions_before = parallel_regions_opened();
        CHECK_EQ(final_hash(scene, start, 2), final_hash(scene, start, 1));
        CHECK(parallel_regions_opened() > regions_before);  // each scene shares some stage
    }
}

// Below a few thousand particles no stage pays for a second thread, and two
// threads do one thread's work: the gas at area fraction 0.3 up to 4096
// disks, and the default scene's density and speeds (the paths search) up
// to 4096, whose first step tests all N^2 / 2 pairs of lines. From 8192 the
// gas shares its search.
void small_scenes_open_no_region() {
    const SpeedRange slow{0.1, 1.0};
    for (const std::size_t count : {std::size_t{1024}, std::size_t{4096}, std::size_t{8192}}) {
        const double n = static_cast<double>(count);
        const StageScene gas{"gas", World{std::sqrt(n * std::numbers::pi / 0.3), 1.0}, count, 4, {}, slow};
        const StageScene sparse{"default density",         World{20000.0 * std::sqrt(n / 1000.0), 1.0}, count, 4, {},
                                SpeedRange{2500.0, 5000.0}};
        for (const StageScene& scene : {gas, sparse}) {
            check::Context context(scene.name, ", ", count, " disks");
            RandomSceneOptions random{.seed = 5};
            random.speeds = scene.speeds;
            const std::vector<Particle> start = make_random_particles(scene.count, scene.world, random);
            const std::uint64_t regions_before = parallel_regions_opened();
            final_hash(scene, start, 2);
            const bool shared = parallel_regions_opened() > regions_before;
            CHECK_EQ(shared, count >= 8192);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_parallel_stages",
                      {{"two threads give one thread's bits", two_threads_give_one_threads_bits},
                       {"small scenes open no region", small_scenes_open_no_region}});
}
