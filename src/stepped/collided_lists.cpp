#include "stepped/collided_lists.hpp"

#include "core/avx512_lanes.hpp"
#include "core/collision.hpp"

#include <bit>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace particlesim {

namespace {

// One particle at a time, from `i` on: each is written to both lists' next
// places, which only a collision of that kind keeps.
CollidedCounts list_one_at_a_time(const std::uint32_t* partner, std::int64_t i, std::int64_t last,
                                  std::uint32_t* pair_at, std::uint32_t* wall_at, CollidedCounts listed) {
    for (; i < last; ++i) {
        const std::uint32_t other = partner[i];
        const auto at = static_cast<std::uint32_t>(i);
        pair_at[listed.pairs] = at;
        listed.pairs += static_cast<std::size_t>(other < wall_collision) & static_cast<std::size_t>(at < other);
        wall_at[listed.walls] = at;
        listed.walls += static_cast<std::size_t>(other == wall_collision);
    }
    return listed;
}

#if defined(__x86_64__)

[[gnu::target("avx512f")]] CollidedCounts list_sixteen_at_a_time(const std::uint32_t* partner, std::int64_t first,
                                                                 std::int64_t last, std::uint32_t* pair_at,
                                                                 std::uint32_t* wall_at) {
    const __m512i walls = _mm512_set1_epi32(static_cast<int>(wall_collision));
    const __m512i sixteen = _mm512_set1_epi32(16);
    __m512i at = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(first)),
                                  _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
    CollidedCounts listed;
    std::int64_t i = first;
    for (; i + 16 <= last; i += 16) {
        const __m512i other = _mm512_loadu_si512(partner + i);
        const __mmask16 pairs = _mm512_cmplt_epu32_mask(other, walls) & _mm512_cmplt_epu32_mask(at, other);
        const __mmask16 hits = _mm512_cmpeq_epi32_mask(other, walls);
        _mm512_storeu_si512(pair_at + listed.pairs, _mm512_maskz_compress_epi32(pairs, at));
        _mm512_storeu_si512(wall_at + listed.walls, _mm512_maskz_compress_epi32(hits, at));
        listed.pairs += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(pairs)));
        listed.walls += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(hits)));
        at = _mm512_add_epi32(at, sixteen);
    }
    return list_one_at_a_time(partner, i, last, pair_at, wall_at, listed);
}
#endif

}  // namespace

CollidedCounts list_collided(const std::uint32_t* partner, std::int64_t first, std::int64_t last,
                             std::uint32_t* pair_at, std::uint32_t* wall_at) {
#if defined(__x86_64__)
    if (avx512_lanes_available()) return list_sixteen_at_a_time(partner, first, last, pair_at, wall_at);
#endif
    return list_one_at_a_time(partner, first, last, pair_at, wall_at, {});
}

}  // namespace particlesim
