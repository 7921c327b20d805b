#pragma once
// A hint to fetch the line at `address` into the caches, which the compiler
// keeps even in a loop that does nothing else: GCC deletes loops whose only
// effect is __builtin_prefetch (-ffinite-loops, on from -O2 in C++), as it
// did to the exact engine's look ahead at first. Each hint also passes its
// address to an empty volatile asm, an effect that must stay. The stepped
// engine's hints sit in loops that do other work, and stay plain
// __builtin_prefetch there.

namespace particlesim {

inline void prefetch(const void* address) {
    __builtin_prefetch(address);
    asm volatile("" : : "r"(address));
}

}  // namespace particlesim
