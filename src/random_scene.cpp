#include "particlesim/random_scene.hpp"

#include "particlesim/box.hpp"
#include "particlesim/random.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

namespace particlesim {

SpeedRange default_speed_range(const SimParams& params) {
    const double a = params.box_size / (8.0 * params.radius);
    const double b = params.box_size / 4.0;
    return {std::min(a, b), std::max(a, b)};
}

namespace {

// Uniform grid of cells at least one diameter wide, holding the placed disks
// as linked lists, so that an overlap check looks at 3 x 3 cells only.
class PlacementGrid {
public:
    PlacementGrid(std::size_t count, const SimParams& params) {
        const double by_radius = std::floor(params.box_size / (2.0 * params.radius));
        const double by_count = std::floor(std::sqrt(static_cast<double>(count))) + 1.0;
        side_ = static_cast<int>(std::clamp(std::min(by_radius, by_count), 1.0, 65536.0));
        inverse_cell_ = side_ / params.box_size;
        head_.assign(static_cast<std::size_t>(side_) * side_, none);
        next_.reserve(count);
    }

    [[nodiscard]] bool overlaps_any(const Vec2& p, std::span<const Particle> placed, double contact_dist_sq) const {
        const int cx = cell(p.x());
        const int cy = cell(p.y());
        for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, side_ - 1); ++y) {
            for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, side_ - 1); ++x) {
                for (std::uint32_t k = head_[index(x, y)]; k != none; k = next_[k]) {
                    const Vec2 d = placed[k].position - p;
                    if (d.dot(d) - contact_dist_sq <= 0.0) return true;  // the rules' C <= 0
                }
            }
        }
        return false;
    }

    void add(const Vec2& p, std::uint32_t k) {
        const std::size_t at = index(cell(p.x()), cell(p.y()));
        next_.push_back(head_[at]);
        head_[at] = k;
    }

private:
    static constexpr std::uint32_t none = 0xffffffffU;

    [[nodiscard]] int cell(double coordinate) const {
        return std::clamp(static_cast<int>(coordinate * inverse_cell_), 0, side_ - 1);
    }
    [[nodiscard]] std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * side_ + x; }

    int side_ = 1;
    double inverse_cell_ = 1.0;
    std::vector<std::uint32_t> head_;
    std::vector<std::uint32_t> next_;
};

Vec2 random_direction(SplitMix64& rng) {
    for (;;) {
        const double x = 2.0 * rng.uniform() - 1.0;
        const double y = 2.0 * rng.uniform() - 1.0;
        const double norm_sq = x * x + y * y;
        if (norm_sq <= 1.0 && norm_sq > 1e-12) return Vec2(x, y) / std::sqrt(norm_sq);
    }
}

}  // namespace

std::vector<Particle> make_random_particles(std::size_t count, const SimParams& params,
                                            const RandomSceneOptions& options) {
    const SpeedRange speeds = options.speeds.value_or(default_speed_range(params));
    if (!(std::isfinite(speeds.min) && std::isfinite(speeds.max) && 0.0 <= speeds.min && speeds.min <= speeds.max)) {
        throw std::invalid_argument("make_random_particles: speed range must satisfy 0 <= min <= max < inf");
    }
    const Box box = Box::of(params);
    const double area_fraction = static_cast<double>(count) * std::numbers::pi * params.radius * params.radius /
                                 (params.box_size * params.box_size);
    // Random sequential placement jams near an area fraction of 0.55; far
    // beyond that it can only fail, so fail at once rather than search.
    const bool hopeless = count > 16 && area_fraction > 0.7;
    const std::uint64_t max_attempts = 64 * static_cast<std::uint64_t>(count) + 100000;

    const auto too_full = [&](std::uint64_t attempts) {
        return SceneTooFull("cannot place " + std::to_string(count) + " non-overlapping disks of radius " +
                            std::to_string(params.radius) + " in a box of side " + std::to_string(params.box_size) +
                            " (area fraction " + std::to_string(area_fraction) + ", gave up after " +
                            std::to_string(attempts) + " attempts)");
    };
    if (hopeless) throw too_full(0);

    SplitMix64 rng(options.seed);
    PlacementGrid grid(count, params);
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
