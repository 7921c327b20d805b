#pragma once
// The one way the library hints a fetch: the line at `address` into the
// caches, a hint the compiler keeps even in a loop that does nothing else: GCC deletes loops whose only
// effect is __builtin_prefetch (-ffinite-loops, on from -O2 in C++), as it
// did to the exact engine's look ahead at first. Each hint also passes its
// address to an empty volatile asm, an effect that must stay (it emits no
// instruction).

namespace particlesim {

inline void prefetch(const void* address) {
    __builtin_prefetch(address);
    asm volatile("" : : "r"(address));
}

// The same, for a line about to be written.
inline void prefetch_for_write(const void* address) {
    __builtin_prefetch(address, 1);
    asm volatile("" : : "r"(address));
}

// Both lines a record may straddle (any record of up to 64 bytes).
template <typename Record>
void prefetch_lines_of(const Record& record) {
    static_assert(sizeof(Record) <= 64);
    prefetch(&record);
    prefetch(reinterpret_cast<const char*>(&record) + sizeof(Record) - 1);
}

}  // namespace particlesim
