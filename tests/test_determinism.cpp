// In the spirit of Box2D's determinism test: one hash of the final state, the
// same for every thread count and every candidate search.

#include "check.hpp"
#include "state_hash.hpp"

#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <cstdio>

using namespace particlesim;

namespace {

std::uint64_t final_hash(const World& params, std::int64_t steps, const std::vector<Particle>& particles,
                         const SteppedOptions& options) {
    SteppedSimulation sim(params, particles, options);
    particlesim::run(sim, steps);
    return state_hash::hash(sim.particles());
}

// `forced_grid`: a G x G grid to impose besides the automatic one.
void same_hash_everywhere(const char* name, const World& params, std::int64_t steps,
                          const std::vector<Particle>& particles, int forced_grid, bool with_brute, int substeps = 1,
                          bool with_paths = false) {
    const std::uint64_t reference =
        final_hash(params, steps, particles, {.pair_search = PairSearch::grid, .threads = 1, .substeps = substeps});
    int differing = 0;
    for (const int threads : {1, 2, 3, 4, 8}) {
        differing +=
            final_hash(params, steps, particles,
                       {.pair_search = PairSearch::grid, .threads = threads, .substeps = substeps}) != reference;
        differing += final_hash(params, steps, particles, {.threads = threads, .substeps = substeps}) != reference;
        differing += final_hash(params, steps, particles,
                                {.pair_search = PairSearch::grid,
                                 .grid_cells = forced_grid,
                                 .threads = threads,
                                 .substeps = substeps}) != reference;
        // Stored by position every step, and never (automatic: every 8 steps from 65536 particles on).
        differing += final_hash(params, steps, particles,
                                {.pair_search = PairSearch::grid,
                                 .threads = threads,
                                 .substeps = substeps,
                                 .sort_by_position_every = 1}) != reference;
        differing += final_hash(params, steps, particles,
                                {.pair_search = PairSearch::grid,
                                 .threads = threads,
                                 .substeps = substeps,
                                 .sort_by_position_every = 0}) != reference;
        if (with_paths) {
            differing +=
                final_hash(params, steps, particles,
                           {.pair_search = PairSearch::paths, .threads = threads, .substeps = substeps}) != reference;
        }
        if (with_brute)
            differing +=
                final_hash(params, steps, particles,
                           {.pair_search = PairSearch::brute_force, .threads = threads, .substeps = substeps}) !=
                reference;
    }
    std::printf("%s, %d substep(s): final state hash %016llx\n", name, substeps,
                static_cast<unsigned long long>(reference));
    CHECK_EQ(differing, 0);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(
        argc, argv, "test_determinism",
        {{"same hash for every search and thread count", [] {
              // The paper's scene (fast particles, sparse box), 200 steps.
              const World paper{20000.0, 1.0};
              same_hash_everywhere("default scene", paper, 200, make_random_particles(1000, paper), 4, true, 1, true);
              // Enough new lines a step (about 5 M line tests) for the paths search to share them between threads.
              same_hash_everywhere("4000 particles", paper, 30, make_random_particles(4000, paper), 8, false, 1, true);
              // Substeps: micro-steps of 1/K under the same rules, the same everywhere too.
              const World short_paper{20000.0, 1.0};
              for (const int substeps : {2, 3, 8}) {
                  same_hash_everywhere("default scene", short_paper, 20, make_random_particles(1000, short_paper), 4,
                                       true, substeps);
              }
              const std::vector<Particle> start = make_random_particles(1000, short_paper);
              CHECK(final_hash(short_paper, 20, start, {.threads = 1}) !=
                    final_hash(short_paper, 20, start, {.threads = 1, .substeps = 2}));
              // A crowded box of slow particles (area fraction 0.3): many collisions.
              const World crowded{160.0, 1.0};
              same_hash_everywhere("crowded box", crowded, 100,
                                   make_random_particles(2400, crowded, {5, SpeedRange{0.1, 1.0}}), 16, false);
              // Large enough for the grid to share each slice between threads, and for
              // the automatic storage order by position.
              const World large{1100.0, 1.0};
              same_hash_everywhere("70000 particles", large, 10,
                                   make_random_particles(70000, large, {9, SpeedRange{0.1, 1.0}}), 256, false);
              // The same with one particle in 500 crossing the box in a step: paths
              // too long for any cell, collected by each thread that bins a share.
              std::vector<Particle> with_fast = make_random_particles(70000, large, {9, SpeedRange{0.1, 1.0}});
              for (std::size_t i = 0; i < with_fast.size(); i += 500) with_fast[i].velocity *= 1500.0;
              same_hash_everywhere("70000 particles, some crossing the box", large, 3, with_fast, 256, false);
          }}});
}
