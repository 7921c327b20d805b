#include "search/box_records.hpp"
#include "search/float_transpose.hpp"

#include <array>
#include <cstring>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace particlesim {

namespace {

void records_to_rows_one_by_one(const std::byte* records, std::uint32_t first, std::uint32_t last, RecordRows rows) {
    for (std::uint32_t k = first; k < last; ++k) {
        float floats[8];
        std::memcpy(floats, records + std::size_t{k} * sizeof(BoxRecord), sizeof floats);
        for (int f = 0; f < 8; ++f) rows[f][k] = floats[f];
    }
}

#if defined(__x86_64__)
// Sixteen records (a 16 x 8 matrix of floats in eight registers, two records
// each) turned into eight rows of sixteen in three rounds of eight two-source
// permutations. Each register's content is a list of (record, float) pairs,
// lane by lane; a permutation's indices are found by looking each wanted pair
// up in its two sources' lists.
struct Element {
    int record = 0;
    int field = 0;
};
using Layout = std::array<Element, 16>;

constexpr std::array<int, 16> permutation(const Layout& wanted, const Layout& first, const Layout& second) {
    std::array<int, 16> index{};
    for (int lane = 0; lane < 16; ++lane) {
        for (int from = 0; from < 32; ++from) {
            const Element& e = from < 16 ? first[from] : second[from - 16];
            if (e.record == wanted[lane].record && e.field == wanted[lane].field) index[lane] = from;
        }
    }
    return index;
}

// The registers' contents after each round. Loaded: register j holds records
// 2j and 2j + 1. Round one: registers j and j + 4 give the records {2j, 2j +
// 1, 2j + 8, 2j + 9}, floats 0 to 3 (half 0) or 4 to 7 (half 1). Round two:
// those of j and j + 2 give eight records and two floats. Round three: the
// rows, sixteen records in order.
constexpr Layout loaded(int j) {
    Layout layout{};
    for (int lane = 0; lane < 16; ++lane) layout[lane] = {2 * j + lane / 8, lane % 8};
    return layout;
}
constexpr std::array<int, 4> round_one_records(int j) { return {2 * j, 2 * j + 1, 2 * j + 8, 2 * j + 9}; }
constexpr Layout round_one(int j, int half) {
    Layout layout{};
    for (int lane = 0; lane < 16; ++lane) layout[lane] = {round_one_records(j)[lane / 4], 4 * half + lane % 4};
    return layout;
}
constexpr Layout round_two(int j, int half, int pair) {
    const std::array<int, 4> low = round_one_records(j);
    const std::array<int, 4> high = round_one_records(j + 2);
    const std::array<int, 8> records{low[0], low[1], low[2], low[3], high[0], high[1], high[2], high[3]};
    Layout layout{};
    for (int lane = 0; lane < 16; ++lane) layout[lane] = {records[lane / 2], 4 * half + 2 * pair + lane % 2};
    return layout;
}
constexpr Layout row(int field) {
    Layout layout{};
    for (int lane = 0; lane < 16; ++lane) layout[lane] = {lane, field};
    return layout;
}

struct Permutations {
    std::array<std::array<int, 16>, 8> one, two, three;
};
constexpr Permutations permutations() {
    Permutations p{};
    for (int j = 0; j < 4; ++j) {
        for (int half = 0; half < 2; ++half)
            p.one[2 * j + half] = permutation(round_one(j, half), loaded(j), loaded(j + 4));
    }
    for (int j = 0; j < 2; ++j) {
        for (int half = 0; half < 2; ++half) {
            for (int pair = 0; pair < 2; ++pair) {
                p.two[4 * j + 2 * half + pair] =
                    permutation(round_two(j, half, pair), round_one(j, half), round_one(j + 2, half));
            }
        }
    }
    for (int field = 0; field < 8; ++field) {
        const int half = field / 4;
        const int pair = field % 4 / 2;
        p.three[field] = permutation(row(field), round_two(0, half, pair), round_two(1, half, pair));
    }
    return p;
}
constexpr Permutations record_permutations = permutations();

[[gnu::target("avx512f")]] __m512i indices(const std::array<int, 16>& index) {
    return _mm512_loadu_si512(index.data());
}

[[gnu::target("avx512f")]] void records_to_rows_sixteen(const std::byte* records, std::uint32_t count,
                                                        RecordRows rows) {
    const Permutations& p = record_permutations;
    __m512i one[8], two[8], three[8];
    for (int k = 0; k < 8; ++k) {
        one[k] = indices(p.one[k]);
        two[k] = indices(p.two[k]);
        three[k] = indices(p.three[k]);
    }
    std::uint32_t k = 0;
    for (; k + 16 <= count; k += 16) {
        // (Intrinsic loads may read any type's bytes.)
        const auto* from = reinterpret_cast<const float*>(records + std::size_t{k} * sizeof(BoxRecord));
        __m512 loaded_registers[8];
        for (int j = 0; j < 8; ++j) loaded_registers[j] = _mm512_loadu_ps(from + 16 * j);
        __m512 first[8];
        for (int j = 0; j < 4; ++j) {
            for (int half = 0; half < 2; ++half) {
                first[2 * j + half] =
                    _mm512_permutex2var_ps(loaded_registers[j], one[2 * j + half], loaded_registers[j + 4]);
            }
        }
        __m512 second[8];
        for (int j = 0; j < 2; ++j) {
            for (int half = 0; half < 2; ++half) {
                for (int pair = 0; pair < 2; ++pair) {
                    const int at = 4 * j + 2 * half + pair;
                    second[at] = _mm512_permutex2var_ps(first[2 * j + half], two[at], first[2 * (j + 2) + half]);
                }
            }
        }
        for (int field = 0; field < 8; ++field) {
            const int half = field / 4;
            const int pair = field % 4 / 2;
            _mm512_storeu_ps(rows[field] + k, _mm512_permutex2var_ps(second[2 * half + pair], three[field],
                                                                     second[4 + 2 * half + pair]));
        }
    }
    records_to_rows_one_by_one(records, k, count, rows);
}

// Eight records (an 8 x 8 matrix of floats) turned into eight rows of eight
// by transpose_eight().
[[gnu::target("avx2")]] void records_to_rows_eight(const std::byte* records, std::uint32_t count, RecordRows rows) {
    std::uint32_t k = 0;
    for (; k + 8 <= count; k += 8) {
        // (Intrinsic loads may read any type's bytes.)
        const auto* from = reinterpret_cast<const float*>(records + std::size_t{k} * sizeof(BoxRecord));
        __m256 record[8];
        for (int j = 0; j < 8; ++j) record[j] = _mm256_loadu_ps(from + 8 * j);
        __m256 row[8];
        transpose_eight(record, row);
        for (int field = 0; field < 8; ++field) _mm256_storeu_ps(rows[field] + k, row[field]);
    }
    records_to_rows_one_by_one(records, k, count, rows);
}
#endif

}  // namespace

void records_to_rows(const std::byte* records, std::uint32_t count, RecordRows rows, int lanes) {
#if defined(__x86_64__)
    if (lanes == 16) {
        records_to_rows_sixteen(records, count, rows);
        return;
    }
    if (lanes == 8) {
        records_to_rows_eight(records, count, rows);
        return;
    }
#endif
    (void)lanes;
    records_to_rows_one_by_one(records, 0, count, rows);
}

}  // namespace particlesim
