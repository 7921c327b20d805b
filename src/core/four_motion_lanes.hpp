#pragma once
// MotionLanes for four particles at once, in the eight double lanes of
// AVX-512: each particle's (x, y) in two neighbouring lanes, moved by the
// same IEEE operations on the same values, lane by lane, so the same bits as
// MotionLanes (and physics.hpp) one particle at a time. Compiled for AVX-512
// function by function: include it only where the callers are too, and call
// them only where avx512_lanes_available().

#include "core/box.hpp"
#include "core/physics.hpp"

#if defined(__x86_64__)
#include <immintrin.h>

namespace particlesim {

// Each particle's two lanes, as MotionLanes holds them: where, speed.
struct FourInLanes {
    __m512d where;
    __m512d speed;
};

class FourMotionLanes {
public:
    [[gnu::target("avx512f,avx512vl")]] explicit FourMotionLanes(const Box& box)
        : lower_(_mm512_set1_pd(box.lower)),
          upper_(_mm512_set1_pd(box.upper)),
          zero_(_mm512_setzero_pd()),
          endless_(_mm512_set1_pd(never)) {}

    // MotionLanes::fly().
    [[gnu::target("avx512f,avx512vl")]] void fly(FourInLanes& four, __m512d time) const {
        advance_onto_walls(four, time, 0);
    }

    // MotionLanes::wall_time(), in both lanes of each particle.
    [[gnu::target("avx512f,avx512vl")]] __m512d wall_time(const FourInLanes& four) const {
        __m512d time;
        first_wall(four, time);
        return time;
    }

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

}  // namespace particlesim

#endif
