#pragma once
// An allocator for the large arrays read at random (the exact engine's
// particles, predictions, queue and cell links): from 4 MiB on, the memory is
// aligned to 2 MiB and Linux is asked to back it with transparent huge
// pages (madvise, where the system leaves that to programs, as Debian
// and Ubuntu do), so that a random read misses the TLB far less often.
// Smaller arrays, and other systems, get plain operator new. The contents
// and every result are the same either way.
//
// PARTICLESIM_HUGE_PAGES=0 in the environment asks for small pages instead
// (MADV_NOHUGEPAGE, which also holds where the system gives huge pages to
// all): on some virtual machines huge pages make many random reads in
// flight slower, not faster (docs/benchmarks.md, "Huge pages for the exact
// engine's arrays").

#include <cstddef>
#include <cstdlib>
#include <new>
#include <string_view>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace particlesim {

// Whether the large arrays ask for huge pages: unless PARTICLESIM_HUGE_PAGES
// is 0 (read once, at the first large array).
inline bool huge_pages_wanted() {
    static const bool wanted = [] {
        const char* setting = std::getenv("PARTICLESIM_HUGE_PAGES");
        return setting == nullptr || std::string_view(setting) != "0";
    }();
    return wanted;
}

template <typename T>
class HugePageAllocator {
public:
    using value_type = T;

    HugePageAllocator() = default;
    template <typename U>
    explicit HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    [[nodiscard]] T* allocate(std::size_t count) {
        if (count > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = count * sizeof(T);
        if (!huge(bytes)) return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
        void* memory = std::aligned_alloc(huge_page, rounded(bytes));
        if (memory == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        // A hint: refused, the pages stay as they are.
        madvise(memory, rounded(bytes), huge_pages_wanted() ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
#endif
        return static_cast<T*>(memory);
    }

    void deallocate(T* memory, std::size_t count) noexcept {
        const std::size_t bytes = count * sizeof(T);
        if (huge(bytes)) {
            std::free(memory);
        } else {
            ::operator delete (memory, std::align_val_t{alignof(T)});  // unsized: clang needs no -fsized-deallocation
        }
    }

    template <typename U>
    bool operator==(const HugePageAllocator<U>&) const noexcept {
        return true;
    }

private:
    static constexpr std::size_t huge_page = std::size_t{2} << 20;
    static constexpr std::size_t from_bytes = std::size_t{4} << 20;
    static bool huge(std::size_t bytes) { return bytes >= from_bytes; }
    static std::size_t rounded(std::size_t bytes) { return (bytes + huge_page - 1) / huge_page * huge_page; }
};

// A vector whose large buffers ask for huge pages.
template <typename T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace particlesim
