// The physics is scale-free, and so must the engines be across the accepted
// range (world.hpp, docs/accepted-range.md): every example and a set of random
// scenes, scaled by 2^k for k from the lowest to the highest the range
// allows, give the same counters and exactly the scaled states at every step,
// under both engines, every search, a forced grid, substeps and 1 or 2 threads.

#include "check.hpp"
#include "example_scenes.hpp"
#include "named_scene.hpp"
#include "random_scenes.hpp"
#include "scaled_by_power_of_two.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

std::vector<NamedScene> scenes() {
    std::vector<NamedScene> all;
    for (const auto& entry : std::filesystem::directory_iterator(PARTICLESIM_EXAMPLES_DIR)) {
        if (entry.path().extension() != ".in") continue;
        const Scene scene = example_scenes::load(entry.path().filename().string());
        if (scene.is_random()) continue;  // the default scene: 1000 steps of 1000 disks, covered by the random ones
        all.push_back(
            {entry.path().filename().string(), scene.world, std::min<std::int64_t>(scene.steps, 40), scene.particles});
    }
    for (std::uint64_t k = 0; k < 12; ++k) {
        NamedScene scene = random_scenes::make(k);
        all.push_back({"random " + std::to_string(k), scene.world, 20, std::move(scene.particles)});
    }
    // Sparse and fast: the grid cuts about 6 slices and decides collisions
    // between them (EarlySelection).
    const World sparse{5000.0, 3.0};
    all.push_back({"sparse, slices decided in stages", sparse, 5,
                   make_random_particles(1500, sparse, {7, SpeedRange{625.0, 2500.0}})});
    return all;
}

NamedScene scaled(NamedScene scene, int k) {
    scale_by_power_of_two(scene.world, scene.particles, k);
    return scene;
}

// The lowest and highest k that keep the scene inside the accepted range.
std::pair<int, int> scale_range(const NamedScene& scene) {
    double largest = scene.world.box_size;
    for (const Particle& p : scene.particles) {
        largest = std::max({largest, std::fabs(p.velocity.x()), std::fabs(p.velocity.y())});
    }
    const int low = static_cast<int>(std::ceil(std::log2(min_length / scene.world.radius)));
    const int high = static_cast<int>(std::floor(std::log2(max_magnitude / largest)));
    return {low, high};
}

using States = std::vector<std::vector<Particle>>;

struct Configuration {
    std::string name;
    std::function<States(const NamedScene&)> run;
};

template <typename E>
States states_of(E&& engine, std::int64_t steps) {
    States states;
    for (std::int64_t s = 0; s < steps; ++s) {
        engine.step();
        states.emplace_back(engine.particles().begin(), engine.particles().end());
    }
    return states;
}

std::vector<Configuration> configurations() {
    const auto stepped = [](SteppedOptions options) {
        return [options](const NamedScene& s) {
            return states_of(SteppedSimulation(s.world, s.particles, options), s.steps);
        };
    };
    return {
        {"brute force, 1 thread", stepped({.pair_search = PairSearch::brute_force, .threads = 1})},
        {"grid, 2 threads", stepped({.pair_search = PairSearch::grid, .threads = 2})},
        {"grid 4 x 4", stepped({.pair_search = PairSearch::grid, .grid_cells = 4, .threads = 1})},
        {"grid 16 x 16, sorted",
         stepped({.pair_search = PairSearch::grid, .grid_cells = 16, .threads = 2, .sort_by_position_every = 1})},
        {"substeps 3", stepped({.threads = 2, .substeps = 3})},
        {"exact", [](const NamedScene& s) { return states_of(ExactSimulation(s.world, s.particles), s.steps); }},
    };
}

bool exact_engine_takes(const NamedScene& scene) {
    if (estimated_events_per_step(scene.world, scene.particles) * static_cast<double>(scene.steps) > 1e5) return false;
    try {
        ExactSimulation engine(scene.world, scene.particles);
    } catch (const OverlappingStart&) {
        return false;
    }
    return true;
}

void scaled_scenes_give_scaled_states() {
    int compared = 0;
    for (const NamedScene& scene : scenes()) {
        const auto [low, high] = scale_range(scene);
        CHECK(low <= -150 && high >= 150);  // the range spans about 2^-199 .. 2^199 in L
        const std::vector<int> ks = check::sanitized
                                        ? std::vector<int>{low, 1, high}
                                        : std::vector<int>{low, low + 1, low / 2, -1, 1, high / 2, high - 1, high};
        const bool exact_ok = exact_engine_takes(scene);
        for (const Configuration& configuration : configurations()) {
            if (configuration.name == "exact" && !exact_ok) continue;
            const States reference = configuration.run(scene);
            for (const int k : ks) {
                check::Context context(scene.name, ", ", configuration.name, ", scaled by 2^", k);
                const States states = configuration.run(scaled(scene, k));
                bool same = states.size() == reference.size();
                for (std::size_t s = 0; same && s < states.size(); ++s) {
                    for (std::size_t i = 0; same && i < states[s].size(); ++i) {
                        const Particle& a = states[s][i];
                        const Particle& b = reference[s][i];
                        same = a.position == Vec2(std::ldexp(b.position.x(), k), std::ldexp(b.position.y(), k)) &&
                               a.velocity == Vec2(std::ldexp(b.velocity.x(), k), std::ldexp(b.velocity.y(), k)) &&
                               a.particle_collisions == b.particle_collisions && a.wall_collisions == b.wall_collisions;
                    }
                }
                CHECK(same);
                ++compared;
            }
        }
    }
    std::printf("%d scaled runs compared\n", compared);
}

// Just outside the range the engines refuse, naming the limit.
void outside_the_range_is_refused() {
    for (const World world : {World{1e61, 1.0}, World{1.0, 1e-61}, World{0.0, 0.0}}) {
        bool refused = false;
        try {
            SteppedSimulation engine(world, {});
        } catch (const std::invalid_argument& e) {
            refused = std::string(e.what()).find("accepted range") != std::string::npos;
        }
        CHECK(refused);
    }
    bool refused = false;
    try {
        ExactSimulation engine(World{20.0, 1.0}, {Particle{Vec2(5, 5), Vec2(2e60, 0), 0, 0}});
    } catch (const std::invalid_argument& e) {
        refused = std::string(e.what()).find("accepted range") != std::string::npos;
    }
    CHECK(refused);
    refused = false;
    try {
        make_random_particles(3, World{1e10, 1e-55});  // speeds up to L/(8r) = 1.25e64
    } catch (const std::invalid_argument& e) {
        refused = std::string(e.what()).find("1e60") != std::string::npos;
    }
    CHECK(refused);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_scale_invariance",
                      {{"scaled scenes give scaled states", scaled_scenes_give_scaled_states},
                       {"outside the range is refused", outside_the_range_is_refused}});
}
