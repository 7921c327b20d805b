#include "search/brute_force_search.hpp"

#include "parallel/parallel.hpp"

#include <cstdint>

namespace particlesim {

void find_pairs_brute_force(const PairSearchInput& in, std::span<ThreadCandidates> buffers) {
    const auto count = static_cast<std::int64_t>(in.particles.size());
    const int threads = worker_count(buffers.size(), count * count / 2, min_pair_work_per_thread);
    parallel_for_dynamic(threads, count, 8, [&](std::int64_t i, std::size_t thread) {
        if (in.wall_time[i] == 0.0) return;  // every candidate of i would be pruned
        ThreadCandidates& out = buffers[thread];
        for (std::int64_t j = i + 1; j < count; ++j) {
            test_pair(in, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), out);
        }
    });
}

}  // namespace particlesim
