// ThreadChoice: which thread count each step gets, from step times and
// run-queue waits fed to it (no clock involved), so that the trials' schedule
// and decisions are exact; and the run-queue wait it reads on Linux.

#include "check.hpp"

#include "parallel/run_queue_wait.hpp"
#include "stepped/thread_choice.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <thread>
#include <vector>

using particlesim::ThreadChoice;
using particlesim::ThreadPolicy;
namespace stepped_tuning = particlesim::stepped_tuning;

namespace {

constexpr int warming = stepped_tuning::trial_warm_up_steps;
constexpr int trial = stepped_tuning::trial_blocks * stepped_tuning::trial_block_steps;
constexpr int watch = stepped_tuning::contention_watch_steps;  // with steps of 1 s
constexpr int contended_trial = stepped_tuning::contended_trial_steps;

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

// The same, with the process's threads waiting `wait_share` of each step's
// time for a CPU while the step runs on more than one thread (one thread
// beside one busy process has a core of its own); `reading` replaces the
// readings where given.
std::vector<int> run_waiting(ThreadChoice& choice, int steps, double one, double most, double wait_share,
                             std::optional<std::optional<double> > reading = std::nullopt) {
    std::vector<int> used;
    double waited = 0.0;
    for (int step = 0; step < steps; ++step) {
        const int threads = choice.threads();
        used.push_back(threads);
        const double seconds = threads == 1 ? one : most;
        if (threads > 1) waited += wait_share * seconds;
        choice.record(seconds);
        if (choice.reading_due()) choice.read_waits(reading ? *reading : std::optional<double>(waited));
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
              ThreadChoice unmeasured(4, ThreadPolicy::all);
              for (const int threads : run(unmeasured, 1000, 0.1, 1.0)) CHECK_EQ(threads, 4);
              for (const ThreadPolicy policy : {ThreadPolicy::trials, ThreadPolicy::trials_when_contended}) {
                  ThreadChoice single(1, policy);
                  for (const int threads : run_waiting(single, 1000, 1.0, 0.1, 1.0)) CHECK_EQ(threads, 1);
                  CHECK_EQ(single.trials(), std::int64_t{0});
              }
          }},
         {"a trial alternates blocks of one thread and all, after the warm-up",
          [] {
              ThreadChoice choice(2, ThreadPolicy::trials);
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
                  ThreadChoice choice(2, ThreadPolicy::trials);
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
              ThreadChoice choice(3, ThreadPolicy::trials);
              const std::vector<int> used = run(choice, warming + trial + stepped_tuning::trial_run_steps, 1.0, 1.0);
              CHECK_EQ(count_of(used, 3, warming + trial, warming + trial + stepped_tuning::trial_run_steps),
                       long{stepped_tuning::trial_run_steps});
          }},
         {"the first step of each block is not counted",
          [] {
              // Every switch costs a slow step; the steps after it decide.
              ThreadChoice choice(2, ThreadPolicy::trials);
              run(choice, warming, 1.0, 1.0);
              for (int step = 0; step < trial; ++step) {
                  const bool first_of_block = step % stepped_tuning::trial_block_steps == 0;
                  const int threads = choice.threads();
                  // One thread: 1.0 a step, but 100 on a block's first step; two: 2.0.
                  choice.record(threads == 1 ? (first_of_block ? 100.0 : 1.0) : 2.0);
              }
              CHECK_EQ(choice.threads(), 1);
          }},
         {"threads that get a CPU when ready keep every step on all of them",
          [] {
              // Two threads twice as fast: trials would cost, and none runs.
              ThreadChoice choice(2, ThreadPolicy::trials_when_contended);
              const std::vector<int> used = run_waiting(choice, 5000, 1.0, 0.5, 0.0);
              CHECK_EQ(count_of(used, 2, 0, 5000), 5000L);
              CHECK_EQ(choice.trials(), std::int64_t{0});
              CHECK_EQ(choice.steps_on_one_thread(), std::int64_t{0});
              // Just below the share of the wall time that counts as waiting: still none.
              ThreadChoice below(2, ThreadPolicy::trials_when_contended);
              run_waiting(below, 5000, 1.0, 0.5, 0.99 * stepped_tuning::contended_wait_share);
              CHECK_EQ(below.trials(), std::int64_t{0});
          }},
         {"waits for a CPU start a trial on one thread after a watch",
          [] {
              // Steps of 1 s: a watch ends after its least steps.
              ThreadChoice choice(2, ThreadPolicy::trials_when_contended);
              const std::vector<int> used = run_waiting(choice, warming + watch + contended_trial, 1.0, 1.0,
                                                        1.01 * stepped_tuning::contended_wait_share);
              CHECK_EQ(count_of(used, 2, 0, warming + watch), long{warming + watch});
              CHECK_EQ(count_of(used, 1, warming + watch, warming + watch + contended_trial), long{contended_trial});
              CHECK_EQ(choice.trials(), std::int64_t{1});
          }},
         {"a watch lasts its least wall time",
          [] {
              // Steps of 1 ms: the watch runs until it spans contention_watch_seconds.
              const int steps = static_cast<int>(stepped_tuning::contention_watch_seconds / 1e-3 + 0.5);
              ThreadChoice choice(2, ThreadPolicy::trials_when_contended);
              const std::vector<int> used = run_waiting(choice, warming + steps + 2, 1e-3, 1e-3, 0.5);
              CHECK_EQ(count_of(used, 2, 0, warming + steps - 1), long{warming + steps - 1});
              CHECK_EQ(used[static_cast<std::size_t>(warming + steps + 1)], 1);
          }},
         {"the trial sets one thread against the whole watch, stalls included",
          [] {
              // On all the threads most steps take half of one thread's time, but every 8th
              // stalls (the other process's turn), and waits only then: with a stall of 4 the
              // watch's mean, 0.9375, is above the margin and loses to one thread; with a
              // stall of 2 (mean 0.6875) it wins.
              for (const double stall : {4.0, 2.0}) {
                  const check::Context context("a stall of ", stall);
                  ThreadChoice choice(2, ThreadPolicy::trials_when_contended);
                  std::vector<int> used;
                  double waited = 0.0;
                  int all_thread_steps = 0;
                  for (int step = 0; step < warming + watch + contended_trial + stepped_tuning::trial_run_steps;
                       ++step) {
                      const int threads = choice.threads();
                      used.push_back(threads);
                      double seconds = 1.0;
                      if (threads > 1) {
                          const bool stalls = ++all_thread_steps % 8 == 0;
                          seconds = stalls ? stall : 0.5;
                          waited += stalls ? stall - 0.5 : 0.0;
                      }
                      choice.record(seconds);
                      if (choice.reading_due()) choice.read_waits(waited);
                  }
                  const int winner = stall == 4.0 ? 1 : 2;
                  const int stretch = warming + watch + contended_trial;
                  CHECK_EQ(count_of(used, winner, stretch, stretch + stepped_tuning::trial_run_steps),
                           long{stepped_tuning::trial_run_steps});
                  CHECK_EQ(choice.trials(), std::int64_t{1});
              }
          }},
         {"after waits, all the threads must beat a share of one thread's time",
          [] {
              const double margin = stepped_tuning::contended_trial_margin;
              for (const double most : {0.99 * margin, 1.01 * margin, 1.0, 0.5}) {
                  const check::Context context("all the threads ", most, " of one thread's time");
                  ThreadChoice choice(2, ThreadPolicy::trials_when_contended);
                  const int stretch = warming + watch + contended_trial;
                  const std::vector<int> used =
                      run_waiting(choice, stretch + stepped_tuning::trial_run_steps, 1.0, most, 0.5);
                  CHECK_EQ(count_of(used, most < margin ? 2 : 1, stretch, stretch + stepped_tuning::trial_run_steps),
                           long{stepped_tuning::trial_run_steps});
              }
          }},
         {"a stretch ends in a watch again",
          [] {
              // Quiet for 10 watches (every reading 0), then waiting, with one thread faster:
              // a trial, a stretch on one thread, then a watch on all the threads and a
              // second trial.
              ThreadChoice choice(2, ThreadPolicy::trials_when_contended);
              run_waiting(choice, warming + 10 * watch, 1.0, 0.5, 0.0);
              CHECK_EQ(choice.trials(), std::int64_t{0});
              const int cycle = watch + contended_trial + stepped_tuning::trial_run_steps;
              const std::vector<int> used = run_waiting(choice, cycle + watch, 1.0, 2.0, 0.5);
              CHECK_EQ(count_of(used, 2, 0, watch), long{watch});
              CHECK_EQ(count_of(used, 1, watch, cycle), long{cycle - watch});
              CHECK_EQ(count_of(used, 2, cycle, cycle + watch), long{watch});
              CHECK_EQ(choice.trials(), std::int64_t{2});
          }},
         {"no reading of the waits: every step on every thread",
          [] {
              ThreadChoice choice(2, ThreadPolicy::trials_when_contended);
              const std::vector<int> used = run_waiting(choice, 2000, 1.0, 2.0, 1.0, std::optional<double>());
              CHECK_EQ(count_of(used, 2, 0, 2000), 2000L);
              CHECK_EQ(choice.trials(), std::int64_t{0});
              CHECK(!choice.reading_due());
          }},
         {"the process's run-queue wait grows when its threads outnumber the cores", [] {
              const std::optional<double> before = particlesim::process_run_queue_wait_seconds();
              CHECK(before.has_value());  // Linux with schedstat: what the thread choice reads
              if (!before) return;
              // Four busy threads a core for 0.3 s: each waits about three quarters of the time.
              const unsigned cores = std::max(1U, std::thread::hardware_concurrency());
              std::atomic<bool> stop{false};
              std::vector<std::thread> busy;
              for (unsigned k = 0; k < 4 * cores; ++k) {
                  busy.emplace_back([&stop] {
                      while (!stop.load(std::memory_order_relaxed)) {
                      }
                  });
              }
              std::this_thread::sleep_for(std::chrono::milliseconds(300));
              // Read while they still run: a thread that ended takes its wait along.
              const std::optional<double> during = particlesim::process_run_queue_wait_seconds();
              stop = true;
              for (std::thread& thread : busy) thread.join();
              CHECK(during.has_value());
              if (!during) return;
              // At least a quarter of what the threads waited together (about 0.9 s a core).
              const check::Context context("waited ", *during - *before, " s on ", cores, " cores");
              CHECK(*during - *before >= 0.25 * 0.3 * 3 * cores);
              const std::optional<double> after = particlesim::process_run_queue_wait_seconds();
              CHECK(after.has_value());
          }}});
}
