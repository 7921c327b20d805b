#include "stepped/wall_candidate_lanes.hpp"

#include <bit>
#include <cstddef>
#include "core/avx512_lanes.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace particlesim {

// A record as three 64-bit lanes: the time; the kind (wall: 0) with the
// index in the upper half; the second index (0) and the padding.
static_assert(sizeof(Collision) == 24 && offsetof(Collision, time) == 0 && offsetof(Collision, kind) == 8 &&
                  offsetof(Collision, i) == 12 && offsetof(Collision, j) == 16,
              "a Collision is three 64-bit lanes");
static_assert(static_cast<int>(CollisionKind::wall) == 0);

#if defined(__x86_64__)

namespace {

[[gnu::target("avx512f")]] WallCandidatesWritten write_in_lanes(const double* wall_time, double duration,
                                                                std::int64_t first, std::int64_t last, Collision* out,
                                                                std::size_t room) {
    const __m512d end = _mm512_set1_pd(duration);
    const __m512i eight = _mm512_set1_epi64(8);
    __m512i index = _mm512_add_epi64(_mm512_set1_epi64(first), _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7));
    // Records k = 0 .. 7 from the compressed times (indices 0 .. 7) and
    // indices (8 .. 15), as lanes 3k, 3k + 1 and 3k + 2 of three vectors;
    // the third lane of each record is zero (the mask leaves it out).
    const __m512i first_three = _mm512_setr_epi64(0, 8, 0, 1, 9, 0, 2, 10);
    const __m512i middle_three = _mm512_setr_epi64(0, 3, 11, 0, 4, 12, 0, 5);
    const __m512i last_two = _mm512_setr_epi64(13, 0, 6, 14, 0, 7, 15, 0);
    constexpr __mmask8 first_kept = 0xDB;   // 1101 1011: lanes 2 and 5 zero
    constexpr __mmask8 middle_kept = 0xB6;  // 1011 0110: lanes 0, 3 and 6 zero
    constexpr __mmask8 last_kept = 0x6D;    // 0110 1101: lanes 1, 4 and 7 zero
    std::size_t written = 0;
    std::int64_t i = first;
    for (; i + 8 <= last && written < room; i += 8) {
        const __m512d times = _mm512_loadu_pd(wall_time + i);
        const __mmask8 hits = _mm512_cmp_pd_mask(times, end, _CMP_LE_OQ);
        const auto count = static_cast<std::size_t>(std::popcount(static_cast<unsigned>(hits)));
        if (count == 0) {
            index = _mm512_add_epi64(index, eight);
            continue;
        }
        if (written + count > room) break;  // the rest one at a time, which stops at the room's end
        const __m512i hit_times = _mm512_castpd_si512(_mm512_maskz_compress_pd(hits, times));
        const __m512i hit_indices = _mm512_maskz_slli_epi64(0xFF, _mm512_maskz_compress_epi64(hits, index), 32);
        // The records' 3 x count lanes (at most 24), in three vectors of eight.
        const std::uint32_t lanes = (std::uint32_t{1} << (3U * static_cast<unsigned>(count))) - 1U;
        auto* const lane = reinterpret_cast<std::int64_t*>(out + written);
        _mm512_mask_storeu_epi64(lane, static_cast<__mmask8>(lanes),
                                 _mm512_maskz_permutex2var_epi64(first_kept, hit_times, first_three, hit_indices));
        _mm512_mask_storeu_epi64(lane + 8, static_cast<__mmask8>(lanes >> 8),
                                 _mm512_maskz_permutex2var_epi64(middle_kept, hit_times, middle_three, hit_indices));
        _mm512_mask_storeu_epi64(lane + 16, static_cast<__mmask8>(lanes >> 16),
                                 _mm512_maskz_permutex2var_epi64(last_kept, hit_times, last_two, hit_indices));
        written += count;
        index = _mm512_add_epi64(index, eight);
    }
    return {i, written};
}

}  // namespace

WallCandidatesWritten write_wall_candidates_in_lanes(const double* wall_time, double duration, std::int64_t first,
                                                     std::int64_t last, Collision* out, std::size_t room) {
    if (!avx512_lanes_available()) return {first, 0};
    return write_in_lanes(wall_time, duration, first, last, out, room);
}

#else

WallCandidatesWritten write_wall_candidates_in_lanes(const double*, double, std::int64_t first, std::int64_t,
                                                     Collision*, std::size_t) {
    return {first, 0};
}

#endif

}  // namespace particlesim
