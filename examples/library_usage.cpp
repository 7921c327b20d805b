// Using particlesim from C++: a random scene, a run with an observer, and
// the final state written in simcli's output format.
#include <particlesim/particlesim.hpp>

#include <cstdio>

int main() {
    using namespace particlesim;
    const World params{20000.0, 1.0};  // L, r, S, mode
    RandomSceneOptions scene;
    scene.seed = 42;
    SteppedOptions options;
    options.threads = 2;  // the output is the same for any number
    SteppedSimulation sim(params, make_random_particles(1000, params, scene), options);

    std::uint64_t wall_hits = 0;
    particlesim::run(sim, 100, [&](std::int64_t /*step*/, std::span<const Particle>) {
        wall_hits += sim.last_step().wall_collisions;
    });

    std::printf("%llu wall and %llu particle collisions in %lld steps\n",
                static_cast<unsigned long long>(wall_hits),
                static_cast<unsigned long long>(sim.totals().particle_collisions),
                static_cast<long long>(sim.steps_done()));
    StateWriter writer(stdout);
    writer.write_final(sim.steps_done(), sim.particles().first(3));
    writer.flush();
}
