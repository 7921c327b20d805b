#pragma once
// Random scenes as rules.md "Random scenes" defines them: non-overlapping
// uniform positions, uniform speeds, uniform directions, reproducible by seed.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

namespace particlesim {

inline constexpr std::uint64_t default_seed = 3210;

struct SpeedRange {
    double min = 0.0;  // length per step
    double max = 0.0;
};

// Between L/(8r) and L/4, whichever is smaller first.
SpeedRange default_speed_range(const World& world);

struct RandomSceneOptions {
    std::uint64_t seed = default_seed;
    std::optional<SpeedRange> speeds = std::nullopt;  // default_speed_range() when empty
};

// The box cannot hold that many non-overlapping disks in reasonable time.
class SceneTooFull : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Draws, particle by particle: a position (x then y, redrawn until it
// overlaps no earlier disk), a speed, then a direction (a point drawn
// uniformly in the unit disk, normalised: no trigonometry, so the result is
// the same on every IEEE-754 platform). Throws SceneTooFull instead of
// searching without end, std::invalid_argument for a bad speed range.
std::vector<Particle> make_random_particles(std::size_t count, const World& world,
                                            const RandomSceneOptions& options = {});

}  // namespace particlesim
