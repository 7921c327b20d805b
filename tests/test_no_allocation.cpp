// Once its buffers have their working size, a step allocates nothing: every
// operator new after the warm-up steps is counted.

#include "check.hpp"

#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

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
        {{"no allocation in the step loop", [] {
              const World params{20000.0, 1.0};
              for (const PairSearch search : {PairSearch::brute_force, PairSearch::grid, PairSearch::paths}) {
                  for (const int threads : {1, 2}) {
                      for (const int sort_every : {0, 1}) {  // never / every step stored by position
                          SteppedSimulation sim(
                              params, make_random_particles(1000, params),
                              {.pair_search = search, .threads = threads, .sort_by_position_every = sort_every});
                          const check::Context context("search ", static_cast<int>(search), ", ", threads,
                                                       " threads, sorted every ", sort_every);
                          particlesim::run(sim, 20);  // warm-up: buffers grow to their working size
                          const long before = allocations.load();
                          particlesim::run(sim, 200);
                          CHECK_EQ(allocations.load() - before, 0L);
                      }
                  }
              }
          }}});
}
