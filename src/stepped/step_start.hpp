#pragma once
// What a (micro-)step's stages read of the state at its start besides the
// particles: each particle's first wall time, and per block of particles its
// number of wall candidates and the sums the grid search sizes its layout
// from. Measured in one pass over the particles, either afresh or by the
// previous step's free flight as it moves them: then the step starts without
// a pass of its own (docs/benchmarks.md).

#include "core/box.hpp"
#include "core/physics.hpp"
#include "particlesim/particle.hpp"

#include <algorithm>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace particlesim {

// Particles a block holds. Sums are added within a block, then block by
// block: the same totals (and so the same grid, and pair tests counted)
// whatever the thread count.
inline constexpr std::int64_t motion_block = 4096;

// The motion of a block of particles within a step of `duration`: a path
// ends at the particle's wall time or at the end of the step.
struct MotionSums {
    double length_sum = 0.0;   // of the paths of the particles present
    double max_speed = 0.0;    // of every particle
    std::int64_t present = 0;  // particles whose path is longer than an instant

    void add(const Vec2& velocity, double wall_time, double duration) {
        const double end = std::min(duration, wall_time);
        const double speed = velocity.norm();
        max_speed = std::max(max_speed, speed);
        if (end > 0.0) {
            ++present;
            length_sum += speed * end;
        }
    }
    void add(const MotionSums& other) {
        length_sum += other.length_sum;
        present += other.present;
        max_speed = std::max(max_speed, other.max_speed);
    }
};

// A block's figures: its wall candidates and its motion.
struct BlockStart {
    std::uint32_t wall_candidates = 0;
    MotionSums motion;

    // Measures one particle of the block and returns its wall time. Inline:
    // it runs once per particle and step, on a block's figures kept in
    // registers by the caller.
    template <bool with_motion>
    double measure(const Particle& particle, const Box& box, double duration) {
        return count<with_motion>(particle.velocity, time_to_wall(particle.position, particle.velocity, box).time,
                                  duration);
    }
    // The same for a particle whose wall time is known.
    template <bool with_motion>
    double count(const Vec2& velocity, double wall_time, double duration) {
        wall_candidates += wall_time <= duration ? 1U : 0U;
        if constexpr (with_motion) motion.add(velocity, wall_time, duration);
        return wall_time;
    }
};

struct StepStart {
    // Whether the wall times and the blocks' figures are those of the
    // particles as they are now; anything that moves or reorders them
    // without measuring them again clears it.
    bool measured = false;
    // Whether the blocks' motion is summed too (a square root a particle):
    // only the grid search reads it.
    bool with_motion = false;
    std::vector<BlockStart> blocks;
    std::vector<std::uint32_t> first_candidate;  // by block, and one past the last: where its candidates go

    void resize(std::size_t particles) {
        const auto count = static_cast<std::int64_t>(particles);
        blocks.resize(static_cast<std::size_t>((count + motion_block - 1) / motion_block));
        first_candidate.resize(blocks.size() + 1);
    }

    // body(std::bool_constant<with_motion>{}): one loop compiled for each case.
    template <typename Body>
    void with_or_without_motion(Body&& body) const {
        if (with_motion) {
            body(std::true_type{});
        } else {
            body(std::false_type{});
        }
    }
};

}  // namespace particlesim
