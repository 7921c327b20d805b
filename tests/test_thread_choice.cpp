// ThreadChoice: which thread count each step gets, from step times fed to it
// (no clock involved), so that the trials' schedule and decisions are exact.

#include "check.hpp"

#include "stepped/thread_choice.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

using particlesim::ThreadChoice;
namespace stepped_tuning = particlesim::stepped_tuning;

namespace {

constexpr int warming = stepped_tuning::trial_warm_up_steps;
constexpr int trial = stepped_tuning::trial_blocks * stepped_tuning::trial_block_steps;

// Runs `steps` steps, each taking `one` seconds on one thread and `most` on
// more, and returns the thread count each step got.
std::vector<int> run(ThreadChoice& choice, int steps, double one, double most) {
    std::vector<int> used;
    for (int step = 0; step < steps; ++step) {
        const int threads = choice.threads();
        used.push_back(threads);
        choice.record(threads == 1 ? one : most);
    }
    return used;
}

// Steps in [first, last) that got `threads`.
long count_of(const std::vector<int>& used, int threads, int first, int last) {
    return std::count(used.begin() + first, used.begin() + last, threads);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(
        argc, argv, "test_thread_choice",
        {{"without trials every step gets every thread",
          [] {
              ThreadChoice unmeasured(4, false);
              for (const int threads : run(unmeasured, 1000, 0.1, 1.0)) CHECK_EQ(threads, 4);
              ThreadChoice single(1, true);
              for (const int threads : run(single, 1000, 1.0, 0.1)) CHECK_EQ(threads, 1);
          }},
         {"a trial alternates blocks of one thread and all, after the warm-up",
          [] {
              ThreadChoice choice(2, true);
              const std::vector<int> used = run(choice, warming + trial, 1.0, 1.0);
              CHECK_EQ(count_of(used, 2, 0, warming), long{warming});
              for (int step = 0; step < trial; ++step) {
                  const int expected = (step / stepped_tuning::trial_block_steps) % 2 == 0 ? 1 : 2;
                  CHECK_EQ(used[static_cast<std::size_t>(warming + step)], expected);
              }
              CHECK_EQ(choice.steps_on_one_thread(), std::int64_t{trial / 2});
          }},
         {"the faster count runs until the next trial",
          [] {
              for (const bool one_is_faster : {true, false}) {
                  const check::Context context(one_is_faster ? "one thread faster" : "two threads faster");
                  ThreadChoice choice(2, true);
                  const int cycle = trial + stepped_tuning::trial_run_steps;
                  const std::vector<int> used =
                      run(choice, warming + 3 * cycle, one_is_faster ? 1.0 : 2.0, one_is_faster ? 2.0 : 1.0);
                  for (int k = 0; k < 3; ++k) {
                      const int run_first = warming + k * cycle + trial;
                      const int winner = one_is_faster ? 1 : 2;
                      CHECK_EQ(count_of(used, winner, run_first, run_first + stepped_tuning::trial_run_steps),
                               long{stepped_tuning::trial_run_steps});
                      CHECK_EQ(count_of(used, 1, run_first - trial, run_first), long{trial / 2});  // the trial before
                  }
              }
          }},
         {"ties keep every thread",
          [] {
              ThreadChoice choice(3, true);
              const std::vector<int> used = run(choice, warming + trial + stepped_tuning::trial_run_steps, 1.0, 1.0);
              CHECK_EQ(count_of(used, 3, warming + trial, warming + trial + stepped_tuning::trial_run_steps),
                       long{stepped_tuning::trial_run_steps});
          }},
         {"the first step of each block is not counted", [] {
              // Every switch costs a slow step; the steps after it decide.
              ThreadChoice choice(2, true);
              run(choice, warming, 1.0, 1.0);
              for (int step = 0; step < trial; ++step) {
                  const bool first_of_block = step % stepped_tuning::trial_block_steps == 0;
                  const int threads = choice.threads();
                  // One thread: 1.0 a step, but 100 on a block's first step; two: 2.0.
                  choice.record(threads == 1 ? (first_of_block ? 100.0 : 1.0) : 2.0);
              }
              CHECK_EQ(choice.threads(), 1);
          }}});
}
