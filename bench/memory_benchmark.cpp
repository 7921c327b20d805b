// particlesim_bench memory: how fast this machine reads 64-byte lines at
// random from an array of the exact engine's size, the pace that bounds
// the engine once its state outgrows the caches. Two ways: independent
// reads (their addresses known in advance, so the processor overlaps as
// many misses as it can hold) and a chain (each read's address in the line
// before, so one miss at a time: the latency). Arrays of 2, 20 and 200 MB,
// about the exact engine's state at 1e4, 1e5 and 1e6 disks (190 bytes a
// disk), each with transparent huge pages asked for (as the engine does)
// and refused (as with PARTICLESIM_HUGE_PAGES=0). One row per size and
// kind of page: the medians of the rounds and their ranges.

#include "benchmarks.hpp"
#include "statistics.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <vector>

namespace bench {

namespace {

struct alignas(64) Line {
    std::uint64_t word[8];
};

struct FreeLines {
    void operator()(Line* lines) const { std::free(lines); }
};

// `count` lines, each naming the next of one random cycle through them all
// in its first word; in huge pages if the kernel gives them and `huge`, else
// in small ones.
std::unique_ptr<Line[], FreeLines> lines_in_a_cycle(std::size_t count, bool huge, std::mt19937_64& random) {
    constexpr std::size_t huge_page = std::size_t{2} << 20;
    const std::size_t bytes = (count * sizeof(Line) + huge_page - 1) / huge_page * huge_page;
    std::unique_ptr<Line[], FreeLines> lines(static_cast<Line*>(std::aligned_alloc(huge_page, bytes)));
    if (!lines) {
        std::fprintf(stderr, "particlesim_bench memory: no room for %zu bytes\n", bytes);
        std::exit(1);
    }
    madvise(lines.get(), bytes, huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
    std::vector<std::uint32_t> order(count);
    for (std::size_t k = 0; k < count; ++k) order[k] = static_cast<std::uint32_t>(k);
    std::shuffle(order.begin(), order.end(), random);
    for (std::size_t k = 0; k < count; ++k) {
        lines[order[k]] = Line{};
        lines[order[k]].word[0] = order[(k + 1) % count];
    }
    return lines;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void memory_benchmark(bool quick) {
    const std::vector<std::size_t> sizes_mb =
        quick ? std::vector<std::size_t>{2, 20} : std::vector<std::size_t>{2, 20, 200};
    const int rounds = quick ? 2 : 5;
    const std::size_t reads = quick ? 2'000'000 : 20'000'000;
    const std::size_t chain_reads = reads / 10;
    std::printf(
        "array_mb,pages,rounds,independent_lines_per_s,independent_min,independent_max,chain_ns,chain_ns_min,"
        "chain_ns_max\n");
    std::mt19937_64 random(7);
    for (const std::size_t mb : sizes_mb) {
        for (const bool huge : {true, false}) {
            const std::size_t count = (mb << 20) / sizeof(Line);
            const auto lines = lines_in_a_cycle(count, huge, random);
            std::vector<std::uint32_t> addresses(reads);
            for (std::uint32_t& a : addresses) a = static_cast<std::uint32_t>(random() % count);
            std::vector<double> rates;
            std::vector<double> latencies;
            std::uint64_t kept = 0;  // what the reads found, printed so that no read can be left out
            for (int round = 0; round < rounds; ++round) {
                auto start = std::chrono::steady_clock::now();
                std::uint64_t sum = 0;
                for (std::size_t k = 0; k < reads; ++k) sum += lines[addresses[k]].word[1 + (k & 3)];
                rates.push_back(static_cast<double>(reads) / seconds_since(start));
                start = std::chrono::steady_clock::now();
                std::uint64_t at = addresses[0];
                for (std::size_t k = 0; k < chain_reads; ++k) at = lines[at].word[0];
                latencies.push_back(seconds_since(start) / static_cast<double>(chain_reads) * 1e9);
                kept += sum + at;
            }
            std::printf("%zu,%s,%d,%.4g,%.4g,%.4g,%.1f,%.1f,%.1f\n", mb, huge ? "huge" : "small", rounds, median(rates),
                        *std::min_element(rates.begin(), rates.end()), *std::max_element(rates.begin(), rates.end()),
                        median(latencies), *std::min_element(latencies.begin(), latencies.end()),
                        *std::max_element(latencies.begin(), latencies.end()));
            std::fprintf(stderr, "memory: %zu MB in %s pages done (%llu)\n", mb, huge ? "huge" : "small",
                         static_cast<unsigned long long>(kept & 1));
        }
    }
}

}  // namespace bench
