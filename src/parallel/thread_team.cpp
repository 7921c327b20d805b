#include "parallel/thread_team.hpp"

#include <algorithm>
#include <chrono>
#include <system_error>
#include <thread>

namespace particlesim {

namespace {

// How long an idle worker polls for the next loop before it sleeps, and how
// long the caller polls between yields while the last chunks finish. A step's
// serial stages between two loops take a few to a few hundred microseconds.
constexpr auto idle_spin = std::chrono::microseconds(100);
constexpr int polls_between_yields = 256;

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
}

}  // namespace

ThreadTeam& ThreadTeam::shared() {
    static ThreadTeam* const team = new ThreadTeam;
    return *team;
}

void ThreadTeam::ensure_workers(int count) {
    for (; workers_ < std::min(count, worker_limit_); ++workers_) {
        const auto participant = static_cast<std::size_t>(workers_) + 1;
        try {
            std::thread([this, participant] { work(participant); }).detach();
        } catch (const std::system_error&) {
            // Out of threads: the loops run on those there are, and later
            // loops do not ask the system again (a failed call per loop).
            worker_limit_ = workers_;
            return;
        }
    }
}

void ThreadTeam::claim_chunks(std::size_t participant) {
    while (true) {
        const std::int64_t first = next_item_.fetch_add(chunk_, std::memory_order_relaxed);
        if (first >= count_) return;
        body_(context_, first, std::min(first + chunk_, count_), participant);
    }
}

void ThreadTeam::run(int participants, std::int64_t count, std::int64_t chunk, ChunkBody body, void* context) {
    chunk = std::max<std::int64_t>(chunk, 1);
    bool expected = false;
    if (participants <= 1 || count <= chunk || !running_.compare_exchange_strong(expected, true)) {
        body(context, 0, count, 0);
        return;
    }
    ensure_workers(participants - 1);
    body_ = body;
    context_ = context;
    count_ = count;
    chunk_ = chunk;
    participants_ = static_cast<std::size_t>(participants);
    next_item_.store(0, std::memory_order_relaxed);
    joined_.fetch_and(~closed_bit, std::memory_order_release);  // open: workers may join
    generation_.fetch_add(1, std::memory_order_release);
    generation_.notify_all();

    claim_chunks(0);

    // No worker joins from now on; wait for those that did.
    joined_.fetch_or(closed_bit, std::memory_order_acq_rel);
    for (int polls = 1; (joined_.load(std::memory_order_acquire) & ~closed_bit) != 0; ++polls) {
        cpu_relax();
        if (polls % polls_between_yields == 0) std::this_thread::yield();
    }
    running_.store(false, std::memory_order_release);
}

void ThreadTeam::work(std::size_t participant) {
    std::uint32_t seen = 0;
    while (true) {
        const auto spin_until = std::chrono::steady_clock::now() + idle_spin;
        for (int polls = 1; generation_.load(std::memory_order_acquire) == seen; ++polls) {
            cpu_relax();
            if (polls % 64 == 0 && std::chrono::steady_clock::now() > spin_until) {
                generation_.wait(seen, std::memory_order_acquire);
            }
        }
        seen = generation_.load(std::memory_order_acquire);
        // Joining and the closing of the loop are one atomic word: a worker
        // that joined is waited for, one too late leaves without touching it.
        if ((joined_.fetch_add(1, std::memory_order_acq_rel) & closed_bit) == 0 && participant < participants_) {
            claim_chunks(participant);
        }
        joined_.fetch_sub(1, std::memory_order_release);
    }
}

}  // namespace particlesim
