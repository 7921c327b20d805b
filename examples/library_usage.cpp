// Using particlesim from C++: a random scene, both engines run side by side
// with an observer, and the final state written in simcli's output format.
#include <particlesim/particlesim.hpp>

#include <cstdio>

int main() {
    using namespace particlesim;
    const World world{20000.0, 1.0};  // L, r
    const std::vector<Particle> start = make_random_particles(1000, world, {.seed = 42});

    // The output is the same for any number of threads and any pair search.
    SteppedSimulation stepped(world, start, {.threads = 2});
    std::uint64_t wall_hits = 0;
    run(stepped, 100, [&](std::int64_t /*step*/, std::span<const Particle> /*particles*/) {
        wall_hits += stepped.last_step().wall_collisions;
    });
    std::printf("%llu wall and %llu particle collisions in %lld steps\n", static_cast<unsigned long long>(wall_hits),
                static_cast<unsigned long long>(stepped.totals().particle_collisions),
                static_cast<long long>(stepped.steps_done()));

    // The same start under real hard-disk dynamics, and how far apart the two are.
    ExactSimulation exact(world, start);
    run(exact, 100);
    std::printf("exact engine: %llu particle collisions\n",
                static_cast<unsigned long long>(exact.totals().particle_collisions));

    StateWriter writer(stdout);
    writer.write_final(stepped.steps_done(), stepped.particles().first(3));
    writer.flush();
}
