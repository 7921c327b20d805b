#include "stepped/wall_bounce_lanes.hpp"

#include "core/avx512_lanes.hpp"
#include "core/four_motion_lanes.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace particlesim {

#if defined(__x86_64__)

namespace {

[[gnu::target("avx512f,avx512vl")]] __m512d two_lanes_each(const double* values, const std::uint32_t* at) {
    return _mm512_setr_pd(values[at[0]], values[at[0]], values[at[1]], values[at[1]], values[at[2]], values[at[2]],
                          values[at[3]], values[at[3]]);
}

[[gnu::target("avx512f,avx512vl")]] __m512d four_pairs(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    const __m512d low = _mm512_castpd256_pd512(
        _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a.data())), _mm_loadu_pd(b.data()), 1));
    const __m256d high =
        _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(c.data())), _mm_loadu_pd(d.data()), 1);
    return _mm512_maskz_insertf64x4(0xFF, low, high, 1);
}

// Particle `pair`'s two lanes (AVX-512 F has no 64-bit extract: the
// 32-bit one moves the same bits).
[[gnu::target("avx512f,avx512vl")]] void store_pair(Vec2& out, __m512d lanes, int pair) {
    const __m512 bits = _mm512_castpd_ps(lanes);
    __m128 two;
    switch (pair) {
    case 0: two = _mm512_maskz_extractf32x4_ps(0xF, bits, 0); break;
    case 1: two = _mm512_maskz_extractf32x4_ps(0xF, bits, 1); break;
    case 2: two = _mm512_maskz_extractf32x4_ps(0xF, bits, 2); break;
    default: two = _mm512_maskz_extractf32x4_ps(0xF, bits, 3); break;
    }
    _mm_storeu_pd(out.data(), _mm_castps_pd(two));
}

[[gnu::target("avx512f,avx512vl")]] std::size_t resolve_in_lanes(Particle* particles, const std::uint32_t* wall_at,
                                                                 std::size_t count, const double* collision_time,
                                                                 const Box& box, double duration) {
    const FourMotionLanes lanes(box);
    const __m512d step = _mm512_set1_pd(duration);
    std::size_t k = 0;
    for (; k + 4 <= count; k += 4) {
        const std::uint32_t* at = wall_at + k;
        Particle& a = particles[at[0]];
        Particle& b = particles[at[1]];
        Particle& c = particles[at[2]];
        Particle& d = particles[at[3]];
        FourInLanes four{four_pairs(a.position, b.position, c.position, d.position),
                         four_pairs(a.velocity, b.velocity, c.velocity, d.velocity)};
        lanes.bounce(four);
        lanes.move_stopping_at_wall(four, _mm512_sub_pd(step, two_lanes_each(collision_time, at)));
        Particle* const four_particles[4] = {&a, &b, &c, &d};
        for (int p = 0; p < 4; ++p) {
            store_pair(four_particles[p]->position, four.where, p);
            store_pair(four_particles[p]->velocity, four.speed, p);
            ++four_particles[p]->wall_collisions;
        }
    }
    return k;
}

}  // namespace

std::size_t resolve_walls_four_at_a_time(Particle* particles, const std::uint32_t* wall_at, std::size_t count,
                                         const double* collision_time, const Box& box, double duration) {
    if (!avx512_lanes_available()) return 0;
    return resolve_in_lanes(particles, wall_at, count, collision_time, box, duration);
}

#else

std::size_t resolve_walls_four_at_a_time(Particle*, const std::uint32_t*, std::size_t, const double*, const Box&,
                                         double) {
    return 0;
}

#endif

}  // namespace particlesim
