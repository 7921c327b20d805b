#pragma once
// The benchmark modes of particlesim_bench; each prints CSV on stdout.

#include "particlesim/random_scene.hpp"
#include "particlesim/world.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>

namespace bench {

// The dense gas's box: `count` disks of radius 1 at area fraction 0.3.
inline particlesim::World dense_gas_world(std::size_t count) {
    return particlesim::World{std::sqrt(static_cast<double>(count) * std::numbers::pi / 0.3), 1.0};
}

// The default scene's density (1000 disks of radius 1 in L = 20000) for
// `count` disks, and its speeds as the rules draw them there (L/8 to L/4 of
// L = 20000 a step), kept whatever the box: the sizes benchmark's family.
inline particlesim::World default_density_world(std::size_t count) {
    return particlesim::World{20000.0 * std::sqrt(static_cast<double>(count) / 1000.0), 1.0};
}
inline constexpr particlesim::SpeedRange default_scene_speeds{2500.0, 5000.0};

// The simcli built beside the harness; exits naming `mode` when the apps were not built.
std::string simcli_path(const char* mode);

void steps_benchmark(bool quick);        // time per step against N, the dense gas
void sizes_benchmark(bool quick);        // time per particle-step, 4 to 1e7 particles, two densities
void choice_benchmark(bool quick);       // the paths search and the grid forced, and which auto takes
void simcli_benchmark(bool quick);       // whole simcli runs of the target scenes
void accuracy_benchmark(bool quick);     // run time against error, K = 1 ... 64 and the exact engine
void exact_benchmark(bool quick);        // the exact engine's collisions per second
void exact_queue_benchmark(bool quick);  // the exact engine's two queues forced, around where it switches
void stress_benchmark(bool quick);       // the long stability run: a crowded box for 1e6 steps
void divergence_benchmark(bool quick);   // two correct programs drifting apart by chaos
void loaded_benchmark(bool quick);       // simcli on 1 and 2 threads, quiet and beside a busy process
void programs_benchmark(bool quick);     // simcli beside the original programs and EDMD (programs_benchmark.cpp)
void memory_benchmark(bool quick);       // random 64-byte reads at the exact engine's sizes (memory_benchmark.cpp)

}  // namespace bench
