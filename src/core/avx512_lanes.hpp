#pragma once
// Whether this processor runs the library's AVX-512 loops (F and VL), which
// are compiled for it function by function beside their portable forms and
// chosen at run time: one binary for every x86-64.

namespace particlesim {

#if defined(__x86_64__)
inline bool avx512_lanes_available() {
    static const bool available = [] {
        __builtin_cpu_init();  // in case this first runs before the library's constructors
        return __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512vl") != 0;
    }();
    return available;
}
#else
inline bool avx512_lanes_available() { return false; }
#endif

}  // namespace particlesim
