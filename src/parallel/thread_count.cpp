#include "parallel/parallel.hpp"

#include <pthread.h>

#include <atomic>

namespace particlesim {

namespace {

// Whether this process has started a parallel region, and whether it is a
// child forked after its parent had (its OpenMP threads stayed behind).
std::atomic<bool> regions_started{false};
std::atomic<bool> forked_after_regions{false};

// Registered once, before the first loop can run.
const bool fork_watch = [] {
    pthread_atfork(nullptr, nullptr, [] { forked_after_regions.store(regions_started.load()); });
    return true;
}();

}  // namespace

int default_thread_count() { return omp_get_active_level() > 0 ? 1 : std::max(omp_get_max_threads(), 1); }

bool loops_may_start_threads() {
    if (omp_get_active_level() > 0 || forked_after_regions.load(std::memory_order_relaxed)) return false;
    if (!regions_started.load(std::memory_order_relaxed)) regions_started.store(true);
    return true;
}

}  // namespace particlesim
