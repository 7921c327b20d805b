// Storing the particles sorted by position changes no result: the user's
// order comes back on demand, and ties still go by the user's indices.

#include "check.hpp"
#include "example_scenes.hpp"
#include "random_scenes.hpp"
#include "state_hash.hpp"
#include "stress_scenes.hpp"

#include "particlesim/random_scene.hpp"
#include "particlesim/scene_families.hpp"
#include "particlesim/stepped_simulation.hpp"
#include "stepped/storage_order.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

using namespace particlesim;

namespace {

bool identical(std::span<const Particle> a, std::span<const Particle> b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

// Each stored particle is the user's particle user_index[s] (tagged by its
// counter), and stored_index is the inverse map.
bool consistent(std::span<const Particle> stored, const StorageOrder& order) {
    bool ok = order.user_index().size() == stored.size() && order.stored_index().size() == stored.size();
    for (std::uint32_t s = 0; ok && s < stored.size(); ++s) {
        ok = stored[s].wall_collisions == order.user_index()[s] && order.stored_index()[order.user_index()[s]] == s;
    }
    return ok;
}

void sorts_by_rows_and_restores_exactly() {
    const World params{200.0, 1.0};
    const Box box = Box::of(params);
    std::vector<Particle> original = make_random_particles(3000, params, {11, SpeedRange{0.1, 1.0}});
    for (std::size_t i = 0; i < original.size(); ++i) original[i].wall_collisions = i;  // a tag
    std::vector<Particle> stored = original;

    StorageOrder order;
    order.reserve(stored.size());
    CHECK(order.is_user_order());
    CHECK(order.user_index().empty());
    order.sort_by_position(stored, box);
    CHECK(!order.is_user_order());
    CHECK(consistent(stored, order));
    // 3000 particles: 38 x 38 cells (about two a cell), in row-major order.
    const double cell = 200.0 / 38.0;
    const auto cell_of = [&](const Particle& p) {
        return std::floor(p.position.y() / cell) * 38.0 + std::floor(p.position.x() / cell);
    };
    bool ordered = true;
    for (std::size_t s = 1; s < stored.size(); ++s) ordered &= cell_of(stored[s - 1]) <= cell_of(stored[s]);
    CHECK(ordered);

    // Moved (x and y swapped, exactly undone below), then sorted again from
    // the sorted order: still consistent.
    const auto transpose = [&] {
        for (Particle& p : stored) p.position = Vec2(p.position.y(), p.position.x());
    };
    transpose();
    order.sort_by_position(stored, box);
    CHECK(consistent(stored, order));
    transpose();

    order.restore_user_order(stored);
    CHECK(order.is_user_order());
    CHECK(identical(stored, original));
}

using States = example_scenes::States;

// Every state of a run sorted each step against one never sorted, and the
// final states of runs sorted every 3 steps (kept sorted between steps).
void same_as_unsorted(const char* name, const World& params, std::int64_t steps,
                      const std::vector<Particle>& particles) {
    const check::Context context(name);
    Scene scene;
    scene.world = params;
    scene.steps = steps;
    scene.particles = particles;
    for (const int threads : {1, 2}) {
        const States reference = example_scenes::run(scene, {.threads = threads, .sort_by_position_every = 0});
        const States sorted = example_scenes::run(scene, {.threads = threads, .sort_by_position_every = 1});
        bool same = reference.size() == sorted.size();
        for (std::size_t s = 0; same && s < reference.size(); ++s) same = identical(reference[s], sorted[s]);
        if (!same) std::printf("differs: %s, %d thread(s), sorted every step\n", name, threads);
        CHECK(same);

        SteppedSimulation every_third(params, particles, {.threads = threads, .sort_by_position_every = 3});
        particlesim::run(every_third, steps);
        const bool same_end = identical(every_third.particles(), reference.back());
        if (!same_end) std::printf("differs: %s, %d thread(s), sorted every 3 steps\n", name, threads);
        CHECK(same_end);
    }
}

// A gas that two threads share is sorted by default from 8192 disks (the
// threads then write apart), on its schedule only while every state is
// read back: the same states as one thread, never sorted.
void gas_shared_by_two_threads() {
    SceneFamilyOptions options;
    options.particles = 9000;
    options.steps = 20;
    const Scene scene = make_family_scene(SceneFamily::gas, options);
    const States reference = example_scenes::run(scene, {.threads = 1, .sort_by_position_every = 0});
    const States shared = example_scenes::run(scene, {.threads = 2});
    bool same = reference.size() == shared.size();
    for (std::size_t s = 0; same && s < reference.size(); ++s) same = identical(reference[s], shared[s]);
    CHECK(same);
    SteppedSimulation unobserved(scene.world, scene.particles, {.threads = 2});
    particlesim::run(unobserved, scene.steps);
    CHECK(identical(unobserved.particles(), reference.back()));
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_storage_order",
                      {{"storage order changes no result", [] {
                            sorts_by_rows_and_restores_exactly();
                            for (const char* name :
                                 {"corner.in", "crossing.in", "faster_than_box.in", "glancing_line.in", "head_on.in",
                                  "newtons_cradle.in", "square.in", "triangle.in", "wall_then_pair.in"}) {
                                const Scene scene = example_scenes::load(name);
                                same_as_unsorted(name, scene.world, scene.steps, scene.particles);
                            }
                            // Symmetric and tied scenes: ties must still go by the user's indices.
                            for (const NamedScene& s : stress_scenes::all())
                                same_as_unsorted(s.name.c_str(), s.world, s.steps, s.particles);
                            NamedScene crowded = stress_scenes::crowded_box();
                            crowded.steps = 300;
                            same_as_unsorted(crowded.name.c_str(), crowded.world, crowded.steps, crowded.particles);
                            for (std::uint64_t k = 0; k < 60; ++k) {
                                const NamedScene scene = random_scenes::make(k);
                                same_as_unsorted("random scene", scene.world, scene.steps, scene.particles);
                            }
                            gas_shared_by_two_threads();
                        }}});
}
