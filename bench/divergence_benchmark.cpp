// Two correct programs against each other: the library and the textbook
// implementation of tests/support (unit normal, B^2 - 4AC) run the same
// scenes from the same exact start, and the largest distance between the
// same particle in the two is printed after every step. It grows by chaos
// from the last bit to the size of the box: why simcheck judges each step
// from the program's own previous one (docs/checking.md).

#include "benchmarks.hpp"

#include "particlesim/particlesim.hpp"
#include "textbook_rules.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace particlesim;

namespace bench {

namespace {

void divergence_rows(const char* name, const Scene& scene) {
    SteppedSimulation ours(scene.world, scene.particles);
    std::vector<textbook::Disk> disks;
    for (const Particle& p : scene.particles) {
        disks.push_back({p.position.x(), p.position.y(), p.velocity.x(), p.velocity.y()});
    }
    textbook::Simulator theirs(scene.world.box_size, scene.world.radius, disks, textbook::Mistake::none, 1);
    for (std::int64_t step = 1; step <= scene.steps; ++step) {
        ours.step();
        theirs.step();
        double largest = 0.0;
        std::vector<double> distances;
        for (std::size_t i = 0; i < scene.particles.size(); ++i) {
            const Vec2 a = ours.particles()[i].position;
            const textbook::Disk& b = theirs.disks()[i];
            distances.push_back(std::hypot(a.x() - b.x, a.y() - b.y));
            largest = std::max(largest, distances.back());
        }
        std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
        std::printf("%s,%zu,%g,%lld,%.3g,%.3g\n", name, scene.particles.size(), scene.world.box_size,
                    static_cast<long long>(step), largest, distances[distances.size() / 2]);
    }
}

}  // namespace

void divergence_benchmark(bool quick) {
    std::printf("scene,particles,box,step,largest_distance,median_distance\n");
    SceneFamilyOptions options;
    options.steps = quick ? 30 : 300;
    options.particles = 1000;
    divergence_rows("default", make_family_scene(SceneFamily::random, options));
    options.particles = 400;
    divergence_rows("gas 0.3", make_family_scene(SceneFamily::gas, options));
}

}  // namespace bench
