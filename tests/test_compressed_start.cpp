// Random dense starts by Lubachevsky-Stillinger growth (simgen compressed):
// every start keeps the dense starts' promises in either box; it is random
// (a liquid's |psi6|, not a lattice's) and reproducible from its seed; the
// same packing at any radius, scaled exactly; the exact engine accepts and
// runs it; its progress is reported as it grows; and what cannot be grown
// is refused with the reason: above close packing, a jam (naming the
// fraction reached), a periodic box too narrow.

#include "check.hpp"
#include "dense_start_checks.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/observables.hpp"
#include "particlesim/scene_families.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

SceneFamilyOptions compression(std::size_t count, double fraction, Boundary boundary = Boundary::walls) {
    SceneFamilyOptions o;
    o.particles = count;
    o.area_fraction = fraction;
    o.temperature = 0.5;
    o.boundary = boundary;
    o.steps = 5;
    return o;
}

Scene compressed(const SceneFamilyOptions& o) { return make_family_scene(SceneFamily::compressed, o); }

// The message of the refusal, or "" when the scene was made.
std::string refusal(const SceneFamilyOptions& o) {
    try {
        compressed(o);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

void every_start_keeps_its_promises() {
    for (const Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        const std::vector<std::size_t> counts =
            check::sanitized ? std::vector<std::size_t>{1, 2, 40} : std::vector<std::size_t>{1, 2, 40, 150};
        for (const std::size_t n : counts) {
            for (const double fraction : {0.05, 0.4, 0.7, 0.8}) {
                check::Context context(boundary == Boundary::walls ? "walls" : "periodic", ", N = ", n, ", fraction ",
                                       fraction);
                const SceneFamilyOptions o = compression(n, fraction, boundary);
                const std::string why = refusal(o);
                if (!why.empty()) {
                    // Only few disks refuse: a periodic box under 5 diameters wide, or
                    // walls that leave no room (2 disks fit a walled square up to 0.54).
                    const double diameters = std::sqrt(static_cast<double>(n) * std::numbers::pi / fraction) / 2.0;
                    if (boundary == Boundary::periodic) {
                        CHECK(diameters < 5.001);
                        CHECK(why.find("at least 5 diameters wide") != std::string::npos);
                    } else {
                        CHECK(n <= 40 && fraction > 0.4);
                        CHECK(why.find("jammed at area fraction") != std::string::npos);
                    }
                    continue;
                }
                dense_start::check_start(compressed(o), fraction, 0.5, boundary);
            }
        }
    }
}

// A liquid, not a lattice: its global |psi6| is of order 1 / sqrt(N), while
// a crystal's is near 1; and each seed gives its own packing, every time.
void random_and_reproducible() {
    SceneFamilyOptions o = compression(300, 0.6, Boundary::periodic);
    const Scene scene = compressed(o);
    const double order = hexatic_order(scene.particles, scene.world, Boundary::periodic);
    check::Context context("|psi6| ", order);
    CHECK(order < 0.2);
    const Scene again = compressed(o);
    CHECK(again.particles[123].position == scene.particles[123].position);
    CHECK(again.particles[123].velocity == scene.particles[123].velocity);
    o.seed = 99;
    CHECK(compressed(o).particles[123].position != scene.particles[123].position);
}

// A compression's progress: the fractions it passes on rise towards the one
// asked for, the target comes with each, and the scene is the one made
// without anyone watching.
void its_progress_rises_to_the_fraction() {
    SceneFamilyOptions o = compression(500, 0.72, Boundary::periodic);
    const Scene unwatched = compressed(o);
    std::vector<double> reached;
    bool target_named = true;
    o.compression_progress = [&](double fraction, double target) {
        reached.push_back(fraction);
        target_named = target_named && target == 0.72;
    };
    const Scene watched = compressed(o);
    check::Context context(reached.size(), " reports, the last ", reached.empty() ? 0.0 : reached.back());
    CHECK(reached.size() >= 10);
    CHECK(target_named);
    CHECK(std::is_sorted(reached.begin(), reached.end()));
    CHECK(!reached.empty() && reached.front() < 0.1 && reached.back() > 0.5 && reached.back() <= 0.72);
    bool same = watched.particles.size() == unwatched.particles.size();
    for (std::size_t i = 0; same && i < watched.particles.size(); ++i) {
        same = watched.particles[i].position == unwatched.particles[i].position &&
               watched.particles[i].velocity == unwatched.particles[i].velocity;
    }
    CHECK(same);
}

// The packing is grown in units of its own; the radius asked for only
// scales it, by a power of two exactly.
void the_same_packing_at_any_radius() {
    SceneFamilyOptions o = compression(200, 0.7);
    const Scene unit = compressed(o);
    o.radius = 0.25;
    const Scene quarter = compressed(o);
    CHECK_EQ(quarter.world.box_size, unit.world.box_size / 4.0);
    bool scaled = true;
    for (std::size_t i = 0; i < unit.particles.size(); ++i) {
        scaled = scaled && quarter.particles[i].position == unit.particles[i].position / 4.0;
    }
    CHECK(scaled);
}

// Dense enough for many collisions a disk a step, in either box.
void the_exact_engine_runs_it() {
    for (const Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        const Scene scene = compressed(compression(200, 0.75, boundary));
        dense_start::check_exact_run(scene, boundary, 3, 2000);
    }
}

void what_cannot_be_grown() {
    // At and above close packing (pi / (2 sqrt 3) = 0.9069), and nonsense.
    for (const double fraction : {0.9069, 0.91, 1.0, 0.0, -0.5}) {
        check::Context context("fraction ", fraction);
        CHECK(refusal(compression(100, fraction)).find("below close packing") != std::string::npos);
    }
    // A fast growth jams well below close packing; the refusal says where.
    SceneFamilyOptions fast = compression(300, 0.89);
    fast.growth_rate = 0.3;
    const std::string jammed = refusal(fast);
    check::Context context(jammed);
    const std::size_t at = jammed.find("jammed at area fraction ");
    CHECK(at != std::string::npos);
    if (at != std::string::npos) {
        const double reached = std::strtod(jammed.c_str() + at + 24, nullptr);
        CHECK(reached > 0.6 && reached < 0.89);
    }
    // A growth too slow to reach the fraction within the event budget is not
    // a jam: the refusal asks for a faster growth, not a slower one.
    SceneFamilyOptions slow = compression(16, 0.5);
    slow.growth_rate = 1e-6;
    const std::string too_slow = refusal(slow);
    CHECK(too_slow.find("still growing") != std::string::npos);
    CHECK(too_slow.find("ask for a faster growth rate than 1e-06") != std::string::npos);
    CHECK(too_slow.find("jammed") == std::string::npos);
    for (const double rate : {0.0, -1.0, 100.0}) {
        SceneFamilyOptions o = compression(100, 0.5);
        o.growth_rate = rate;
        CHECK(refusal(o).find("growth rate") != std::string::npos);
    }
    SceneFamilyOptions cold = compression(100, 0.5);
    cold.temperature = -1.0;
    CHECK(refusal(cold).find("the temperature must be in [0, 1e116]") != std::string::npos);
    // So hot that the fastest disks would leave the accepted range: the temperature is named, not a disk.
    SceneFamilyOptions hot = compression(100, 0.5);
    hot.temperature = 1e308;
    CHECK(refusal(hot).find("the temperature must be in [0, 1e116] (speeds within the accepted range), not 1e+308") !=
          std::string::npos);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_compressed_start",
                      {{"every start keeps its promises", every_start_keeps_its_promises},
                       {"random and reproducible", random_and_reproducible},
                       {"its progress rises to the fraction", its_progress_rises_to_the_fraction},
                       {"the same packing at any radius", the_same_packing_at_any_radius},
                       {"the exact engine runs it", the_exact_engine_runs_it},
                       {"what cannot be grown", what_cannot_be_grown}});
}
