// The parallel loops (OpenMP regions): each item runs exactly once, on a
// thread below the loop's thread count, however loops follow, nest or race
// each other, with one queue of chunks or a share a thread (more threads
// than shares too); a second thread really takes part; each thread starts
// on its own share; a loop inside a parallel
// region of the caller's runs on the caller alone; and a child forked after
// loops ran finishes its own loops and exits.

#include "check.hpp"

#include "parallel/parallel.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <omp.h>
#include <atomic>
#include <chrono>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace particlesim;

namespace {
[[maybe_unused]] bool in_forked_child = false;
}  // namespace

#ifdef __SANITIZE_ADDRESS__
// LeakSanitizer's hook: the forked child's exit finds the parent's OpenMP
// threads in its records, cannot suspend them and would only warn; the
// parent is checked.
extern "C" int __lsan_is_turned_off() { return in_forked_child ? 1 : 0; }
#endif

namespace {

// Whether `condition()` comes to hold within 10 s (far beyond any scheduling
// delay), asked again and again with the core yielded between.
template <typename Condition>
bool holds_within_ten_seconds(Condition condition) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!condition()) {
        if (std::chrono::steady_clock::now() > give_up) return false;
        std::this_thread::yield();
    }
    return true;
}

// Runs one loop; checks every item ran once and each participant was in range.
template <typename Loop>
void check_one_loop(Loop loop, int workers, std::int64_t count, std::int64_t chunk) {
    std::vector<std::atomic<int>> runs(static_cast<std::size_t>(count));
    std::atomic<int> bad_participant{0};
    loop(workers, count, chunk, [&](std::int64_t i, std::size_t thread) {
        runs[static_cast<std::size_t>(i)].fetch_add(1, std::memory_order_relaxed);
        if (thread >= static_cast<std::size_t>(std::max(workers, 1))) bad_participant.fetch_add(1);
    });
    int wrong = 0;
    for (const std::atomic<int>& r : runs) wrong += r.load() != 1 ? 1 : 0;
    CHECK_EQ(wrong, 0);
    CHECK_EQ(bad_participant.load(), 0);
}

void every_item_runs_once() {
    const auto one_queue = [](int workers, std::int64_t count, std::int64_t chunk, auto&& body) {
        parallel_for_dynamic(workers, count, chunk, body);
    };
    const auto in_shares = [](int workers, std::int64_t count, std::int64_t chunk, auto&& body) {
        parallel_for_in_shares(workers, count, chunk, body);
    };
    // 70 threads: more than the loops' shares (detail::max_loop_shares).
    for (int workers : {1, 2, 3, 8, 70}) {
        for (std::int64_t count : {0, 1, 2, 7, 64, 1000, 100003}) {
            for (std::int64_t chunk : {1, 3, 64, 5000}) {
                check::Context context("workers " + std::to_string(workers) + ", count " + std::to_string(count) +
                                       ", chunk " + std::to_string(chunk));
                check_one_loop(one_queue, workers, count, chunk);
                check_one_loop(in_shares, workers, count, chunk);
            }
        }
    }
}

// A loop of one item a thread whose items each wait for all the others to
// start: no thread can take another's share, so item k runs on thread k
// (the share whose data that thread's core holds from the step before).
void each_thread_starts_on_its_own_share() {
    for (const int workers : {2, 3, 4}) {
        check::Context context("workers " + std::to_string(workers));
        std::vector<std::size_t> ran_on(static_cast<std::size_t>(workers), 99);
        std::atomic<int> started{0};
        std::atomic<bool> waited_out{false};
        parallel_for_in_shares(workers, workers, 1, [&](std::int64_t i, std::size_t thread) {
            ran_on[static_cast<std::size_t>(i)] = thread;
            started.fetch_add(1);
            if (!holds_within_ten_seconds([&] { return started.load() == workers; })) waited_out.store(true);
        });
        CHECK(!waited_out.load());
        for (int k = 0; k < workers; ++k) CHECK_EQ(ran_on[static_cast<std::size_t>(k)], static_cast<std::size_t>(k));
    }
}

// Thousands of short loops in a row: a worker late for one loop must neither
// run items of the next one twice nor miss its end.
void many_short_loops_in_a_row() {
    std::vector<std::int64_t> slots(256);
    std::int64_t wrong = 0;
    for (int loop = 0; loop < 20000; ++loop) {
        parallel_for(2, static_cast<std::int64_t>(slots.size()),
                     [&](std::int64_t i, std::size_t) { slots[static_cast<std::size_t>(i)] += i + loop; });
    }
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const auto n = static_cast<std::int64_t>(i);
        wrong += slots[i] != 20000 * n + 19999 * 20000 / 2 ? 1 : 0;
    }
    CHECK_EQ(wrong, 0);
}

// A loop started from inside a loop's body runs on its own caller; loops
// started by several threads at once each complete.
void nested_and_concurrent_loops_are_complete() {
    std::atomic<std::int64_t> inner_items{0};
    std::atomic<int> bad_participant{0};
    parallel_for_dynamic(2, 16, 1, [&](std::int64_t, std::size_t) {
        parallel_for(2, 100, [&](std::int64_t, std::size_t thread) {
            inner_items.fetch_add(1);
            if (thread >= 2) bad_participant.fetch_add(1);
        });
    });
    CHECK_EQ(inner_items.load(), 1600);
    CHECK_EQ(bad_participant.load(), 0);

    std::vector<std::int64_t> sums(4, 0);
    std::vector<std::thread> callers;
    for (std::size_t c = 0; c < sums.size(); ++c) {
        callers.emplace_back([&sums, c] {
            for (int loop = 0; loop < 500; ++loop) {
                std::atomic<std::int64_t> sum{0};
                parallel_for(2, 1000, [&](std::int64_t i, std::size_t) { sum.fetch_add(i); });
                sums[c] += sum.load();
            }
        });
    }
    for (std::thread& caller : callers) caller.join();
    for (const std::int64_t sum : sums) CHECK_EQ(sum, 500 * (999 * 1000 / 2));
}

// Item 0 waits until some other participant has run an item: it returns
// only if a worker really joined (10 s is far beyond any scheduling delay).
void a_worker_takes_part() {
    std::atomic<bool> other_ran{false};
    std::atomic<bool> waited_out{false};
    parallel_for_dynamic(2, 64, 1, [&](std::int64_t i, std::size_t thread) {
        if (thread != 0) other_ran.store(true);
        if (i != 0 || thread != 0) return;
        if (!holds_within_ten_seconds([&] { return other_ran.load(); })) waited_out.store(true);
    });
    CHECK(other_ran.load());
    CHECK(!waited_out.load());
}

// A child forked after loops have started threads has none of them: its
// loops must still finish (on the child alone), and so must its exit.
void a_forked_child_runs_loops_and_exits() {
#if defined(__SANITIZE_THREAD__) || defined(PARTICLESIM_TSAN_BUILD)
    std::puts("  (skipped under ThreadSanitizer, which does not follow a multi-threaded fork)");
#else
    parallel_for(2, 1000, [](std::int64_t, std::size_t) {});
    const pid_t child = fork();
    if (child == 0) {
        in_forked_child = true;
        std::atomic<std::int64_t> sum{0};
        parallel_for(2, 1000, [&](std::int64_t i, std::size_t) { sum.fetch_add(i); });
        std::exit(sum.load() == 999 * 1000 / 2 ? 0 : 3);  // exit(), not _exit(): static destructors run
    }
    CHECK(child > 0);
    int status = -1;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > give_up) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            CHECK(false);  // the child hung
            return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    CHECK(WIFEXITED(status));
    CHECK_EQ(WEXITSTATUS(status), 0);
#endif
}

// Inside a parallel region of the caller's (a host program's own OpenMP
// threads), every loop runs on its caller alone, even where the host allows
// nested regions: nothing oversubscribes the machine.
void loops_inside_a_host_region_run_on_the_caller() {
    for (const int levels : {1, 4}) {
        check::Context context("max active levels " + std::to_string(levels));
        const int previous = omp_get_max_active_levels();
        omp_set_max_active_levels(levels);
        std::atomic<std::int64_t> items{0};
        std::atomic<int> not_the_caller{0};
        std::atomic<int> defaults_above_one{0};
#pragma omp parallel num_threads(2)
        {
            if (default_thread_count() != 1) defaults_above_one.fetch_add(1);
            const int caller_level = omp_get_level();
            parallel_for(2, 10000, [&](std::int64_t, std::size_t thread) {
                items.fetch_add(1);
                if (thread != 0 || omp_get_level() != caller_level) not_the_caller.fetch_add(1);
            });
        }
        omp_set_max_active_levels(previous);
        CHECK_EQ(items.load(), 2 * 10000);
        CHECK_EQ(not_the_caller.load(), 0);
        CHECK_EQ(defaults_above_one.load(), 0);
    }
}

}  // namespace

// What a body throws on a worker reaches the caller, as it does on one
// thread, instead of ending the program (an exception may not leave a
// parallel region): the first one, once every item has run or thrown.
void an_exception_reaches_the_caller() {
    for (const int workers : {1, 2, 4}) {
        check::Context context("workers ", workers);
        std::atomic<std::int64_t> ran{0};
        std::string caught;
        try {
            parallel_for_dynamic(workers, 1000, 4, [&](std::int64_t i, std::size_t) {
                ran.fetch_add(1, std::memory_order_relaxed);
                if (i == 417) throw std::runtime_error("item 417");
            });
        } catch (const std::runtime_error& e) {
            caught = e.what();
        }
        CHECK_EQ(caught, std::string("item 417"));
        // One thread stops at the throw; workers run the other items, as parallel.hpp says.
        CHECK_EQ(ran.load(), std::int64_t{workers == 1 ? 418 : 1000});
        // Allocations that fail on every worker: one std::bad_alloc comes out.
        bool out_of_memory = false;
        try {
            parallel_for_dynamic(workers, 64, 1, [](std::int64_t, std::size_t) { throw std::bad_alloc(); });
        } catch (const std::bad_alloc&) {
            out_of_memory = true;
        }
        CHECK(out_of_memory);
    }
}

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_parallel_loops",
                      {{"every item runs once", every_item_runs_once},
                       {"many short loops in a row", many_short_loops_in_a_row},
                       {"nested and concurrent loops are complete", nested_and_concurrent_loops_are_complete},
                       {"a worker takes part", a_worker_takes_part},
                       {"each thread starts on its own share", each_thread_starts_on_its_own_share},
                       {"a forked child runs loops and exits", a_forked_child_runs_loops_and_exits},
                       {"loops inside a host region run on the caller", loops_inside_a_host_region_run_on_the_caller},
                       {"an exception reaches the caller", an_exception_reaches_the_caller}});
}
