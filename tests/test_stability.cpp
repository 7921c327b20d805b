// Stability under stress (quick cases; the 1e6-step run is in the benchmark
// tree): adversarial scenes under both engines and several substeps, every
// step checked: no NaN, no escape, energy drift <= 1e-12, no hang (CTest's
// timeout).

#include "check.hpp"
#include "stress_scenes.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <cstdio>

using namespace particlesim;

namespace {

constexpr double max_drift = 1e-12;

void adversarial_scenes() {
    for (const NamedScene& scene : stress_scenes::all()) {
        for (const int substeps : {1, 4}) {
            for (const PairSearch search : {PairSearch::brute_force, PairSearch::grid}) {
                SteppedSimulation stepped(scene.world, scene.particles,
                                          {.pair_search = search, .threads = 2, .substeps = substeps});
                const double drift = stress_scenes::run_checked(stepped, scene.world, scene.steps);
                CHECK(drift <= max_drift);
                if (!(drift <= max_drift))
                    std::fprintf(stderr, "  %s (stepped, K = %d): drift %g\n", scene.name.c_str(), substeps, drift);
            }
        }
        // The exact engine takes what it can: no overlaps, a bounded number of events.
        const double events =
            estimated_events_per_step(scene.world, scene.particles) * static_cast<double>(scene.steps);
        if (scene.overlapping || events > 1e7) {
            std::printf("%s: exact engine skipped (%s)\n", scene.name.c_str(),
                        scene.overlapping ? "overlaps" : "too many events");
            continue;
        }
        ExactSimulation exact(scene.world, scene.particles);
        const double drift = stress_scenes::run_checked(exact, scene.world, scene.steps);
        CHECK(drift <= max_drift);
        if (!(drift <= max_drift)) std::fprintf(stderr, "  %s (exact): drift %g\n", scene.name.c_str(), drift);
        std::printf("%s: exact engine %llu particle and %llu wall collisions\n", scene.name.c_str(),
                    static_cast<unsigned long long>(exact.totals().particle_collisions),
                    static_cast<unsigned long long>(exact.totals().wall_collisions));
    }
}

void exact_engine_refuses_what_would_hang() {
    // Exactly the scenes skipped above: the guard sees them coming.
    for (const NamedScene& scene : stress_scenes::all()) {
        if (scene.name.rfind("tiny radius", 0) == 0 || scene.name.rfind("speeds far above", 0) == 0) {
            CHECK(estimated_events_per_step(scene.world, scene.particles) > 1e7);
        }
        if (scene.overlapping) {
            bool refused = false;
            try {
                ExactSimulation exact(scene.world, scene.particles);
            } catch (const OverlappingStart&) {
                refused = true;
            }
            CHECK(refused);
        }
    }
}

void crowded_box_quick() {
    const NamedScene scene = stress_scenes::crowded_box();
    SteppedSimulation stepped(scene.world, scene.particles, {.threads = 1});
    CHECK(stress_scenes::run_checked(stepped, scene.world, 20000) <= max_drift);
    ExactSimulation exact(scene.world, scene.particles);
    CHECK(stress_scenes::run_checked(exact, scene.world, 5000) <= max_drift);
    CHECK(exact.totals().particle_collisions > 100000);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_stability",
                      {{"adversarial scenes", adversarial_scenes},
                       {"exact engine refuses what would hang", exact_engine_refuses_what_would_hang},
                       {"crowded box quick", crowded_box_quick}});
}
