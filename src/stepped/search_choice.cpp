#include "stepped/search_choice.hpp"

#include "search/grid_search.hpp"
#include "search/path_lines.hpp"
#include "stepped/stepped_tuning.hpp"

#include <algorithm>
#include <cmath>

namespace particlesim {

using namespace stepped_tuning;

SearchCosts estimate_search_costs(const World& world, std::span<const Particle> particles, int substeps) {
    SearchCosts costs;
    const auto count = static_cast<double>(particles.size());
    if (particles.empty()) return costs;
    double axis_speeds = 0.0, speeds = 0.0;  // sums of |vx| + |vy| and of |v|, per step
    for (const Particle& p : particles) {
        axis_speeds += std::abs(p.velocity.x()) + std::abs(p.velocity.y());
        speeds += p.velocity.norm();
    }
    const double micro = 1.0 / substeps;
    const double box = world.box_size, r = world.radius;
    // Wall hits at the speeds along each axis over the span; pair collisions
    // along a collision length of 4r through the others' density (within
    // 25 % of the rules' random scenes, which let a particle collide once a
    // micro-step; half a dense gas's, whose lines the near term prices).
    const double span = std::max(box - 2.0 * r, r);
    const double walls = axis_speeds / span;
    const double pairs = 0.5 * speeds * 4.0 * r * (count - 1.0) / (box * box);
    costs.new_lines = (walls + 2.0 * pairs) * micro;
    // The grid's slices, as GridSearch::choose_layout() cuts them.
    const double spacing = box / std::sqrt(count);
    costs.slices = time_slices(speeds / count * micro, slice_sweep_in_spacings * spacing);
    // Each new line is tested against every line; the lines that pass (about
    // 4r / L of them, more in a small box) get the exact interval.
    const bool sixteen_lanes = PathLines::supports_lanes(16);
    const double line_test_ns = sixteen_lanes ? paths_line_test_sixteen_lanes_ns : paths_line_test_ns;
    const double new_line_ns = sixteen_lanes ? paths_new_line_sixteen_lanes_ns : paths_new_line_ns;
    const double per_line_test = line_test_ns + paths_near_line_ns * std::min(1.0, 4.0 * r / box);
    costs.paths_ns = costs.new_lines * (new_line_ns + count * per_line_test);
    const double slice_ns =
        GridSearch::supports_lanes(16) ? grid_particle_slice_sixteen_lanes_ns : grid_particle_slice_ns;
    costs.grid_ns = count * (grid_particle_ns + slice_ns * costs.slices);
    return costs;
}

PairSearch automatic_search(const World& world, std::span<const Particle> particles, int substeps) {
    const std::size_t count = particles.size();
    if (count < brute_force_below) return PairSearch::brute_force;
    if (count > paths_up_to) return PairSearch::grid;
    const SearchCosts costs = estimate_search_costs(world, particles, substeps);
    return costs.paths_ns < costs.grid_ns ? PairSearch::paths : PairSearch::grid;
}

}  // namespace particlesim
