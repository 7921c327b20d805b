#include "particlesim/random_scene.hpp"

#include "core/box.hpp"
#include "core/random.hpp"
#include "core/uniform_grid.hpp"
#include "input/scene_checks.hpp"
#include "io/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

namespace particlesim {

SpeedRange default_speed_range(const World& world) {
    const double a = world.box_size / (8.0 * world.radius);
    const double b = world.box_size / 4.0;
    return {std::min(a, b), std::max(a, b)};
}

namespace {

// Uniform grid of cells at least one diameter wide, holding the placed disks
// as linked lists, so that an overlap check looks at 3 x 3 cells only.
class PlacementGrid {
public:
    PlacementGrid(std::size_t count, const World& world)
        : grid_(world.box_size, UniformGrid::cells_per_side(world.box_size, 2.0 * world.radius,
                                                            std::floor(std::sqrt(static_cast<double>(count))) + 1.0)),
          head_(grid_.cell_count(), none) {
        next_.reserve(count);
    }

    [[nodiscard]] bool overlaps_any(const Vec2& p, std::span<const Particle> placed, double contact_dist_sq) const {
        const int cx = grid_.column_of(p.x());
        const int cy = grid_.column_of(p.y());
        const int last = grid_.per_side() - 1;
        for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, last); ++y) {
            for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, last); ++x) {
                for (std::uint32_t k = head_[grid_.cell_at(x, y)]; k != none; k = next_[k]) {
                    const Vec2 d = placed[k].position - p;
                    if (d.dot(d) - contact_dist_sq <= 0.0) return true;  // the rules' C <= 0
                }
            }
        }
        return false;
    }

    void add(const Vec2& p, std::uint32_t k) {
        const std::uint32_t at = grid_.cell_of(p);
        next_.push_back(head_[at]);
        head_[at] = k;
    }

private:
    static constexpr std::uint32_t none = 0xffffffffU;

    UniformGrid grid_;
    std::vector<std::uint32_t> head_;
    std::vector<std::uint32_t> next_;
};

}  // namespace

std::vector<Particle> make_random_particles(std::size_t count, const World& world, const RandomSceneOptions& options) {
    const SpeedRange speeds = options.speeds.value_or(default_speed_range(world));
    require_valid_scene("particlesim::make_random_particles", world, {});
    if (!(0.0 <= speeds.min && speeds.min <= speeds.max && speeds.max <= max_magnitude)) {
        // Name the range that was refused: the caller's, or the default one, which reaches L/(8r).
        std::string message = "particlesim::make_random_particles: the speed range ";
        if (!options.speeds) message += "by default, [0, L/(8r)] = ";
        message += '[';
        message += format_brief(speeds.min);
        message += ", ";
        message += format_brief(speeds.max);
        message += ']';
        if (!options.speeds) message += ",";
        message += " must satisfy 0 <= min <= max <= 1e60 (the accepted range)";
        throw std::invalid_argument(message);
    }
    const Box box = Box::of(world);
    const double area_fraction =
        static_cast<double>(count) * std::numbers::pi * world.radius * world.radius / (world.box_size * world.box_size);
    // Random sequential placement jams near an area fraction of 0.55; far
    // beyond that it can only fail, so fail at once rather than search.
    const bool hopeless = count > 16 && area_fraction > 0.7;
    const std::uint64_t max_attempts = 64 * static_cast<std::uint64_t>(count) + 100000;

    const auto too_full = [&](std::uint64_t attempts) {
        return SceneTooFull("cannot place " + std::to_string(count) + " non-overlapping disks of radius " +
                            format_short(world.radius) + " in a box of side " + format_short(world.box_size) +
                            " (area fraction " + format_brief(area_fraction) + ", gave up after " +
                            std::to_string(attempts) + " attempts)");
    };
    if (hopeless) throw too_full(0);

    SplitMix64 rng(options.seed);
    PlacementGrid grid(count, world);
    std::vector<Particle> particles;
    particles.reserve(count);
    std::uint64_t attempts = 0;
    const double span = box.upper - box.lower;
    for (std::size_t k = 0; k < count; ++k) {
        Vec2 position;
        do {
            if (++attempts > max_attempts) throw too_full(attempts - 1);
            position.x() = std::min(box.lower + rng.uniform() * span, box.upper);
            position.y() = std::min(box.lower + rng.uniform() * span, box.upper);
        } while (grid.overlaps_any(position, particles, box.contact_dist_sq));
        grid.add(position, static_cast<std::uint32_t>(k));
        const double speed = speeds.min + rng.uniform() * (speeds.max - speeds.min);
        Particle p;
        p.position = position;
        p.velocity = speed * random_direction(rng);
        particles.push_back(p);
    }
    return particles;
}

}  // namespace particlesim
