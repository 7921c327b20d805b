#pragma once
// Four consecutive particles (x, y, vx, vy, pc, wc each: 24 doubles) in the
// three vectors of AVX-512 that hold them, and their fields gathered into
// lanes: positions and velocities as (x, y) in neighbouring lanes, as
// FourMotionLanes takes them, collision counts one a lane. Compiled for
// AVX-512 function by function: include it only where the callers are too,
// and call them only where avx512_lanes_available().

#include "particlesim/particle.hpp"

#include <cstdint>

#if defined(__x86_64__)
#include <immintrin.h>

namespace particlesim {

static_assert(sizeof(Particle) == 6 * sizeof(double), "four particles fill three 512-bit vectors");

struct FourParticles {
    __m512d a;  // doubles 0 to 7: particle k's fields start at 6k
    __m512d b;  // 8 to 15
    __m512d c;  // 16 to 23

    [[gnu::target("avx512f,avx512vl")]] static FourParticles load(const Particle* first) {
        const auto* const doubles = reinterpret_cast<const double*>(first);
        return {_mm512_loadu_pd(doubles), _mm512_loadu_pd(doubles + 8), _mm512_loadu_pd(doubles + 16)};
    }

    // Doubles `from` and `from + 1` of each particle into its two lanes
    // (indices from 8 name b; c's lanes for the last particle).
    [[gnu::target("avx512f,avx512vl")]] __m512d pairs_at(int from) const {
        const __m512i from_ab = _mm512_setr_epi64(from, from + 1, from + 6, from + 7, from + 12, from + 13, 0, 0);
        const __m512i from_c = _mm512_setr_epi64(0, 0, 0, 0, 0, 0, from + 2, from + 3);
        return _mm512_mask_permutexvar_pd(_mm512_permutex2var_pd(a, from_ab, b), 0xC0, from_c, c);
    }
    [[gnu::target("avx512f,avx512vl")]] __m512d positions() const { return pairs_at(0); }
    [[gnu::target("avx512f,avx512vl")]] __m512d velocities() const { return pairs_at(2); }

    // pc + wc of each particle, in lanes 0 to 3 (wrapping as the counts'
    // own unsigned sum does).
    [[gnu::target("avx512f,avx512vl")]] __m256i collision_counts() const {
        const __m512i ai = _mm512_castpd_si512(a);
        const __m512i bi = _mm512_castpd_si512(b);
        const __m512i ci = _mm512_castpd_si512(c);
        const __m512i pcs =
            _mm512_mask_permutexvar_epi64(_mm512_permutex2var_epi64(ai, _mm512_setr_epi64(4, 10, 0, 0, 0, 0, 0, 0), bi),
                                          0x0C, _mm512_setr_epi64(0, 0, 0, 6, 0, 0, 0, 0), ci);
        const __m512i wcs =
            _mm512_mask_permutexvar_epi64(_mm512_permutex2var_epi64(ai, _mm512_setr_epi64(5, 11, 0, 0, 0, 0, 0, 0), bi),
                                          0x0C, _mm512_setr_epi64(0, 0, 1, 7, 0, 0, 0, 0), ci);
        return _mm512_maskz_extracti64x4_epi64(0x0F, _mm512_add_epi64(pcs, wcs), 0);
    }

    // Stores the four particles with their positions from `where` (as
    // positions() gives them); every other field as loaded.
    [[gnu::target("avx512f,avx512vl")]] void store_with_positions(Particle* first, __m512d where) const {
        auto* const doubles = reinterpret_cast<double*>(first);
        _mm512_storeu_pd(doubles,
                         _mm512_mask_permutexvar_pd(a, 0xC3, _mm512_setr_epi64(0, 1, 0, 0, 0, 0, 2, 3), where));
        _mm512_storeu_pd(doubles + 8,
                         _mm512_mask_permutexvar_pd(b, 0x30, _mm512_setr_epi64(0, 0, 0, 0, 4, 5, 0, 0), where));
        _mm512_storeu_pd(doubles + 16,
                         _mm512_mask_permutexvar_pd(c, 0x0C, _mm512_setr_epi64(0, 0, 6, 7, 0, 0, 0, 0), where));
    }
};

}  // namespace particlesim

#endif
