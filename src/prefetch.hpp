#pragma once
// A hint to fetch the line at `address` into the caches, which the program
// keeps even where nothing else happens: GCC deletes loops whose only effect
// is __builtin_prefetch (-ffinite-loops, on from -O2 in C++), so each hint
// also passes its address to an empty volatile asm, an effect it must keep.

namespace particlesim {

inline void prefetch(const void* address) {
    __builtin_prefetch(address);
    asm volatile("" : : "r"(address));
}

}  // namespace particlesim
