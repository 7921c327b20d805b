// The apps' global operator new and delete: glibc's malloc and free, with
// the whole huge pages inside every block from 2 MiB on offered to
// transparent huge pages (madvise) before its first touch, as
// GLIBC_TUNABLES=glibc.malloc.hugetlb=1 offers them. Where the system leaves
// huge pages to programs (Debian's default) and a page's first touch is
// slow, as on a virtual machine (about 10 us a 4 KiB page on the benchmark
// host), a large scene's whole run then takes far less time: a million
// disks' one step in 0.61 of it (docs/benchmarks.md, "The apps' large
// blocks in huge pages"). Only a program may replace operator new, so the
// library cannot do this for its users; its exact engine's arrays ask for
// huge pages themselves (src/core/huge_page_allocator.hpp, whose reading of
// PARTICLESIM_HUGE_PAGES offering() repeats: the apps see no internal
// header). PARTICLESIM_HUGE_PAGES=0 asks for small pages instead
// (MADV_NOHUGEPAGE, which also holds where the system gives huge pages to
// all); sanitized builds keep the sanitizers' own operators
// (large_blocks.hpp).

#include "common/large_blocks.hpp"

#include <cstdint>
#include <cstdlib>
#include <new>
#include <string_view>

#if PARTICLESIM_LARGE_BLOCKS_OFFERED

namespace {

constexpr std::uintptr_t huge_page = std::uintptr_t{2} << 20;
constexpr std::size_t offered_from = std::size_t{2} << 20;

// Unless PARTICLESIM_HUGE_PAGES is 0 (then small pages are asked for, as
// the library asks for its arrays), read once.
bool offering() {
    static const bool offered = [] {
        const char* setting = std::getenv("PARTICLESIM_HUGE_PAGES");
        return setting == nullptr || std::string_view(setting) != "0";
    }();
    return offered;
}

// A block of `bytes` from malloc, the whole huge pages inside it offered
// (a hint: refused, nothing changes). Not rounded up to whole huge pages:
// their untouched ends would add to the memory a run holds.
void* block_of(std::size_t bytes) {
    void* block = std::malloc(bytes == 0 ? 1 : bytes);
    if (block == nullptr || bytes < offered_from) return block;
    const auto first = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t start = (first + huge_page - 1) & ~(huge_page - 1);
    const std::uintptr_t end = (first + bytes) & ~(huge_page - 1);
    if (end > start) madvise(reinterpret_cast<void*>(start), end - start, offering() ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
    return block;
}

// As the standard's operator new: a block, and on failure the new handler
// until there is none.
void* allocate(std::size_t bytes) {
    for (;;) {
        if (void* block = block_of(bytes)) return block;
        const std::new_handler handler = std::get_new_handler();
        if (handler == nullptr) throw std::bad_alloc();
        handler();
    }
}

}  // namespace

// The nothrow and aligned forms are the runtime's: the first call these,
// the second allocate apart (aligned_alloc and free), and neither needs a hint.
void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t) noexcept { std::free(block); }

#endif
