#include "stepped/wall_bounce_lanes.hpp"

#include "core/avx512_lanes.hpp"
#include "core/box.hpp"
#include "core/physics.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace particlesim {

#if defined(__x86_64__)

namespace {

// Each particle's two lanes, as MotionLanes holds them: where, speed.
struct FourInLanes {
    __m512d where;
    __m512d speed;
};

class WallLanes {
public:
    [[gnu::target("avx512f,avx512vl")]] WallLanes(const Box& box)
        : lower_(_mm512_set1_pd(box.lower)),
          upper_(_mm512_set1_pd(box.upper)),
          zero_(_mm512_setzero_pd()),
          endless_(_mm512_set1_pd(never)) {}

    // MotionLanes::bounce().
    [[gnu::target("avx512f,avx512vl")]] void bounce(FourInLanes& four) const {
        __m512d time;
        const __mmask8 on = first_wall(four, time);
        advance_onto_walls(four, time, on);
        const __m512i sign = _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ULL));
        four.speed = _mm512_mask_mov_pd(four.speed, on,
                                        _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(four.speed), sign)));
    }

    // MotionLanes::move_stopping_at_wall(), `remaining` in both lanes of each particle.
    [[gnu::target("avx512f,avx512vl")]] void move_stopping_at_wall(FourInLanes& four, __m512d remaining) const {
        __m512d time;
        const __mmask8 on = first_wall(four, time);
        const __mmask8 stops = _mm512_cmp_pd_mask(time, remaining, _CMP_LE_OQ);
        // std::min(time, remaining)
        const __m512d until = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(remaining, time, _CMP_LT_OQ), time, remaining);
        advance_onto_walls(four, until, on & stops);
    }

private:
    // MotionLanes::first_wall(): the earlier of each particle's two wall
    // times into both its lanes, and the lanes of the walls met then.
    [[gnu::target("avx512f,avx512vl")]] __mmask8 first_wall(const FourInLanes& four, __m512d& time) const {
        const __m512d wall = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(four.speed, zero_, _CMP_LT_OQ), upper_, lower_);
        const __m512d to_wall = _mm512_add_pd(_mm512_div_pd(_mm512_sub_pd(wall, four.where), four.speed), zero_);
        const __m512d times =
            _mm512_mask_blend_pd(_mm512_cmp_pd_mask(four.speed, zero_, _CMP_NEQ_UQ), endless_, to_wall);
        // std::min(times[0], times[1]) in the first lane; in the second the
        // same value (the times are never -0.0, so equal times have equal bits).
        const __m512d swapped = _mm512_shuffle_pd(times, times, 0x55);
        time = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(swapped, times, _CMP_LT_OQ), times, swapped);
        return _mm512_cmp_pd_mask(times, time, _CMP_EQ_OQ) & _mm512_cmp_pd_mask(times, endless_, _CMP_NEQ_UQ);
    }

    // MotionLanes::advance_onto_walls().
    [[gnu::target("avx512f,avx512vl")]] void advance_onto_walls(FourInLanes& four, __m512d time, __mmask8 on) const {
        __m512d at = _mm512_add_pd(four.where, _mm512_mul_pd(four.speed, time));
        at = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(at, lower_, _CMP_LT_OQ), at, lower_);
        at = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(upper_, at, _CMP_LT_OQ), at, upper_);
        const __m512d wall = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(four.speed, zero_, _CMP_LT_OQ), upper_, lower_);
        four.where = _mm512_mask_blend_pd(on, at, wall);
    }

    __m512d lower_;
    __m512d upper_;
    __m512d zero_;
    __m512d endless_;
};

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
    const WallLanes lanes(box);
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
