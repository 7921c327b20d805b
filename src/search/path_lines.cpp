#include "search/path_lines.hpp"

#include "core/assert.hpp"
#include "core/avx512_lanes.hpp"
#include "core/four_particles.hpp"
#include "core/lane_choice.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#if defined(__x86_64__)
#include <immintrin.h>
#endif
#include <stdexcept>
#include <string>

namespace particlesim {

struct LineQuery {
    FloatLine line;  // the line tested against all, scaled
    LineTerms terms;
};

namespace {

// Lines tested together by the widest test compiled (two groups of
// AVX-512's sixteen); the arrays are padded to a whole number of them.
constexpr std::size_t widest_lanes = 32;

// `lines` rounded up to a whole number of the widest groups.
std::size_t whole_groups(std::size_t lines) { return (lines + widest_lanes - 1) / widest_lanes * widest_lanes; }

using FourFloats = float __attribute__((vector_size(16)));
using EightFloats = float __attribute__((vector_size(32)));
using SixteenFloats = float __attribute__((vector_size(64)));
using FourInts = std::int32_t __attribute__((vector_size(16)));

// One bit per lane of a comparison's result (all ones or all zeros), lane
// 0 the lowest: on x86-64 the sign bits, four lanes at a time by SSE's
// movmskps (any x86-64 has it; no wider vector is passed by value, which
// would change the calling convention of a build without AVX).
template <typename Mask>
[[gnu::always_inline]] inline std::uint32_t lane_bits(const Mask& mask) {
    constexpr std::size_t lanes = sizeof(Mask) / sizeof(float);
    std::uint32_t bits = 0;
#if defined(__SSE__)
    for (std::size_t quarter = 0; quarter < lanes / 4; ++quarter) {
        FourFloats four;
        std::memcpy(&four, reinterpret_cast<const char*>(&mask) + quarter * sizeof four, sizeof four);
        bits |= static_cast<std::uint32_t>(__builtin_ia32_movmskps(four)) << (4 * quarter);
    }
#else
    for (std::size_t lane = 0; lane < lanes; ++lane) bits |= mask[lane] != 0 ? 1U << lane : 0U;
#endif
    return bits;
}

// Whether any lane of a comparison's result is set: its quarters or'd into
// four lanes first, then one movmskps.
template <typename Mask>
[[gnu::always_inline]] inline bool any_lane(const Mask& mask) {
    FourInts either{};
    for (std::size_t quarter = 0; quarter < sizeof(Mask) / sizeof(FourInts); ++quarter) {
        FourInts four;
        std::memcpy(&four, reinterpret_cast<const char*>(&mask) + quarter * sizeof four, sizeof four);
        either |= four;
    }
    return lane_bits(either) != 0;
}

// One group of stored lines (four, eight or sixteen), as loaded into lanes.
template <typename Floats>
struct LineGroup {
    Floats x, y, vx, vy;
};

// (Vectors are passed by reference only: a wider one passed or returned by
// value would change the calling convention of a build without AVX.)
template <typename Floats>
[[gnu::always_inline]] inline void load_group(const float* x, const float* y, const float* vx, const float* vy,
                                              std::size_t at, LineGroup<Floats>& group) {
    std::memcpy(&group.x, x + at, sizeof(Floats));
    std::memcpy(&group.y, y + at, sizeof(Floats));
    std::memcpy(&group.vx, vx + at, sizeof(Floats));
    std::memcpy(&group.vy, vy + at, sizeof(Floats));
}

// The two sides of the line test (line_test.hpp) for one group: the
// positions are scaled so that the factor of |dv|^2 is 1.
template <typename Floats>
[[gnu::always_inline]] inline void line_test_sides(const LineGroup<Floats>& group, const LineQuery& q, Floats& cross_sq,
                                                   Floats& bound) {
    unit_reach_line_test_sides(group.x, group.y, group.vx, group.vy, q.line, q.terms, cross_sq, bound);
}

// The line test: |dp x dv|^2 <= |dv|^2 + margin_term.
template <typename Floats, typename Mask>
[[gnu::always_inline]] inline void lines_close(const LineGroup<Floats>& group, const LineQuery& q, Mask& close) {
    Floats cross_sq, bound;
    line_test_sides(group, q, cross_sq, bound);
    close = cross_sq <= bound;
}

// Appends first + k to `near` for every bit k set, lowest first.
[[gnu::always_inline]] inline void append_lanes(std::uint64_t bits, std::size_t first,
                                                std::vector<std::uint32_t>& near) {
    for (; bits != 0; bits &= bits - 1) {
        near.push_back(static_cast<std::uint32_t>(first) + static_cast<std::uint32_t>(std::countr_zero(bits)));
    }
}

// What a scan reads (PathLines::gather_slots()): the slots of two ranges,
// each a whole number of the widest groups, and which lanes to clear: query
// k's own line, the slot own_first + k, passes its own test, and each group
// with a passing line goes through the appending (the own lines were half
// of the default scene's such groups).
struct SlotScan {
    std::size_t ranges[2][2];
    std::size_t own_first;  // PathLines::no_slot: none to clear
    std::size_t queries;
};

// The groups of `lanes` that hold the own lines: a group starting at slot j
// holds some when j - first <= span (never when there are none).
struct OwnGroups {
    std::size_t first;
    std::size_t span;
};
[[gnu::always_inline]] inline OwnGroups own_groups(const SlotScan& scan, std::size_t lanes) {
    if (scan.own_first == PathLines::no_slot) return {PathLines::no_slot, 0};
    const std::size_t first = scan.own_first / lanes * lanes;
    return {first, (scan.own_first + scan.queries - 1) / lanes * lanes - first};
}

// The groups of a scan with a passing line, noted by its loop and appended
// to the near lists after it (or when `capacity` are noted): with no
// call in the loop, its queries stay in registers instead of being saved
// around each append (no vector register survives a call), 0.95 of the
// default scene's time. For `queries` queries of `lanes` lines a group,
// each group's bits for all the queries (query k's from bit lanes * k) are
// one word. A block's scans note every group, and the list's end moves on
// only where a bit is set, so that a passing group costs no mispredicted
// branch (with a branch on each group's bits the default scene's step took
// 1.04 times as long; docs/benchmarks.md), in runs of at most `capacity`
// groups; the one-query scans note only the groups with a passing line,
// and append when the notes are full (runs of their own cost the exact
// engine's line search 1.02 to 1.05 of its time).
template <std::size_t lanes, int queries>
class NotedWords {
public:
    static_assert(lanes * queries <= 64, "the queries' bits fit one word");
    static constexpr std::size_t capacity = 64;

    // Notes the group from slot `first` if a bit of its word is set; true
    // when the notes are full, and append_to() must come before the next.
    [[gnu::always_inline]] bool note(std::size_t first, std::uint64_t word) {
        firsts_[noted_] = static_cast<std::uint32_t>(first);
        words_[noted_] = word;
        noted_ += word != 0 ? 1 : 0;
        return noted_ == capacity;
    }
    // The group's word with each query's own line cleared (query k's is the
    // slot own_first + k).
    [[gnu::always_inline]] static std::uint64_t without_own_lines(std::uint64_t word, std::size_t group,
                                                                  std::size_t own_first) {
        for (int k = 0; k < queries; ++k) {
            const std::size_t own = own_first + static_cast<std::size_t>(k);
            if (own - group < lanes) word &= ~(std::uint64_t{1} << (lanes * static_cast<std::size_t>(k) + own - group));
        }
        return word;
    }
    void append_to(std::vector<std::uint32_t>* const* near) {
        constexpr std::uint64_t lane_mask = lanes == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << lanes) - 1;
        for (std::size_t n = 0; n < noted_; ++n) {
            for (int k = 0; k < queries; ++k)
                append_lanes((words_[n] >> (lanes * static_cast<std::size_t>(k))) & lane_mask, firsts_[n], *near[k]);
        }
        noted_ = 0;
    }

private:
    std::uint32_t firsts_[capacity];
    std::uint64_t words_[capacity];
    std::size_t noted_ = 0;
};

// Appends to `near` every line of the scan that passes lines_close(),
// `Floats` lines (four or eight) to a group, two groups at a time:
// nearly every pair of groups has no close line, so one test of all their
// lanes. Always inlined, so that a caller compiled for AVX2 gets
// its lanes.
template <typename Floats>
[[gnu::always_inline]] inline void gather_lanes(const float* x, const float* y, const float* vx, const float* vy,
                                                const SlotScan& scan, const LineQuery& query,
                                                std::vector<std::uint32_t>& near) {
    using Mask = decltype(Floats{} < Floats{});
    constexpr std::size_t lanes = sizeof(Floats) / sizeof(float);
    // A copy: `near` could alias the query as far as the compiler knows.
    const LineQuery q = query;
    using Noted = NotedWords<2 * lanes, 1>;
    const OwnGroups own = own_groups(scan, 2 * lanes);
    Noted noted;
    std::vector<std::uint32_t>* const nears[1] = {&near};
    for (const auto& range : scan.ranges) {
        for (std::size_t j = range[0]; j < range[1];) {
            for (; j < range[1]; j += 2 * lanes) {
                Mask close[2];
                for (std::size_t g = 0; g < 2; ++g) {
                    LineGroup<Floats> group;
                    load_group(x, y, vx, vy, j + g * lanes, group);
                    lines_close(group, q, close[g]);
                }
                std::uint64_t bits;
                if (j - own.first <= own.span) [[unlikely]] {
                    bits = Noted::without_own_lines(lane_bits(close[0]) | std::uint64_t{lane_bits(close[1])} << lanes,
                                                    j, scan.own_first);
                    if (bits == 0) continue;
                } else {
                    if (!any_lane(close[0] | close[1])) continue;
                    bits = lane_bits(close[0]) | std::uint64_t{lane_bits(close[1])} << lanes;
                }
                if (noted.note(j, bits)) {
                    j += 2 * lanes;
                    break;
                }
            }
            noted.append_to(nears);
        }
    }
}

// gather_lanes() for `queries` lines at once (2 to 4), one group at a time,
// each group loaded once for all of them (two groups' temporaries for four
// queries would not fit AVX2's sixteen registers); the passing groups
// noted without a branch (NotedWords).
template <typename Floats, int queries>
[[gnu::always_inline]] inline void gather_lanes_block(const float* x, const float* y, const float* vx, const float* vy,
                                                      const SlotScan& scan, const LineQuery* query,
                                                      std::vector<std::uint32_t>* const* near) {
    using Mask = decltype(Floats{} < Floats{});
    constexpr std::size_t lanes = sizeof(Floats) / sizeof(float);
    using Noted = NotedWords<lanes, queries>;
    LineQuery q[queries];
    for (int k = 0; k < queries; ++k) q[k] = query[k];
    const OwnGroups own = own_groups(scan, lanes);
    Noted noted;
    for (const auto& range : scan.ranges) {
        for (std::size_t j = range[0]; j < range[1];) {
            const std::size_t run_end = std::min(range[1], j + lanes * Noted::capacity);
            for (; j < run_end; j += lanes) {
                LineGroup<Floats> group;
                load_group(x, y, vx, vy, j, group);
                std::uint64_t word = 0;
                for (int k = 0; k < queries; ++k) {
                    Mask close;
                    lines_close(group, q[k], close);
                    word |= std::uint64_t{lane_bits(close)} << (lanes * static_cast<std::size_t>(k));
                }
                if (j - own.first <= own.span) [[unlikely]]
                    word = Noted::without_own_lines(word, j, scan.own_first);
                noted.note(j, word);
            }
            noted.append_to(near);
        }
    }
}

void gather_four(const float* x, const float* y, const float* vx, const float* vy, const SlotScan& scan,
                 const LineQuery& q, std::vector<std::uint32_t>& near) {
    gather_lanes<FourFloats>(x, y, vx, vy, scan, q, near);
}

#if defined(__x86_64__)
[[gnu::target("avx2,fma")]] void gather_eight(const float* x, const float* y, const float* vx, const float* vy,
                                              const SlotScan& scan, const LineQuery& q,
                                              std::vector<std::uint32_t>& near) {
    gather_lanes<EightFloats>(x, y, vx, vy, scan, q, near);
}

// gather_lanes_block() in eight lanes (AVX2), each group's bits for a
// query taken by one vmovmskps of the whole comparison: the generic loop
// moves the two halves and shifts one, which cost most of what the notes
// without a branch gain (docs/benchmarks.md). Written out here, since an AVX builtin
// cannot be called from the generic template (GCC and clang both refuse).
template <int queries>
[[gnu::target("avx2,fma")]] void gather_eight_block(const float* x, const float* y, const float* vx, const float* vy,
                                                    const SlotScan& scan, const LineQuery* query,
                                                    std::vector<std::uint32_t>* const* near) {
    using Noted = NotedWords<8, queries>;
    LineQuery q[queries];
    for (int k = 0; k < queries; ++k) q[k] = query[k];
    const OwnGroups own = own_groups(scan, 8);
    Noted noted;
    for (const auto& range : scan.ranges) {
        for (std::size_t j = range[0]; j < range[1];) {
            const std::size_t run_end = std::min(range[1], j + 8 * Noted::capacity);
            for (; j < run_end; j += 8) {
                LineGroup<EightFloats> group;
                load_group(x, y, vx, vy, j, group);
                std::uint64_t word = 0;
                for (int k = 0; k < queries; ++k) {
                    EightFloats cross_sq, bound;
                    line_test_sides(group, q[k], cross_sq, bound);
                    const auto close = cross_sq <= bound;
                    EightFloats signs;
                    std::memcpy(&signs, &close, sizeof signs);
                    word |= std::uint64_t{static_cast<std::uint32_t>(__builtin_ia32_movmskps256(signs))} << (8 * k);
                }
                if (j - own.first <= own.span) [[unlikely]]
                    word = Noted::without_own_lines(word, j, scan.own_first);
                noted.note(j, word);
            }
            noted.append_to(near);
        }
    }
}

// AVX-512 compares into mask registers, and GCC's vector extension takes a
// sixteen-lane comparison lane by lane to make a vector of it (3.6 times
// the eight lanes' time on the default scene). The sixteen-lane test takes
// its bits from the mask register instead. Its two loops below repeat
// gather_lanes() and gather_lanes_block(): a function compiled for AVX-512
// cannot be inlined into those generic templates (GCC and clang both refuse).
[[gnu::target("avx512f,fma"), gnu::always_inline]] inline __mmask16 close_bits_sixteen(
    const LineGroup<SixteenFloats>& group, const LineQuery& q) {
    SixteenFloats cross_sq, bound;
    line_test_sides(group, q, cross_sq, bound);
    return _mm512_cmp_ps_mask(static_cast<__m512>(cross_sq), static_cast<__m512>(bound), _CMP_LE_OQ);
}

// gather_lanes() in sixteen lanes.
[[gnu::target("avx512f,fma")]] void gather_sixteen(const float* x, const float* y, const float* vx, const float* vy,
                                                   const SlotScan& scan, const LineQuery& query,
                                                   std::vector<std::uint32_t>& near) {
    const LineQuery q = query;  // a copy: `near` could alias the query as far as the compiler knows
    using Noted = NotedWords<32, 1>;
    const OwnGroups own = own_groups(scan, 32);
    Noted noted;
    std::vector<std::uint32_t>* const nears[1] = {&near};
    for (const auto& range : scan.ranges) {
        for (std::size_t j = range[0]; j < range[1];) {
            for (; j < range[1]; j += 32) {
                LineGroup<SixteenFloats> first;
                LineGroup<SixteenFloats> second;
                load_group(x, y, vx, vy, j, first);
                load_group(x, y, vx, vy, j + 16, second);
                std::uint64_t bits = close_bits_sixteen(first, q) | std::uint64_t{close_bits_sixteen(second, q)} << 16;
                if (j - own.first <= own.span) [[unlikely]]
                    bits = Noted::without_own_lines(bits, j, scan.own_first);
                if (bits == 0) [[likely]]
                    continue;
                if (noted.note(j, bits)) {
                    j += 32;
                    break;
                }
            }
            noted.append_to(nears);
        }
    }
}

// gather_lanes_block() in sixteen lanes, its bits taken from the mask
// registers.
template <int queries>
[[gnu::target("avx512f,fma")]] void gather_sixteen_block(const float* x, const float* y, const float* vx,
                                                         const float* vy, const SlotScan& scan, const LineQuery* query,
                                                         std::vector<std::uint32_t>* const* near) {
    using Noted = NotedWords<16, queries>;
    LineQuery q[queries];
    for (int k = 0; k < queries; ++k) q[k] = query[k];
    const OwnGroups own = own_groups(scan, 16);
    Noted noted;
    for (const auto& range : scan.ranges) {
        for (std::size_t j = range[0]; j < range[1];) {
            const std::size_t run_end = std::min(range[1], j + 16 * Noted::capacity);
            for (; j < run_end; j += 16) {
                LineGroup<SixteenFloats> group;
                load_group(x, y, vx, vy, j, group);
                std::uint64_t word = 0;
                for (int k = 0; k < queries; ++k)
                    word |= std::uint64_t{_cvtmask16_u32(close_bits_sixteen(group, q[k]))} << (16 * k);
                if (j - own.first <= own.span) [[unlikely]]
                    word = Noted::without_own_lines(word, j, scan.own_first);
                noted.note(j, word);
            }
            noted.append_to(near);
        }
    }
}

bool cpu_supports_lanes(int lanes) {
    static const bool sixteen = [] {
        __builtin_cpu_init();  // in case this first runs before the library's constructors
        return __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("fma") != 0;
    }();
    static const bool eight = __builtin_cpu_supports("avx2") != 0 && __builtin_cpu_supports("fma") != 0;
    return lanes == 4 || (lanes == 8 && eight) || (lanes == 16 && sixteen);
}
#endif

template <int queries>
void gather_four_block(const float* x, const float* y, const float* vx, const float* vy, const SlotScan& scan,
                       const LineQuery* q, std::vector<std::uint32_t>* const* near) {
    gather_lanes_block<FourFloats, queries>(x, y, vx, vy, scan, q, near);
}

template <int queries>
void gather_block(int lanes, const float* x, const float* y, const float* vx, const float* vy, const SlotScan& scan,
                  const LineQuery* q, std::vector<std::uint32_t>* const* near) {
    switch (lanes) {
#if defined(__x86_64__)
    case 16: gather_sixteen_block<queries>(x, y, vx, vy, scan, q, near); break;
    case 8: gather_eight_block<queries>(x, y, vx, vy, scan, q, near); break;
#endif
    default: gather_four_block<queries>(x, y, vx, vy, scan, q, near); break;
    }
}

// Drops from near[first, end), which is in increasing order, what the lane
// tests let through that is no neighbour of line i: the padding's lines
// (from `count` on, so last) and i's own (always there: it passes its own test).
void drop_non_neighbours(std::uint32_t i, std::size_t count, std::vector<std::uint32_t>& near, std::size_t first) {
    while (near.size() > first && near.back() >= count) near.pop_back();
    const auto own = std::lower_bound(near.begin() + static_cast<std::ptrdiff_t>(first), near.end(), i);
    if (own != near.end() && *own == i) near.erase(own);
}

}  // namespace

bool PathLines::supports_lanes(int lanes) {
#if defined(__x86_64__)
    return cpu_supports_lanes(lanes);
#else
    return lanes == 4;
#endif
}

PathLines::PathLines(int lanes) : lanes_(chosen_lanes(lanes, supports_lanes, "PathLines")) {}

void PathLines::assign(std::span<const Particle> particles, const Box& box) {
    count_ = particles.size();
    double fastest = 0.0;
    for (const Particle& p : particles)
        fastest = std::max({fastest, std::abs(p.velocity.x()), std::abs(p.velocity.y())});
    // The box's side scaled below 1 first, then by up to 2^40 more so that
    // 1.3 times the reach squared (line_test_terms()' factor of |dv|^2) is
    // below 1, with room for the rounding of these products.
    const double side_scale = power_of_two_below(box.side);
    const double reach = contact_reach(box);
    position_scale_ = side_scale * std::min(0x1p40, (1.0 - 0x1p-20) / (std::sqrt(1.3) * reach * side_scale));
    reach_scaled_ = reach * position_scale_;
    velocity_scale_ = power_of_two_below(fastest);
    largest_ = {box.side * position_scale_, 0.0};
    // Room for arrange()'s gap between the old lines and the new.
    for (CacheLineVector<float>* component : {&x_, &y_, &vx_, &vy_})
        component->assign(whole_groups(count_) + widest_lanes, 0.0f);
    for (std::size_t i = 0; i < count_; ++i)
        set(static_cast<std::uint32_t>(i), particles[i].position, particles[i].velocity);
    particle_in_slot_.clear();
    first_new_slot_ = 0;
    arranged_end_ = 0;
}

void PathLines::set(std::uint32_t i, const Vec2& position, const Vec2& velocity) {
    store_line(i, position, velocity, largest_);
}

void PathLines::arrange(std::span<const Particle> particles, std::span<const std::uint32_t> old_lines,
                        std::span<const std::uint32_t> new_lines) {
    if (old_lines.size() + new_lines.size() != count_ || particles.size() != count_)
        throw std::invalid_argument("PathLines::arrange: every line once, old or new");
    first_new_slot_ = whole_groups(old_lines.size());
    arranged_end_ = whole_groups(first_new_slot_ + new_lines.size());
    particle_in_slot_.resize(arranged_end_);
    std::uint32_t slot = 0;
    Largest largest = largest_;
    const auto place = [&](std::span<const std::uint32_t> lines) {
        for (const std::uint32_t i : lines) {
            store_line(slot, particles[i].position, particles[i].velocity, largest);
            particle_in_slot_[slot++] = i;
        }
    };
    place(old_lines);
    pad(slot, first_new_slot_);
    slot = static_cast<std::uint32_t>(first_new_slot_);
    place(new_lines);
    pad(slot, arranged_end_);
    largest_ = largest;
}

void PathLines::pad(std::size_t from, std::size_t end) {
    for (std::size_t slot = from; slot < end; ++slot) {
        x_[slot] = y_[slot] = vx_[slot] = vy_[slot] = 0.0f;
        particle_in_slot_[slot] = no_particle;
    }
}

void PathLines::arrange_changed(std::span<const Particle> particles, std::span<std::uint64_t> counts, bool all_new,
                                std::vector<std::uint32_t>& new_lines) {
    if (particles.size() != count_ || counts.size() != count_)
        throw std::invalid_argument("PathLines::arrange_changed: a particle and a count for every line");
#if defined(__x86_64__)
    if (avx512_lanes_available()) {
        arrange_changed_in_lanes(particles, counts, all_new, new_lines);
        return;
    }
#endif
    // Written without a branch on whether a particle collided: about one in
    // four did, at random, in the default scene's steps.
    new_lines.resize(count_);
    old_lines_.resize(count_);
    std::size_t changed = 0;
    std::size_t kept = 0;
    for (std::uint32_t i = 0; i < count_; ++i) {
        const std::uint64_t count = particles[i].particle_collisions + particles[i].wall_collisions;
        const bool is_new = all_new || count != counts[i];
        new_lines[changed] = i;
        old_lines_[kept] = i;
        changed += static_cast<std::size_t>(is_new);
        kept += static_cast<std::size_t>(!is_new);
        counts[i] = count;
    }
    new_lines.resize(changed);
    old_lines_.resize(kept);
    arrange(particles, old_lines_, new_lines);
}

#if defined(__x86_64__)
// Four particles at a time (FourParticles), each line scaled and rounded to float as
// store_line() does, then compressed to the old lines' end (in place) or
// the new lines' (set aside until the old lines' end is known).
[[gnu::target("avx512f,avx512vl")]] void PathLines::arrange_changed_in_lanes(std::span<const Particle> particles,
                                                                             std::span<std::uint64_t> counts,
                                                                             bool all_new,
                                                                             std::vector<std::uint32_t>& new_lines) {
    const std::size_t count = count_;
    particle_in_slot_.resize(whole_groups(count) + widest_lanes);
    new_lines.resize(count + 4);
    for (std::vector<float>* staged : {&new_x_, &new_y_, &new_vx_, &new_vy_}) staged->resize(count + 4);
    const __m256i x_then_y = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
    const __m512d position_scale = _mm512_set1_pd(position_scale_);
    const __m512d velocity_scale = _mm512_set1_pd(velocity_scale_);
    __m512d largest_coordinate = _mm512_setzero_pd();
    __m512d largest_speed = _mm512_setzero_pd();
    // In locals: the vector stores below may alias anything, so the
    // compiler would read the members' pointers again after each.
    float* const old_lines[4] = {x_.data(), y_.data(), vx_.data(), vy_.data()};
    float* const new_lines_of[4] = {new_x_.data(), new_y_.data(), new_vx_.data(), new_vy_.data()};
    std::uint32_t* const old_particles = particle_in_slot_.data();
    std::uint32_t* const new_particles = new_lines.data();
    std::size_t kept = 0;
    std::size_t changed = 0;
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4) {
        const FourParticles four = FourParticles::load(particles.data() + i);
        // In 256-bit lanes: a masked 512-bit store of the four counts would
        // hold up the next four's load, which its masked-off half overlaps.
        const __m256i totals = four.collision_counts();
        auto* const count_at = reinterpret_cast<__m256i*>(counts.data() + i);
        const __mmask8 fresh =
            all_new ? __mmask8{0x0F} : _mm256_cmpneq_epu64_mask(totals, _mm256_loadu_si256(count_at));
        _mm256_storeu_si256(count_at, totals);
        const auto old = static_cast<__mmask8>(~fresh & 0x0F);
        const __m512d where = _mm512_mul_pd(four.positions(), position_scale);
        const __m512d speed = _mm512_mul_pd(four.velocities(), velocity_scale);
        largest_coordinate = _mm512_maskz_max_pd(0xFF, largest_coordinate, _mm512_abs_pd(where));
        largest_speed = _mm512_maskz_max_pd(0xFF, largest_speed, _mm512_abs_pd(speed));
        const __m256 where_split = _mm256_permutevar8x32_ps(_mm512_maskz_cvtpd_ps(0xFF, where), x_then_y);
        const __m256 speed_split = _mm256_permutevar8x32_ps(_mm512_maskz_cvtpd_ps(0xFF, speed), x_then_y);
        const __m128 component[4] = {_mm256_castps256_ps128(where_split), _mm256_extractf128_ps(where_split, 1),
                                     _mm256_castps256_ps128(speed_split), _mm256_extractf128_ps(speed_split, 1)};
        for (int k = 0; k < 4; ++k) {
            _mm_storeu_ps(old_lines[k] + kept, _mm_maskz_compress_ps(old, component[k]));
            _mm_storeu_ps(new_lines_of[k] + changed, _mm_maskz_compress_ps(fresh, component[k]));
        }
        const __m128i index = _mm_add_epi32(_mm_set1_epi32(static_cast<int>(i)), _mm_setr_epi32(0, 1, 2, 3));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(old_particles + kept), _mm_maskz_compress_epi32(old, index));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(new_particles + changed), _mm_maskz_compress_epi32(fresh, index));
        kept += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(old)));
        changed += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(fresh)));
    }
    double coordinates[8];
    double speeds[8];
    _mm512_storeu_pd(coordinates, largest_coordinate);
    _mm512_storeu_pd(speeds, largest_speed);
    Largest largest{std::max(largest_.coordinate, *std::max_element(coordinates, coordinates + 8)),
                    std::max(largest_.speed, *std::max_element(speeds, speeds + 8))};
    for (; i < count; ++i) {  // the last few, one at a time
        const Particle& p = particles[i];
        const std::uint64_t total = p.particle_collisions + p.wall_collisions;
        const bool fresh = all_new || total != counts[i];
        counts[i] = total;
        // Scaled into the slot past the old lines: kept there, or set aside.
        store_line(static_cast<std::uint32_t>(kept), p.position, p.velocity, largest);
        if (!fresh) {
            particle_in_slot_[kept++] = static_cast<std::uint32_t>(i);
            continue;
        }
        new_x_[changed] = x_[kept];
        new_y_[changed] = y_[kept];
        new_vx_[changed] = vx_[kept];
        new_vy_[changed] = vy_[kept];
        new_lines[changed++] = static_cast<std::uint32_t>(i);
    }
    largest_ = largest;
    first_new_slot_ = whole_groups(kept);
    arranged_end_ = whole_groups(first_new_slot_ + changed);
    pad(kept, first_new_slot_);
    std::copy_n(new_x_.begin(), changed, x_.begin() + static_cast<std::ptrdiff_t>(first_new_slot_));
    std::copy_n(new_y_.begin(), changed, y_.begin() + static_cast<std::ptrdiff_t>(first_new_slot_));
    std::copy_n(new_vx_.begin(), changed, vx_.begin() + static_cast<std::ptrdiff_t>(first_new_slot_));
    std::copy_n(new_vy_.begin(), changed, vy_.begin() + static_cast<std::ptrdiff_t>(first_new_slot_));
    std::copy_n(new_lines.begin(), changed, particle_in_slot_.begin() + static_cast<std::ptrdiff_t>(first_new_slot_));
    pad(first_new_slot_ + changed, arranged_end_);
    particle_in_slot_.resize(arranged_end_);
    new_lines.resize(changed);
}
#else
void PathLines::arrange_changed_in_lanes(std::span<const Particle>, std::span<std::uint64_t>, bool,
                                         std::vector<std::uint32_t>&) {}
#endif

LineTerms PathLines::terms() const {
    const LineTerms terms = line_test_terms(largest_.coordinate, largest_.speed, reach_scaled_);
    PARTICLESIM_ASSERT(terms.reach_term <= 1.0f, "the lines' positions are scaled for a factor of |dv|^2 of 1");
    return terms;
}

LineQuery PathLines::query_for(std::uint32_t i, const LineTerms& terms) const {
    return {{x_[i], y_[i], vx_[i], vy_[i]}, terms};
}

void PathLines::gather_slots(const LineQuery* queries, std::size_t count, std::size_t first_end,
                             std::size_t second_begin, std::size_t second_end, std::size_t own_first,
                             std::vector<std::uint32_t>* const* nears) const {
    const SlotScan scan{{{0, first_end}, {second_begin, second_end}}, own_first, count};
    const float* x = x_.data();
    const float* y = y_.data();
    const float* vx = vx_.data();
    const float* vy = vy_.data();
    static_assert(max_block == 4, "a case below for each block size");
    switch (count) {
    case 1:
        switch (lanes_) {
#if defined(__x86_64__)
        case 16: gather_sixteen(x, y, vx, vy, scan, queries[0], *nears[0]); break;
        case 8: gather_eight(x, y, vx, vy, scan, queries[0], *nears[0]); break;
#endif
        default: gather_four(x, y, vx, vy, scan, queries[0], *nears[0]); break;
        }
        break;
    case 2: gather_block<2>(lanes_, x, y, vx, vy, scan, queries, nears); break;
    case 3: gather_block<3>(lanes_, x, y, vx, vy, scan, queries, nears); break;
    case 4: gather_block<4>(lanes_, x, y, vx, vy, scan, queries, nears); break;
    default: break;
    }
}

void PathLines::gather_new_block(std::size_t first, std::span<std::vector<std::uint32_t>* const> nears) const {
    const std::size_t count = nears.size();
    if (count == 0) return;
    if (count > max_block) throw std::invalid_argument("PathLines::gather_new_block: at most four lines a block");
    const std::size_t first_slot = first_new_slot_ + first;
    if (first_slot + count > arranged_end_ || particle_in_slot_[first_slot + count - 1] == no_particle)
        throw std::invalid_argument("PathLines::gather_new_block: no such new lines (arrange() first)");
    LineQuery q[max_block];
    std::size_t found_from[max_block];
    const LineTerms block_terms = terms();
    for (std::size_t k = 0; k < count; ++k) {
        q[k] = query_for(static_cast<std::uint32_t>(first_slot + k), block_terms);
        found_from[k] = nears[k]->size();
    }
    // The old lines, then the new ones from the block's group on, but the
    // block's own.
    gather_slots(q, count, first_new_slot_, first_slot / widest_lanes * widest_lanes, arranged_end_, first_slot,
                 nears.data());
    // Slots to particles, without the padding.
    for (std::size_t k = 0; k < count; ++k) {
        std::vector<std::uint32_t>& near = *nears[k];
        std::size_t kept = found_from[k];
        for (std::size_t n = found_from[k]; n < near.size(); ++n) {
            const std::uint32_t particle = particle_in_slot_[near[n]];
            near[kept] = particle;
            kept += static_cast<std::size_t>(particle != no_particle);
        }
        near.resize(kept);
    }
}

void PathLines::gather_near_block(std::span<const std::uint32_t> lines,
                                  std::span<std::vector<std::uint32_t>* const> nears) const {
    if (lines.size() > max_block)
        throw std::invalid_argument("PathLines::gather_near_block: at most four lines a block");
    PARTICLESIM_ASSERT(particle_in_slot_.empty(), "lines in slot order: not arranged since assign()");
    LineQuery q[max_block];
    std::size_t first[max_block];
    const LineTerms block_terms = terms();
    for (std::size_t k = 0; k < lines.size(); ++k) {
        q[k] = query_for(lines[k], block_terms);
        first[k] = nears[k]->size();
    }
    // A single line's own lane is cleared in the scan; a block's lines lie
    // anywhere, and drop_non_neighbours() removes them.
    const std::size_t own = lines.size() == 1 ? lines[0] : no_slot;
    gather_slots(q, lines.size(), whole_groups(count_), 0, 0, own, nears.data());
    for (std::size_t k = 0; k < lines.size(); ++k) drop_non_neighbours(lines[k], count_, *nears[k], first[k]);
}

void PathLines::gather_near(std::uint32_t i, std::vector<std::uint32_t>& near) const {
    std::vector<std::uint32_t>* const nears[1] = {&near};
    gather_near_block(std::span(&i, 1), nears);
}

}  // namespace particlesim
