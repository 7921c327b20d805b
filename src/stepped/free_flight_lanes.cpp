#include "stepped/free_flight_lanes.hpp"

#include "core/avx512_lanes.hpp"
#include "core/collision.hpp"
#include "core/four_motion_lanes.hpp"
#include "core/four_particles.hpp"

#include <bit>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace particlesim {

#if defined(__x86_64__)

namespace {

// The lanes of the four particles' pairs of lanes, from a mask with a bit a particle.
unsigned pairs_of_lanes(unsigned particles) {
    return ((particles & 1U) * 3U) | ((particles & 2U) * 6U) | ((particles & 4U) * 12U) | ((particles & 8U) * 24U);
}

// Each particle as MotionLanes moves it: fly(), then wall_time().
[[gnu::target("avx512f,avx512vl")]] std::int64_t fly_in_lanes(Particle* particles, std::uint32_t* partner,
                                                              double* wall_time, const Box& box, double step,
                                                              std::int64_t first, std::int64_t last,
                                                              std::uint32_t& wall_candidates) {
    const FourMotionLanes lanes(box);
    const __m512d whole_step = _mm512_set1_pd(step);
    const __m128i none = _mm_set1_epi32(static_cast<int>(no_collision));
    const __m512i even_lanes = _mm512_setr_epi64(0, 2, 4, 6, 0, 2, 4, 6);
    std::uint32_t candidates = 0;
    std::int64_t i = first;
    for (; i + 4 <= last; i += 4) {
        const FourParticles loaded = FourParticles::load(particles + i);
        // A collided particle, resolved already, moves for +0.0.
        const __mmask8 free =
            _mm_cmpeq_epi32_mask(_mm_loadu_si128(reinterpret_cast<const __m128i*>(partner + i)), none);
        const __m512d flight = _mm512_maskz_mov_pd(static_cast<__mmask8>(pairs_of_lanes(free)), whole_step);
        FourInLanes four{loaded.positions(), loaded.velocities()};
        lanes.fly(four, flight);
        const __m512d earliest = lanes.wall_time(four);
        candidates += static_cast<std::uint32_t>(
            std::popcount(static_cast<unsigned>(_mm512_cmp_pd_mask(earliest, whole_step, _CMP_LE_OQ) & 0x55U)));
        _mm512_mask_storeu_pd(wall_time + i, 0x0F, _mm512_maskz_permutexvar_pd(0x0F, even_lanes, earliest));
        loaded.store_with_positions(particles + i, four.where);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(partner + i), none);
    }
    wall_candidates += candidates;
    return i;
}

}  // namespace

std::int64_t fly_four_at_a_time(Particle* particles, std::uint32_t* partner, double* wall_time, const Box& box,
                                double step, std::int64_t first, std::int64_t last, std::uint32_t& wall_candidates) {
    if (!avx512_lanes_available()) return first;
    return fly_in_lanes(particles, partner, wall_time, box, step, first, last, wall_candidates);
}

#else

std::int64_t fly_four_at_a_time(Particle*, std::uint32_t*, double*, const Box&, double, std::int64_t first,
                                std::int64_t, std::uint32_t&) {
    return first;
}

#endif

}  // namespace particlesim
