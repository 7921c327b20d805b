#pragma once
// Families of test scenes for people who write or grade their own simulator
// (simgen; docs/checking.md). Every scene lists its particles explicitly and
// is reproducible from its options and seed; write_scene() writes each number
// in the shortest text that reads back to the same double, so a scene means
// the same to every program that reads it.

#include "particlesim/random_scene.hpp"
#include "particlesim/scene.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace particlesim {

enum class SceneFamily {
    random,      // the rules' random scene: what simcli draws for the same N, L, r and seed
    gas,         // random disks at a given area fraction and speed range
    lattice,     // a perturbed triangular lattice: denser than random placement reaches
    line,        // the original design's worst case: N disks in a row moving together
    cradle,      // Newton's cradle: a row of touching disks at rest, one moving into it
    clusters,    // dense clusters in an empty box, drifting into each other
    ties,        // simultaneous collisions by construction, in exact numbers: every tie rule
    fast,        // speeds of several box sides per step
    walls,       // disks starting on the walls, and pairs starting in contact
    crystal,     // a triangular lattice at any area fraction up to close packing, Maxwell velocities
    compressed,  // a random packing grown to an area fraction (Lubachevsky-Stillinger), Maxwell velocities
};

struct SceneFamilyInfo {
    SceneFamily family;
    const char* name;
    const char* description;
};

// Every family, in the order above.
const std::vector<SceneFamilyInfo>& scene_families();
std::optional<SceneFamily> scene_family_named(std::string_view name);

// What a family may be asked for. The radius, steps, mode and seed go to
// every family (those without randomness ignore the seed); each optional
// setting only to the families named beside it, and make_family_scene()
// refuses one given to another family (the ties family, for example, has its
// own particles and box).
struct SceneFamilyOptions {
    std::optional<std::size_t> particles;  // N: every family but ties
    std::int64_t steps = 100;
    OutputMode mode = OutputMode::print;
    std::uint64_t seed = default_seed;
    double radius = 1.0;
    std::optional<double> box_size;       // random, line, fast, walls
    std::optional<double> area_fraction;  // gas, clusters, crystal, compressed
    std::optional<SpeedRange> speeds;     // length per step: not ties, crystal, compressed
    std::optional<double> temperature;    // crystal, compressed: kT, mass 1, in (length per step)^2
    Boundary boundary = Boundary::walls;  // crystal, compressed: a periodic box instead
    // compressed: the diameter's growth per unit time, in units of the thermal speed sqrt(kT / m).
    std::optional<double> growth_rate;
    // compressed: called now and then (every N events of the growth) with the
    // area fraction the growing disks fill and the one they grow to: to show
    // a long compression's progress. It does not change the scene.
    std::function<void(double reached, double target)> compression_progress;
};

// Throws std::invalid_argument for a setting the family has no use for, for
// options the family cannot honour (a
// crystal denser than its lattice fits: the message names the densest; a
// compression above close packing, or one that jams first or runs out of
// events still growing: the message names the fraction reached; a periodic
// start in a box too narrow for the exact engine's periodic box, 5 contact
// distances (a crystal of a few disks); a cradle
// of fewer than 2 disks; more particles than this machine can hold,
// as the scene reader counts them; a radius outside the accepted range,
// world.hpp), and SceneTooFull when random disks do not fit.
Scene make_family_scene(SceneFamily family, const SceneFamilyOptions& options);

// io.md's input format with every particle listed: "N L r S mode" and "i x y vx vy";
// a random scene (Scene::is_random(), as read_scene() returns it) as its
// first lines alone, from which the reader draws the same particles. Throws
// std::invalid_argument, writing nothing, for what the reader would refuse:
// L or r outside the accepted range (world.hpp), S < 0, a mode that is
// neither print nor perf, a coordinate beyond 1e60 or NaN.
void write_scene(std::ostream& out, const Scene& scene);

}  // namespace particlesim
