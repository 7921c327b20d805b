// Once its buffers have their working size, a step allocates nothing: every
// operator new after the warm-up steps is counted.

#include "check.hpp"

#include "parallel/run_queue_wait.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <atomic>
#include <cstdlib>
#include <new>
#include <optional>

namespace {
std::atomic<long> allocations{0};
}

void* operator new(std::size_t size) {
    ++allocations;
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace particlesim;

int main(int argc, char** argv) {
    return check::run(
        argc, argv, "test_no_allocation",
        {{"no allocation in the step loop",
          [] {
              const World params{20000.0, 1.0};
              for (const PairSearch search : {PairSearch::brute_force, PairSearch::grid, PairSearch::paths}) {
                  // Unset: small scenes then switch between one thread and all of them (thread_choice.hpp).
                  for (const std::optional<int> threads :
                       {std::optional<int>(1), std::optional<int>(2), std::optional<int>()}) {
                      for (const int sort_every : {0, 1}) {  // never / every step stored by position
                          // The brute force tests every pair: fewer disks keep it quick, with the same stages.
                          const std::size_t count = search == PairSearch::brute_force ? 300 : 1000;
                          SteppedSimulation sim(
                              params, make_random_particles(count, params),
                              {.pair_search = search, .threads = threads, .sort_by_position_every = sort_every});
                          const check::Context context("search ", static_cast<int>(search), ", ", threads.value_or(0),
                                                       " threads (0: unset), sorted every ", sort_every);
                          // Warm-up: buffers grow to their working size (with threads unset, past a first
                          // trial of both thread counts).
                          particlesim::run(sim, 40);
                          const long before = allocations.load();
                          particlesim::run(sim, 600);  // with threads unset, two more trials
                          CHECK_EQ(allocations.load() - before, 0L);
                      }
                  }
              }
          }},
         {"reading the threads' run-queue wait", [] {
              // A large scene's thread choice reads it every few steps (stepped/thread_choice.hpp).
              // CHECK itself may allocate (its text): the readings are counted first.
              int readings = 0;
              const long before = allocations.load();
              for (int k = 0; k < 100; ++k) readings += process_run_queue_wait_seconds().has_value() ? 1 : 0;
              const long allocated = allocations.load() - before;
              CHECK_EQ(readings, 100);
              CHECK_EQ(allocated, 0L);
          }}});
}
