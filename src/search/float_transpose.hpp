#pragma once
// An 8 x 8 matrix of floats transposed in AVX registers by the usual
// sequence of unpacks, shuffles and lane swaps (24 in all): the grid search
// turns eight records into eight rows with it, and eight lanes' fields into
// eight records.

#if defined(__x86_64__)
#include <immintrin.h>

namespace particlesim {

// out[j][k] = in[k][j].
[[gnu::target("avx2"), gnu::always_inline]] inline void transpose_eight(const __m256 (&in)[8], __m256 (&out)[8]) {
    __m256 pairs[8];  // rows 2m and 2m + 1 interleaved, low and high floats of each half
    for (int m = 0; m < 4; ++m) {
        pairs[2 * m] = _mm256_unpacklo_ps(in[2 * m], in[2 * m + 1]);
        pairs[2 * m + 1] = _mm256_unpackhi_ps(in[2 * m], in[2 * m + 1]);
    }
    __m256 quads[8];  // rows 4q to 4q + 3, one float of each half
    for (int q = 0; q < 2; ++q) {
        const __m256* low = pairs + 4 * q;
        quads[4 * q] = _mm256_shuffle_ps(low[0], low[2], 0x44);
        quads[4 * q + 1] = _mm256_shuffle_ps(low[0], low[2], 0xEE);
        quads[4 * q + 2] = _mm256_shuffle_ps(low[1], low[3], 0x44);
        quads[4 * q + 3] = _mm256_shuffle_ps(low[1], low[3], 0xEE);
    }
    for (int column = 0; column < 4; ++column) {
        out[column] = _mm256_permute2f128_ps(quads[column], quads[4 + column], 0x20);
        out[4 + column] = _mm256_permute2f128_ps(quads[column], quads[4 + column], 0x31);
    }
}

}  // namespace particlesim
#endif
