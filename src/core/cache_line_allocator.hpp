#pragma once
// An allocator whose arrays start on a 64-byte line, so that a loop reading
// them sixteen floats at a time never splits a load across two lines (the
// paths search's lines: 0.99 of the default scene's time against arrays
// aligned only to 16 bytes, docs/benchmarks.md).

#include <cstddef>
#include <new>
#include <vector>

namespace particlesim {

template <typename T>
class CacheLineAllocator {
public:
    using value_type = T;
    static constexpr std::size_t line = 64;

    CacheLineAllocator() = default;
    template <typename U>
    explicit CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}

    [[nodiscard]] T* allocate(std::size_t count) {
        if (count > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(::operator new (count * sizeof(T), std::align_val_t{line}));
    }
    void deallocate(T* memory, std::size_t) noexcept {
        ::operator delete (memory, std::align_val_t{line});  // unsized: clang needs no -fsized-deallocation
    }

    template <typename U>
    bool operator==(const CacheLineAllocator<U>&) const noexcept {
        return true;
    }
};

template <typename T>
using CacheLineVector = std::vector<T, CacheLineAllocator<T>>;

}  // namespace particlesim
