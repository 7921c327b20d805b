// A host program with OpenMP threads of its own calls the library from inside
// its `#pragma omp parallel`: every call gives the bytes of a call from
// outside, the library's default thread count there is one, and no call
// starts threads beyond the host's (even where the host allows nested
// regions). Outside a region, the default thread count is OpenMP's.

#include "check.hpp"
#include "state_hash.hpp"

#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <omp.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

// The process's threads now (Linux: /proc/self/status).
int process_threads() {
    std::ifstream status("/proc/self/status");
    std::string word;
    while (status >> word) {
        if (word == "Threads:") {
            int threads = 0;
            status >> threads;
            return threads;
        }
    }
    return -1;
}

// 4000 disks in the default box: large enough that the grid and the paths
// search would share their work between threads outside a region.
const World world{20000.0, 1.0};
const std::vector<Particle>& start() {
    static const std::vector<Particle> particles = make_random_particles(4000, world, {.seed = 11});
    return particles;
}

std::uint64_t run_hash(const SteppedOptions& options, int* threads_used = nullptr) {
    SteppedSimulation simulation(world, start(), options);
    run(simulation, 12);
    if (threads_used != nullptr) *threads_used = simulation.threads();
    return state_hash::hash(simulation.particles());
}

void same_bytes_and_no_oversubscription_inside_a_host_region() {
    const std::uint64_t reference = run_hash({.threads = 2});
    for (const int levels : {1, 4}) {
        check::Context context("host's max active levels " + std::to_string(levels));
        const int previous = omp_get_max_active_levels();
        omp_set_max_active_levels(levels);
        std::vector<std::uint64_t> hashes(4, 0);
        std::vector<int> default_threads(2, 0);
        std::vector<int> most_threads_seen(2, 0);
        int host_threads = 0;
#pragma omp parallel num_threads(2)
        {
            const int me = omp_get_thread_num();
#pragma omp single
            host_threads = process_threads();
            // One call with the library's default threads, one asking for 2 and one for each search.
            hashes[static_cast<std::size_t>(me)] = run_hash({}, &default_threads[static_cast<std::size_t>(me)]);
            hashes[static_cast<std::size_t>(2 + me)] =
                run_hash({.pair_search = me == 0 ? PairSearch::grid : PairSearch::paths, .threads = 2});
            most_threads_seen[static_cast<std::size_t>(me)] = process_threads();
        }
        omp_set_max_active_levels(previous);
        for (const std::uint64_t hash : hashes) CHECK_EQ(hash, reference);
        for (const int threads : default_threads) CHECK_EQ(threads, 1);
        for (const int threads : most_threads_seen) CHECK_EQ(threads, host_threads);
    }
}

void default_thread_count_is_openmps() {
    const int previous = omp_get_max_threads();
    for (const int threads : {1, 3}) {
        omp_set_num_threads(threads);
        int used = 0;
        const std::uint64_t hash = run_hash({}, &used);
        CHECK_EQ(used, threads);
        CHECK_EQ(hash, run_hash({.threads = 1}));
    }
    omp_set_num_threads(previous);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_openmp_host",
                      {{"same bytes and no oversubscription inside a host region",
                        same_bytes_and_no_oversubscription_inside_a_host_region},
                       {"default thread count is OpenMP's", default_thread_count_is_openmps}});
}
