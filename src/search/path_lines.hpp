#pragma once
// Every particle's straight path as a line in single precision, and a test
// of one line against all the others in float lanes: which particles could
// ever come within a given distance of this one, were both to keep their
// velocities. For scenes so sparse that a particle changes its velocity a
// few times in its crossing of the box, testing its new line against every
// other line costs less than a spatial search every step.
//
// Two particles' separation moves along a line, so they come within `reach`
// of each other only if that line passes within `reach` of the origin:
// |dp x dv| <= reach |dv|, whatever the time. The lines' points must all be
// taken at one common time (the epoch), and the test looks both ways in time
// (the caller drops meetings in the past); it needs no division and no
// square root.
//
// The test is conservative: rounding to float, and the float arithmetic,
// are covered by a margin derived from the largest coordinate and speed
// stored, so a pair that the double-precision tests would find is never
// dropped; a few more pass. Velocities are scaled by a power of two so that
// the largest is about 1, and positions so that the reach is about 1 (at
// most 2^40 times the box's side): the test's factor of |dv|^2 is then 1,
// one multiplication a line fewer (line_test.hpp), nothing overflows in
// float, and rounding any value (even a tiny one) errs by at most 2^-24 of
// the largest.

#include "core/box.hpp"
#include "core/cache_line_allocator.hpp"
#include "particlesim/particle.hpp"
#include "search/line_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

struct LineQuery;  // one line's test against all (path_lines.cpp)

class PathLines {
public:
    // Tests `lanes` lines at a time: 4 (any processor), 8 (x86-64 with AVX2
    // and FMA) or 16 (AVX-512); 0 picks the widest this processor has. All
    // keep every pair within reach; the tests run each one there is.
    explicit PathLines(int lanes = 0);
    [[nodiscard]] static bool supports_lanes(int lanes);

    // Lines through the particles' positions (all at the epoch) along their
    // velocities; the box sets the position scale and the reach,
    // contact_reach(box).
    void assign(std::span<const Particle> particles, const Box& box);

    // Moves every line's point to a new epoch, position_of(i) for each i;
    // the velocities stay (the particles moved along their lines).
    template <typename PositionOf>
    void move_each(PositionOf&& position_of) {
        Largest largest = largest_;
        for (std::uint32_t i = 0; i < count_; ++i) store_position(i, position_of(i), largest);
        largest_ = largest;
    }

    // Replaces one line: `position` is the particle's position at the epoch
    // (extrapolated back, if it changed velocity after the epoch).
    void set(std::uint32_t i, const Vec2& position, const Vec2& velocity);

    // Appends to `near` every j != i whose line may come within the reach of
    // i's line (see above), in increasing order.
    void gather_near(std::uint32_t i, std::vector<std::uint32_t>& near) const;
    // gather_near() for up to max_block lines at once, *nears[k] for
    // lines[k]: each group of lines is read once for all of them (four
    // queries' temporaries still fit AVX2's sixteen registers).
    static constexpr std::size_t max_block = 4;
    static constexpr std::size_t no_slot = ~std::size_t{0};  // gather_slots(): no own lines to clear
    void gather_near_block(std::span<const std::uint32_t> lines,
                           std::span<std::vector<std::uint32_t>* const> nears) const;

    // The paths search's layout, made afresh from the particles at each
    // micro-step (with the scales assign() chose): the lines of `old_lines`
    // first, then, from a whole group of the widest lanes on, those of
    // `new_lines`, so that gather_new_block() tests a new line against the
    // old lines and only the new ones from its own group on: a pair of new
    // lines once (twice within a group), instead of twice. From then until
    // the next assign(), slots are no longer particles: only arrange() and
    // gather_new_block() may be called.
    void arrange(std::span<const Particle> particles, std::span<const std::uint32_t> old_lines,
                 std::span<const std::uint32_t> new_lines);
    // arrange() with its lists made in the same pass over the particles:
    // particle i's line is new where its collision count (pc + wc) differs
    // from counts[i], or for every particle where `all_new`; counts[i]
    // becomes its count, and new_lines the new lines' particles in
    // increasing order. Four particles at a time where the processor has
    // AVX-512 (avx512_lanes_available()); the same layout either way.
    void arrange_changed(std::span<const Particle> particles, std::span<std::uint64_t> counts, bool all_new,
                         std::vector<std::uint32_t>& new_lines);
    // gather_near_block() after arrange(), for the new lines new_lines[first]
    // to new_lines[first + nears.size() - 1] (at most max_block): appends the
    // particles whose lines may come near each, in no particular order; a
    // pair of new lines may be found from either line or both.
    void gather_new_block(std::size_t first, std::span<std::vector<std::uint32_t>* const> nears) const;

    [[nodiscard]] std::size_t size() const { return count_; }
    // The largest scaled coordinate and velocity component of any line
    // stored since assign(): they set the test's margin for rounding.
    [[nodiscard]] double largest_coordinate() const { return largest_.coordinate; }
    [[nodiscard]] double largest_speed() const { return largest_.speed; }

private:
    // arrange_changed() four particles at a time.
    void arrange_changed_in_lanes(std::span<const Particle> particles, std::span<std::uint64_t> counts, bool all_new,
                                  std::vector<std::uint32_t>& new_lines);
    // Slots [from, end) as padding: lines at rest at the origin, no particle's.
    void pad(std::size_t from, std::size_t end);
    // The test's terms for the lines stored now (line_test.hpp).
    [[nodiscard]] LineTerms terms() const;
    [[nodiscard]] LineQuery query_for(std::uint32_t i, const LineTerms& terms) const;
    // Appends, for each of `count` queries, the slots of [0, first_end) and
    // [second_begin, second_end) whose lines pass the test (each bound a
    // whole number of the widest groups), but the queries' own: query k's
    // line is the slot own_first + k (none where own_first is no_slot).
    void gather_slots(const LineQuery* queries, std::size_t count, std::size_t first_end, std::size_t second_begin,
                      std::size_t second_end, std::size_t own_first, std::vector<std::uint32_t>* const* nears) const;
    // The largest scaled coordinate and velocity component of any line
    // stored since assign(). The stores below update a copy that loops keep
    // in registers (held in the object, it was written back at every line).
    struct Largest {
        double coordinate = 0.0;
        double speed = 0.0;
    };
    // A line scaled into slot `slot`, or only its point.
    void store_line(std::uint32_t slot, const Vec2& position, const Vec2& velocity, Largest& largest) {
        store_position(slot, position, largest);
        const double vx = velocity.x() * velocity_scale_;
        const double vy = velocity.y() * velocity_scale_;
        largest.speed = std::max({largest.speed, std::abs(vx), std::abs(vy)});
        vx_[slot] = static_cast<float>(vx);
        vy_[slot] = static_cast<float>(vy);
    }
    void store_position(std::uint32_t slot, const Vec2& position, Largest& largest) {
        const double x = position.x() * position_scale_;
        const double y = position.y() * position_scale_;
        largest.coordinate = std::max(largest.coordinate, std::max(std::abs(x), std::abs(y)));
        x_[slot] = static_cast<float>(x);
        y_[slot] = static_cast<float>(y);
    }

    int lanes_ = 4;
    std::size_t count_ = 0;
    double position_scale_ = 1.0;  // the reach scaled to about 1
    double velocity_scale_ = 1.0;  // a power of two
    double reach_scaled_ = 0.0;    // contact_reach(box) times position_scale_
    Largest largest_;
    // Scaled, one array per component, padded to a whole number of lane
    // groups (with room for arrange()'s gap), each group on its own lines.
    CacheLineVector<float> x_, y_, vx_, vy_;
    // After arrange(): the particle in each slot (`no_particle` in the
    // padding), the first new line's slot, and the end of the slots in use.
    static constexpr std::uint32_t no_particle = 0xffffffff;
    std::vector<std::uint32_t> particle_in_slot_;
    std::size_t first_new_slot_ = 0;
    std::size_t arranged_end_ = 0;
    // arrange_changed()'s scratch: the old lines' particles (one at a time),
    // or the new lines, scaled, until the old lines' end is known (in lanes).
    std::vector<std::uint32_t> old_lines_;
    std::vector<float> new_x_, new_y_, new_vx_, new_vy_;
};

}  // namespace particlesim
