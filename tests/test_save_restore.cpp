// Saving and restoring an engine: a run saved after any step and restored
// (even with other searches or thread counts) goes on bit for bit like the
// uninterrupted run, under both engines and with substeps; a damaged saved
// state is refused with std::invalid_argument, never trusted, and so is an
// exact state whose disks are out of their cells or overlap.

#include "check.hpp"
#include "random_scenes.hpp"
#include "state_hash.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/scene_families.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

template <typename E>
std::vector<std::uint64_t> hashes_of(E& engine, std::int64_t steps) {
    std::vector<std::uint64_t> hashes;
    for (std::int64_t s = 0; s < steps; ++s) {
        engine.step();
        hashes.push_back(state_hash::hash(engine.particles()));
    }
    return hashes;
}

// Runs `stop` steps, saves, restores with `make_restored`, runs on, and
// compares every later step and the totals with the uninterrupted run.
template <typename E, typename Make, typename Restore>
void check_resumes_exactly(Make&& make, Restore&& restore, std::int64_t steps, std::int64_t stop) {
    check::Context context("stopping after step ", stop);
    E whole = make();
    const std::vector<std::uint64_t> expected = hashes_of(whole, steps);
    E first = make();
    hashes_of(first, stop);
    std::stringstream saved;
    first.save(saved);
    E resumed = restore(saved);
    CHECK_EQ(resumed.steps_done(), stop);
    CHECK_EQ(state_hash::hash(resumed.particles()), state_hash::hash(first.particles()));
    const std::vector<std::uint64_t> rest = hashes_of(resumed, steps - stop);
    CHECK(std::equal(rest.begin(), rest.end(), expected.begin() + stop));
    CHECK_EQ(resumed.totals().particle_collisions, whole.totals().particle_collisions);
    CHECK_EQ(resumed.totals().wall_collisions, whole.totals().wall_collisions);
    if constexpr (requires { whole.collision_sums(); }) {
        // The pressure's sums go on from the saved ones, to the same bits.
        CHECK_EQ(resumed.collision_sums().pair_virial, whole.collision_sums().pair_virial);
        CHECK_EQ(resumed.collision_sums().wall_impulse, whole.collision_sums().wall_impulse);
    }
}

void stepped_engine_resumes_bit_for_bit() {
    // Every regime (k mod 5) twice; once under the sanitizers.
    for (std::uint64_t k = 0; k < (check::sanitized ? 5 : 10); ++k) {
        const NamedScene scene = random_scenes::make(k);
        for (const int substeps : {1, 3}) {
            check::Context context("scene ", k, ", substeps ", substeps);
            const auto make = [&] {
                return SteppedSimulation(scene.world, scene.particles, {.threads = 1, .substeps = substeps});
            };
            // Restored with another search and thread count: results must not care.
            const auto restore = [&](std::istream& saved) {
                return SteppedSimulation::restore(
                    scene.world, saved, {.pair_search = PairSearch::brute_force, .threads = 2, .substeps = substeps});
            };
            for (const std::int64_t stop : {std::int64_t{0}, std::int64_t{1}, scene.steps / 2, scene.steps}) {
                check_resumes_exactly<SteppedSimulation>(make, restore, scene.steps, stop);
            }
        }
    }
}

void exact_engine_resumes_bit_for_bit() {
    int tested = 0;
    for (std::uint64_t k = 0; k < 40; ++k) {
        const NamedScene scene = random_scenes::make(k);
        if (estimated_events_per_step(scene.world, scene.particles) * static_cast<double>(scene.steps) > 2e5) continue;
        const auto make = [&] { return ExactSimulation(scene.world, scene.particles); };
        try {
            make();
        } catch (const OverlappingStart&) {
            continue;
        }
        ++tested;
        check::Context context("scene ", k);
        const auto restore = [&](std::istream& saved) { return ExactSimulation::restore(scene.world, saved); };
        // And with one cell: the particles' lines (rebuilt on restoring).
        const auto make_lines = [&] { return ExactSimulation(scene.world, scene.particles, {.cells_per_side = 1}); };
        const auto restore_lines = [&](std::istream& saved) {
            return ExactSimulation::restore(scene.world, saved, {.cells_per_side = 1});
        };
        for (const std::int64_t stop : {std::int64_t{0}, std::int64_t{1}, std::int64_t{7}, scene.steps / 2}) {
            check_resumes_exactly<ExactSimulation>(make, restore, scene.steps, stop);
            check_resumes_exactly<ExactSimulation>(make_lines, restore_lines, scene.steps, stop);
        }
    }
    CHECK(tested >= 10);
}

template <typename E>
void expect_refused(const World& world, const std::string& text, const char* why) {
    check::Context context(why);
    std::istringstream in(text);
    bool refused = false;
    try {
        E::restore(world, in);
    } catch (const std::invalid_argument&) {
        refused = true;
    }
    CHECK(refused);
}

std::string saved_text(auto& engine) {
    std::ostringstream out;
    engine.save(out);
    return out.str();
}

std::vector<std::string> tokens_of(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> tokens;
    for (std::string t; in >> t;) tokens.push_back(t);
    return tokens;
}

// Replaces the n-th whitespace-separated token.
std::string with_token(const std::string& text, std::size_t n, const std::string& token) {
    std::vector<std::string> tokens = tokens_of(text);
    tokens.at(n) = token;
    std::string result;
    for (const std::string& t : tokens) result += t + " ";
    return result;
}

void damaged_states_are_refused() {
    const NamedScene scene = random_scenes::make(0);
    SteppedSimulation stepped(scene.world, scene.particles);
    stepped.step();
    const std::string good_stepped = saved_text(stepped);
    ExactSimulation exact(scene.world, scene.particles);
    exact.step();
    const std::string good_exact = saved_text(exact);
    for (const std::string& good : {good_stepped, good_exact}) {
        const bool is_exact = good == good_exact;
        const auto refused = [&](const std::string& text, const char* why) {
            if (is_exact) {
                expect_refused<ExactSimulation>(scene.world, text, why);
            } else {
                expect_refused<SteppedSimulation>(scene.world, text, why);
            }
        };
        refused("", "empty");
        refused(good.substr(0, good.size() / 2), "truncated");
        refused(with_token(good, 0, "other-engine-state"), "another engine's state");
        refused(with_token(good, 1, is_exact ? "4" : "2"), "another version");
        // The exact engine's state: the header (2 tokens), N, the time, the
        // step, 3 counts, 2 collision sums, the cells a side; then each particle's 6 numbers,
        // its stamp, cell, wall time, crossing (time, cell) and pair event
        // (time, i, j, partner, partner's version).
        const std::size_t first_particle = is_exact ? 11 : 7;
        refused(with_token(good, first_particle, "nan"), "a NaN position");
        refused(with_token(good, first_particle, "1e300"), "a position outside the box");
        refused(with_token(good, first_particle, std::string(100, '1')), "a huge token");
        refused(with_token(good, 2, "4000000000"), "more particles than the file holds");
        if (is_exact) {
            refused(with_token(good, first_particle + 6, "1e9"), "a time stamp in the future");
            refused(with_token(good, first_particle + 7, "99999999"), "a cell outside the grid");
            // Saved after step 1: every event up to it has happened.
            refused(with_token(good, first_particle + 8, "0.5"), "a wall hit before the saved step");
            refused(with_token(good, first_particle + 9, "0.5"), "a crossing before the saved step");
            refused(with_token(good, first_particle + 14, "99999999"), "a partner outside the scene");
            refused(with_token(good, 8, "inf"), "a collision sum that is not finite");
            refused(with_token(good, 9, "nan"), "a NaN collision sum");
            refused(with_token(good, 10, "0"), "no cells");
            refused(with_token(good, 10, "4097"), "more cells than a grid may have");
        }
        refused(with_token(good, 5, "-1"), "a negative count");
    }
    // A saved state for another world is refused when it leaves that box.
    expect_refused<SteppedSimulation>(World{10.0, 1.0}, good_stepped, "a smaller box");
}

// The exact engine's pair prediction names a partner and the pair's event;
// a saved event that does not name the particle and its partner is refused.
void pair_event_of_other_particles_is_refused() {
    const World world{60.0, 1.0};  // 300 disks: area fraction 0.26
    ExactSimulation exact(world, make_random_particles(300, world, {11, SpeedRange{0.1, 1.0}}));
    exact.step();
    const std::string good = saved_text(exact);
    const std::vector<std::string> tokens = tokens_of(good);
    // After the 11 tokens of the header, 16 a particle; its pair event's time
    // is the 12th, then i, j, the partner and its version.
    constexpr std::size_t first_particle = 11;
    std::size_t damaged = 0;
    for (std::size_t k = 0; first_particle + 16 * (k + 1) <= tokens.size() && damaged < 5; ++k) {
        const std::size_t time = first_particle + 16 * k + 11;
        if (tokens[time] == "inf") continue;  // nothing predicted
        expect_refused<ExactSimulation>(world, with_token(good, time + 2, tokens[time + 2] == "0" ? "1" : "0"),
                                        "a pair event of other particles");
        expect_refused<ExactSimulation>(world, with_token(good, time + 3, std::to_string(k)),
                                        "the particle as its own partner");
        expect_refused<ExactSimulation>(world, with_token(good, time, "0.5"), "a pair event before the saved step");
        ++damaged;
    }
    CHECK_EQ(damaged, std::size_t{5});
    std::istringstream in(good);
    CHECK_EQ(ExactSimulation::restore(world, in).steps_done(), 1);  // the undamaged state restores
}

// A saved state whose disks, moved to the saved step, are out of place is
// refused, naming them: a disk outside the cell saved for it (the engine
// would never test it against its neighbours), two disks that overlap.
void disks_out_of_place_are_refused() {
    const World world{60.0, 1.0};
    ExactOptions options;
    options.cells_per_side = 8;  // cells of 7.5, whatever the cost model would take
    ExactSimulation exact(world, make_random_particles(300, world, {11, SpeedRange{0.1, 1.0}}), options);
    exact.step();
    const std::string good = saved_text(exact);
    const std::vector<std::string> tokens = tokens_of(good);
    constexpr std::size_t first_particle = 11, per_particle = 16, cell = 7;
    const auto refused_saying = [&](const std::string& text, const std::string& words) {
        check::Context context(words);
        std::istringstream in(text);
        std::string message;
        try {
            ExactSimulation::restore(world, in);
        } catch (const std::invalid_argument& e) {
            message = e.what();
        }
        check::Context said("message ", message);
        CHECK(message.find(words) != std::string::npos);
    };
    // Disk 0 saved in the cell four columns and four rows on.
    const int saved_cell = std::stoi(tokens.at(first_particle + cell));
    const int elsewhere = ((saved_cell % 8 + 4) % 8) + 8 * ((saved_cell / 8 + 4) % 8);
    refused_saying(with_token(good, first_particle + cell, std::to_string(elsewhere)),
                   "disk 0 is not in the cell saved for it");
    // Disk 1 given disk 0's position, velocity, stamp, cell and events: the two are one.
    std::string coinciding = good;
    for (std::size_t k = 0; k <= 10; ++k) {
        if (k == 4 || k == 5) continue;  // the collision counters
        coinciding = with_token(coinciding, first_particle + per_particle + k, tokens.at(first_particle + k));
    }
    refused_saying(coinciding, "disks 0 and 1 overlap at the saved step");
    std::istringstream in(good);
    CHECK_EQ(ExactSimulation::restore(world, in).steps_done(), 1);  // the undamaged state restores
}

// States saved before the exact engine saved its cells a side (version 2:
// the same tokens without it) and its collision sums (version 1: without
// both) still restore, to the same run, the sums of version 1 starting at 0.
void exact_states_of_earlier_versions_restore() {
    const NamedScene scene = random_scenes::make(0);
    for (const int version : {1, 2}) {
        const check::Context context("version ", version);
        ExactSimulation exact(scene.world, scene.particles);
        for (int k = 0; k < 3; ++k) exact.step();
        CHECK(exact.collision_sums().pair_virial != 0.0 || exact.collision_sums().wall_impulse != 0.0);
        std::istringstream in(saved_text(exact));
        std::vector<std::string> tokens;
        for (std::string t; in >> t;) tokens.push_back(t);
        // The head: name, version, N, time, steps, three counts, two sums, the cells a side.
        CHECK(tokens.size() > 11 && tokens[0] == "exact-engine-state" && tokens[1] == "3");
        CHECK_EQ(tokens[10], std::to_string(exact.cells_per_side()));
        tokens[1] = std::to_string(version);
        tokens.erase(tokens.begin() + (version == 1 ? 8 : 10), tokens.begin() + 11);
        std::string earlier;
        for (const std::string& t : tokens) earlier += t + " ";
        std::istringstream saved(earlier);
        ExactSimulation restored = ExactSimulation::restore(scene.world, saved);
        CHECK_EQ(restored.cells_per_side(), exact.cells_per_side());
        if (version == 1) {
            CHECK_EQ(restored.collision_sums().pair_virial, 0.0);
            CHECK_EQ(restored.collision_sums().wall_impulse, 0.0);
        } else {
            CHECK_EQ(restored.collision_sums().pair_virial, exact.collision_sums().pair_virial);
        }
        CHECK_EQ(restored.steps_done(), exact.steps_done());
        for (int k = 0; k < 3; ++k) {
            exact.step();
            restored.step();
            CHECK_EQ(state_hash::hash(restored.particles()), state_hash::hash(exact.particles()));
        }
    }
}

// The cells a side a run chose from its particles (lines that crowd take
// the cells, which the model from N, r and L alone would not) are saved,
// and a restored run takes them: the same run, where the model's choice
// would have read the saved cells wrongly. Other cells asked for are refused.
void crowded_lines_restore_with_their_cells() {
    SceneFamilyOptions row;
    row.particles = 400;
    const Scene cradle = make_family_scene(SceneFamily::cradle, row);
    ExactSimulation exact(cradle.world, cradle.particles);
    CHECK(exact.cells_per_side() > 1);  // the lines crowd: every disk is on the moving one's line
    ExactSimulation by_lines(cradle.world, cradle.particles, {.cells_per_side = 1});
    for (int k = 0; k < 20; ++k) {
        exact.step();
        by_lines.step();
    }
    CHECK_EQ(state_hash::hash(by_lines.particles()), state_hash::hash(exact.particles()));
    const std::string text = saved_text(exact);
    std::istringstream in(text);
    ExactSimulation restored = ExactSimulation::restore(cradle.world, in);
    CHECK_EQ(restored.cells_per_side(), exact.cells_per_side());
    for (int k = 0; k < 20; ++k) {
        exact.step();
        restored.step();
    }
    CHECK_EQ(state_hash::hash(restored.particles()), state_hash::hash(exact.particles()));
    std::istringstream again(text);
    bool refused = false;
    try {
        (void)ExactSimulation::restore(cradle.world, again, {.cells_per_side = 1});
    } catch (const std::invalid_argument& e) {
        refused = std::string(e.what()).find("the state was saved with") != std::string::npos;
    }
    CHECK(refused);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_save_restore",
                      {{"stepped engine resumes bit for bit", stepped_engine_resumes_bit_for_bit},
                       {"exact engine resumes bit for bit", exact_engine_resumes_bit_for_bit},
                       {"exact states of earlier versions restore", exact_states_of_earlier_versions_restore},
                       {"crowded lines restore with their cells", crowded_lines_restore_with_their_cells},
                       {"damaged states are refused", damaged_states_are_refused},
                       {"disks out of place are refused", disks_out_of_place_are_refused},
                       {"a pair event of other particles is refused", pair_event_of_other_particles_is_refused}});
}
