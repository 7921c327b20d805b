// The exact engine's large arrays, and the apps' large blocks, ask for
// transparent huge pages, or for small ones with PARTICLESIM_HUGE_PAGES=0:
// the request reaches the kernel (the array's mapping in /proc/self/smaps),
// and the engine gives the same bytes either way. The setting is read once a process, so each case runs
// this program again, as a child with the environment it needs.

#include "check.hpp"
#include "common/large_blocks.hpp"
#include "core/huge_page_allocator.hpp"
#include "run_process.hpp"
#include "state_hash.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/random_scene.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

std::string self;  // this program, run again as a child

// The huge pages (kB) of the mapping that holds `address`, -1 if none is found.
long huge_kilobytes_at(std::uintptr_t address) {
    std::ifstream maps("/proc/self/smaps");
    bool inside = false;
    for (std::string line; std::getline(maps, line);) {
        unsigned long start = 0;
        unsigned long end = 0;
        if (std::sscanf(line.c_str(), "%lx-%lx ", &start, &end) == 2) {
            inside = start <= address && address < end;
        } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
            return std::strtol(line.c_str() + 14, nullptr, 10);
        }
    }
    return -1;
}

// The child's part: a 16 MiB array of the allocator, every page touched;
// prints the huge pages (kB) of its mapping.
int print_huge_kilobytes_of_an_array() {
    HugePageVector<std::uint64_t> array(std::size_t{2} << 20, 1);
    std::printf("%ld\n", huge_kilobytes_at(reinterpret_cast<std::uintptr_t>(array.data())));
    return 0;
}

// The child's part: a 16 MiB std::vector, from the apps' operator new
// (apps/common/large_blocks.cpp, linked into this test as into simcli),
// every page touched; prints the huge pages (kB) of the mapping that holds
// its middle (madvise makes the whole huge pages inside the block a mapping
// of their own).
int print_huge_kilobytes_of_a_block() {
    std::vector<std::uint64_t> block(std::size_t{2} << 20, 1);
    std::printf("%ld\n", huge_kilobytes_at(reinterpret_cast<std::uintptr_t>(block.data() + block.size() / 2)));
    return 0;
}

// The child's part: 2 steps of the exact engine on 70 000 disks at area
// fraction 0.3 (its predictions and cell links above the allocator's 4
// MiB); prints the final state's hash.
int print_hash_of_an_exact_run() {
    constexpr std::size_t disks = 70000;
    const World world{std::sqrt(disks * std::numbers::pi / 0.3), 1.0};
    ExactSimulation exact(world, make_random_particles(disks, world, {11, SpeedRange{0.1, 1.0}}));
    run(exact, 2);
    std::printf("%llu\n", static_cast<unsigned long long>(state_hash::hash(exact.particles())));
    return 0;
}

// This program as a child with PARTICLESIM_HUGE_PAGES set to `setting`
// (nullptr: unset), doing `part`; its output.
std::string child(const char* setting, const char* part) {
    if (setting != nullptr) {
        setenv("PARTICLESIM_HUGE_PAGES", setting, 1);
    } else {
        unsetenv("PARTICLESIM_HUGE_PAGES");
    }
    const run_process::Result r = run_process::run(self, {part});
    unsetenv("PARTICLESIM_HUGE_PAGES");
    CHECK_EQ(r.status, 0);
    return r.out;
}

// The system's setting: "always", "madvise" or "never" (the bracketed word).
std::string transparent_huge_pages() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string text;
    std::getline(in, text);
    const auto open = text.find('[');
    const auto close = text.find(']');
    return open == std::string::npos || close == std::string::npos ? "" : text.substr(open + 1, close - open - 1);
}

void the_request_reaches_the_kernel() {
    // Asked for small pages, none is huge, whatever the system's setting.
    for (int k = 0; k < 3; ++k) {
        CHECK_EQ(std::stol(child("0", "--probe-pages")), 0L);
        if (PARTICLESIM_LARGE_BLOCKS_OFFERED) CHECK_EQ(std::stol(child("0", "--probe-block")), 0L);
    }
    const std::string system = transparent_huge_pages();
    if (system != "madvise" && system != "always") {
        std::printf("SKIPPED (in part): transparent huge pages are \"%s\" here, so no array gets them\n",
                    system.c_str());
        return;
    }
    // Asked for huge pages (the default, or 1), they come: a hint the kernel
    // may refuse where memory is too fragmented, so three tries each.
    for (const char* setting : {static_cast<const char*>(nullptr), "1"}) {
        long huge = 0;
        for (int k = 0; k < 3 && huge <= 0; ++k) huge = std::stol(child(setting, "--probe-pages"));
        std::printf("PARTICLESIM_HUGE_PAGES %s: %ld kB of the 16 MiB array in huge pages\n",
                    setting ? setting : "unset", huge);
        CHECK(huge >= 2048);
    }
    // The apps' large blocks likewise: at least the 14 MiB of whole huge
    // pages inside a 16 MiB block that malloc places anywhere.
    if (!PARTICLESIM_LARGE_BLOCKS_OFFERED) {
        std::printf("SKIPPED (in part): this build's operator new is the sanitizer's, which offers no huge pages\n");
        return;
    }
    long huge = 0;
    for (int k = 0; k < 3 && huge < 14336; ++k) huge = std::stol(child(nullptr, "--probe-block"));
    std::printf("the apps' operator new: %ld kB of a 16 MiB block in huge pages\n", huge);
    CHECK(huge >= 14336);
}

void the_same_bytes_either_way() {
    const std::string huge = child(nullptr, "--exact-run");
    CHECK(!huge.empty());
    CHECK_EQ(child("0", "--exact-run"), huge);
    CHECK_EQ(child("1", "--exact-run"), huge);
}

}  // namespace

int main(int argc, char** argv) {
    self = argv[0];
    if (argc == 2 && std::string(argv[1]) == "--probe-pages") return print_huge_kilobytes_of_an_array();
    if (argc == 2 && std::string(argv[1]) == "--probe-block") return print_huge_kilobytes_of_a_block();
    if (argc == 2 && std::string(argv[1]) == "--exact-run") return print_hash_of_an_exact_run();
    run_process::children_without_leak_checks();
    return check::run(argc, argv, "test_huge_pages",
                      {{"the request reaches the kernel", the_request_reaches_the_kernel},
                       {"the same bytes either way", the_same_bytes_either_way}});
}
