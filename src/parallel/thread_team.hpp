#pragma once
// The library's worker threads: one team for the process, started on first
// use and kept, running one parallel loop at a time.
//
// Why not OpenMP's regions: libgomp fixes its waiting policy when it loads
// (OMP_WAIT_POLICY, GOMP_SPINCOUNT), and by default an idle worker spins for
// milliseconds after every region. On a machine where another process keeps
// a core busy, that spinning worker takes time slices from the thread doing
// the serial stages, and a worker descheduled in the middle of a static share
// makes the others wait at the barrier: two threads then took 2.2 times as
// long as one (docs/benchmarks.md). Here every loop is shared out in chunks
// that whoever is running claims, so a descheduled worker delays nobody but
// its own chunk; idle workers spin for about 100 microseconds (enough to
// carry them across the serial stages of a step) and then sleep in the kernel.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace particlesim {

class ThreadTeam {
public:
    // body(context, first, last, participant) runs items [first, last); the
    // caller is participant 0, workers 1, 2, ...; it must not throw.
    using ChunkBody = void (*)(void* context, std::int64_t first, std::int64_t last, std::size_t participant);

    // The process's team. It is never destroyed: its sleeping workers end
    // with the process, and a child forked after a loop (which has no
    // workers, only the parent's record of them) runs its loops alone
    // instead of waiting at exit for threads it does not have.
    static ThreadTeam& shared();

    ThreadTeam(const ThreadTeam&) = delete;
    ThreadTeam& operator=(const ThreadTeam&) = delete;

    // Runs items [0, count) in chunks of `chunk` on the caller and up to
    // participants - 1 workers (fewer if the system refuses more threads),
    // and returns when all are done. A loop started while the team runs
    // another (from another thread, or from inside a body) runs on its
    // caller alone: results never depend on who ran what.
    void run(int participants, std::int64_t count, std::int64_t chunk, ChunkBody body, void* context);

private:
    ThreadTeam() = default;

    void ensure_workers(int count);
    void work(std::size_t participant);
    void claim_chunks(std::size_t participant);

    std::atomic<bool> running_{false};  // a loop is running
    int workers_ = 0;                   // started, detached: each waits for loops until the process ends
    int worker_limit_ = std::numeric_limits<int>::max();  // lowered to workers_ when the system refuses one

    // The loop being run: written before generation_ is raised, read by workers that joined.
    ChunkBody body_ = nullptr;
    void* context_ = nullptr;
    std::int64_t count_ = 0;
    std::int64_t chunk_ = 1;
    std::size_t participants_ = 1;
    std::atomic<std::int64_t> next_item_{0};

    std::atomic<std::uint32_t> generation_{0};  // raised for every loop; workers sleep on it
    // Workers inside the current loop, plus closed_bit once no worker may join.
    std::atomic<std::uint32_t> joined_{0};
    static constexpr std::uint32_t closed_bit = 1U << 31;
};

}  // namespace particlesim
