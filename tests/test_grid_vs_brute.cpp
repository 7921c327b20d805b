// The grid search and the paths search must find exactly the brute-force
// candidate set in every step, whatever the speeds, cells and threads, hence
// byte-identical runs.
// 200 random scenes: sparse and dense boxes, slow particles and particles
// faster than the box per step, overlapping starts, particles on walls; and
// clustered scenes that overflow the cells of the grid.

#include "check.hpp"
#include "random_scenes.hpp"
#include "state_hash.hpp"

#include "particlesim/stepped_simulation.hpp"
#include "search/brute_force_search.hpp"
#include "search/grid_search.hpp"
#include "search/path_search.hpp"
#include "stepped/early_selection.hpp"
#include "stepped/step_pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

using namespace particlesim;

namespace {

std::vector<Collision> merged(const std::vector<ThreadCandidates>& buffers) {
    std::vector<Collision> all;
    for (const ThreadCandidates& thread : buffers) all.insert(all.end(), thread.found.begin(), thread.found.end());
    // Any total order makes equal sets equal lists: (t, kind, i, j) on the stored indices.
    std::sort(all.begin(), all.end(), [](const Collision& a, const Collision& b) { return comes_before(a, b); });
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}

// Candidates of one search on one state, merged and in the total order.
// The grid scans `lanes` boxes at a time (0: the widest this processor has).
std::vector<Collision> pair_candidates(const PairSearchInput& in, std::optional<int> grid_cells, bool brute,
                                       int threads, int lanes = 0) {
    std::vector<ThreadCandidates> buffers(static_cast<std::size_t>(threads));
    if (brute) {
        find_pairs_brute_force(in, buffers);
    } else {
        GridSearch grid(lanes);
        grid.find_pairs(in, grid_cells, buffers);
    }
    return merged(buffers);
}

// Runs the scene with the brute force, comparing at every step the grid's
// candidate set (with `grid_cells`, or sized from the motion; scanning
// `lanes` boxes at a time) and the paths search's (which keeps its lines
// from step to step) on the same state.
bool same_candidates_every_step(const NamedScene& scene, std::optional<int> grid_cells, int threads, int lanes = 0) {
    SteppedSimulation sim(scene.world, scene.particles, {.pair_search = PairSearch::brute_force, .threads = 1});
    const Box box = Box::of(scene.world);
    std::vector<double> wall_time(scene.particles.size());
    StepStart start;
    PathSearch paths;
    std::vector<ThreadCandidates> path_buffers(static_cast<std::size_t>(threads));
    for (std::int64_t s = 0; s < scene.steps; ++s) {
        measure_step_start(sim.particles(), box, 1.0, wall_time, start, 1);
        const PairSearchInput in{sim.particles(), wall_time, box, 1.0};
        const std::vector<Collision> reference = pair_candidates(in, std::nullopt, true, 1);
        for (ThreadCandidates& buffer : path_buffers) buffer.found.clear();
        // No limit: every scene here, crowded or not, gets the paths search's candidates compared.
        if (!paths.find_pairs(in, path_buffers, std::numeric_limits<std::size_t>::max())) return false;
        if (reference != pair_candidates(in, grid_cells, false, threads, lanes) || reference != merged(path_buffers)) {
            return false;
        }
        sim.step();
    }
    return true;
}

// The stages of the selection that the grid search runs between its slices,
// counted, and the times its first slice, crowded, had the pairs at t = 0
// decided first.
struct CountedStages final : SliceDecisions {
    CountedStages(EarlySelection& selection, std::span<std::uint32_t> partner)
        : SliceDecisions(partner), selection(selection) {}
    void decide_before(double time, std::span<ThreadCandidates> found, int threads) override {
        ++stages;
        selection.decide_before(time, found, threads);
    }
    void decide_pairs_at_zero() override {
        ++pairs_at_zero;
        selection.decide_pairs_at_zero();
    }
    EarlySelection& selection;
    int stages = 0;
    int pairs_at_zero = 0;
};

// What the selection leaves for the resolution: each particle's partner and
// the time of its collision.
struct Selected {
    std::vector<std::uint32_t> partner;
    std::vector<double> time;

    bool operator==(const Selected& other) const {
        for (std::size_t i = 0; i < partner.size(); ++i) {
            if (partner[i] != other.partner[i]) return false;
            if (partner[i] != no_collision && time[i] != other.time[i]) return false;
        }
        return true;
    }
};

// How the selection is checked on piled disks: the searches keep at most
// `kept` candidates at t = 0 (ImmediateCandidateBudget), the ties go by
// `user_index` (the particles as if stored out of the user's order), and
// `overflowed` counts the steps whose pairs at t = 0 the selection decided
// from the particles.
struct ImmediatePairs {
    std::size_t kept = 0;
    std::span<const std::uint32_t> user_index;
    int overflowed = 0;
};

// Runs the scene with the brute force and, at every step, selects twice on
// the same state: once from all the brute force's candidates, once in stages
// between the grid's slices (EarlySelection), the later slices leaving out
// the decided particles. The same collisions every step; `stages` and
// `pair_tests` (with and without the stages) add up what the grid did.
// With `immediate`, a third time from the brute force's candidates, and the
// grid's stages too, under its budget of candidates at t = 0.
bool same_selection_every_step(const NamedScene& scene, int threads, int& stages, std::uint64_t& staged_tests,
                               std::uint64_t& unstaged_tests, ImmediatePairs* immediate = nullptr,
                               int* crowded_first_slices = nullptr) {
    SteppedSimulation sim(scene.world, scene.particles, {.pair_search = PairSearch::brute_force, .threads = 1});
    const Box box = Box::of(scene.world);
    const std::size_t count = scene.particles.size();
    const CandidateOrder order(immediate != nullptr ? immediate->user_index : std::span<const std::uint32_t>{});
    std::vector<double> wall_time(count);
    StepStart start;
    start.with_motion = true;
    ImmediateCandidateBudget budget;
    for (std::int64_t s = 0; s < scene.steps; ++s) {
        measure_step_start(sim.particles(), box, 1.0, wall_time, start, 1);
        const auto select = [&](bool staged, bool budgeted) {
            Selected out{std::vector<std::uint32_t>(count, no_collision), wall_time};
            std::vector<Collision> candidates;
            std::vector<Collision> ready;
            gather_wall_candidates(wall_time, 1.0, start, candidates, 1);
            std::vector<double> stage_time;
            SelectionScratch scratch(count);
            std::vector<ThreadCandidates> buffers(static_cast<std::size_t>(staged ? threads : 1));
            // The search reads its wall times from the array the selection
            // leaves the collision times in, as in the engine.
            if (budgeted) budget.reset(immediate->kept);
            const PairSearchInput in{
                sim.particles(), out.time, box, 1.0, start.blocks, 0.0, budgeted ? &budget : nullptr};
            EarlySelection selection(in, candidates, ready, order, out.partner, out.time, stage_time, scratch, threads);
            if (staged) {
                CountedStages counted(selection, out.partner);
                GridSearch grid;
                grid.find_pairs(in, std::nullopt, buffers, &counted);
                stages += counted.stages;
                if (crowded_first_slices != nullptr) *crowded_first_slices += counted.pairs_at_zero;
                for (const ThreadCandidates& thread : buffers) staged_tests += thread.pair_tests;
                // And the grid without stages, for its pair tests alone.
                std::vector<ThreadCandidates> unstaged(static_cast<std::size_t>(threads));
                grid.find_pairs({sim.particles(), wall_time, box, 1.0, start.blocks}, std::nullopt, unstaged);
                for (const ThreadCandidates& thread : unstaged) unstaged_tests += thread.pair_tests;
            } else {
                find_pairs_brute_force(in, buffers);
            }
            selection.decide_rest(buffers);
            if (budgeted && budget.overflowed()) ++immediate->overflowed;
            return out;
        };
        const Selected reference = select(false, false);
        if (!(select(true, immediate != nullptr) == reference)) return false;
        if (immediate != nullptr && !(select(false, true) == reference)) return false;
        sim.step();
    }
    return true;
}

// Disks piled within 1e-6 of two points, one in the box and one on its
// left wall (there some move into the wall: a wall collision at t = 0, which
// comes before any pair), and thrown into a 30 x 30 patch (overlapping
// across the cells), beside a gas; fast enough for the grid to cut the step
// into slices.
NamedScene piled_disks(std::uint64_t seed, std::size_t piled, std::size_t gas) {
    SplitMix64 rng(seed);
    NamedScene scene{"piles", World{400.0, 1.0}, 3, {}};
    const auto offset = [&] { return (2.0 * rng.uniform() - 1.0) * 1e-6; };
    const auto speed = [&] { return (2.0 * rng.uniform() - 1.0) * 200.0; };
    for (std::size_t k = 0; k < piled; ++k) {
        const Vec2 at = k % 4 == 3   ? Vec2(1.0, 150.0 + offset())
                        : k % 4 == 2 ? Vec2(300.0 + 30.0 * rng.uniform(), 300.0 + 30.0 * rng.uniform())
                                     : Vec2(200.0 + offset(), 220.0 + offset());
        scene.particles.push_back(Particle{at, Vec2(speed(), speed())});
    }
    for (std::size_t k = 0; k < gas; ++k) {
        const Vec2 at(1.0 + 398.0 * rng.uniform(), 1.0 + 398.0 * rng.uniform());
        scene.particles.push_back(Particle{at, Vec2(speed(), speed())});
    }
    // The piles' disks spread over the indices.
    for (std::size_t k = scene.particles.size() - 1; k > 0; --k)
        std::swap(scene.particles[k], scene.particles[rng.next() % (k + 1)]);
    return scene;
}

std::uint64_t run_hash(const NamedScene& scene, const SteppedOptions& options) {
    SteppedSimulation sim(scene.world, scene.particles, options);
    std::uint64_t h = state_hash::hash(sim.particles());
    particlesim::run(sim, scene.steps,
                     [&](std::int64_t, std::span<const Particle> particles) { h = state_hash::hash(particles, h); });
    return h;
}

// One row of three disks for every time k / S (S = 4 ... 64, 0 < k < S),
// the edges of every slicing the grid can choose: A at rest; B fast from the
// left, touching A just after the edge (by 2^-18 of the step); C slow from
// the right, touching A later (by 2^-17), so close at the edge that their
// boxes of the slice before it already meet. A stage that decided past the
// end of the slices searched would take (A, C), found first, for (A, B).
// The rows are 3.5 apart, more than a contact distance: no row meets another.
NamedScene slice_edge_contacts() {
    std::vector<double> edges;
    for (int slices = 4; slices <= 64; ++slices) {
        for (int k = 1; k < slices; ++k) edges.push_back(static_cast<double>(k) / slices);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    NamedScene scene{"slice edges", World{5000.0, 1.0}, 2, {}};
    const double fast = 3000.0;
    const double slow = 1.0;
    for (std::size_t row = 0; row < edges.size(); ++row) {
        const double y = 4.0 + 3.5 * static_cast<double>(row);
        const double fast_contact = edges[row] + 0x1p-18;
        const double slow_contact = edges[row] + 0x1p-17;
        scene.particles.push_back({Vec2(4000.0, y), Vec2(0.0, 0.0), 0, 0});
        scene.particles.push_back({Vec2(4000.0 - 2.0 - fast * fast_contact, y), Vec2(fast, 0.0), 0, 0});
        scene.particles.push_back({Vec2(4000.0 + 2.0 + slow * slow_contact, y), Vec2(-slow, 0.0), 0, 0});
    }
    return scene;
}

// The grid's lane counts this processor has (4 everywhere; 8 and 16 on
// x86-64 with AVX2 and AVX-512), one for each k in turn.
int lanes_for(std::uint64_t k) {
    std::vector<int> supported;
    for (const int lanes : {4, 8, 16}) {
        if (GridSearch::supports_lanes(lanes)) supported.push_back(lanes);
    }
    return supported[k % supported.size()];
}

// Fast disks in a box of side L, and pairs built to pass each other at a
// distance of 2r times (1 -+ 2^-30) at a time t0 within the step: the
// nearest a pair can pass and still collide, and the nearest it can pass
// without. Their separation's line is as close to the line test's reach
// as the pairs a search finds ever come. Returns the scene and, in `built`,
// how many pairs were built to collide.
NamedScene passing_pairs(double box_size, std::uint64_t seed, int& built) {
    SplitMix64 rng(seed);
    const double r = box_size * 1e-4;
    NamedScene scene{"passing pairs", World{box_size, r}, 2, {}};
    scene.particles = make_random_particles(150, scene.world, {seed, SpeedRange{box_size / 8.0, box_size / 4.0}});
    const auto random_velocity = [&] {
        const double speed = box_size * (0.125 + 0.125 * rng.uniform());
        const double angle = 6.283185307179586 * rng.uniform();
        return Vec2(speed * std::cos(angle), speed * std::sin(angle));
    };
    const auto inside = [&](const Vec2& p) {
        return p.x() >= r && p.x() <= box_size - r && p.y() >= r && p.y() <= box_size - r;
    };
    built = 0;
    for (int pair = 0; pair < 60;) {
        const Vec2 meeting(box_size * (0.1 + 0.8 * rng.uniform()), box_size * (0.1 + 0.8 * rng.uniform()));
        const double t0 = 0.05 + 0.9 * rng.uniform();
        const Vec2 va = random_velocity();
        const Vec2 vb = random_velocity();
        const Vec2 dv = vb - va;
        const Vec2 normal = Vec2(-dv.y(), dv.x()) / dv.norm();
        const bool collides = pair % 2 == 0;
        const Vec2 apart = normal * (2.0 * r * (collides ? 1.0 - 0x1p-30 : 1.0 + 0x1p-30));
        const Vec2 a = meeting - va * t0;
        const Vec2 b = meeting + apart - vb * t0;
        if (!inside(a) || !inside(b)) continue;
        scene.particles.push_back({a, va, 0, 0});
        scene.particles.push_back({b, vb, 0, 0});
        built += collides ? 1 : 0;
        ++pair;
    }
    return scene;
}

}  // namespace

int main(int argc, char** argv) {
    static constexpr int forced_grids[] = {1, 2, 4, 7, 16, 64};
    static constexpr int thread_counts[] = {1, 2, 3, 8};
    return check::run(
        argc, argv, "test_grid_vs_brute",
        {{"random scenes",
          [] {
              for (std::uint64_t k = 0; k < 200; ++k) {
                  const NamedScene scene = random_scenes::make(k);
                  const int forced = forced_grids[k % 6];
                  const int threads = thread_counts[(k / 6) % 4];
                  const std::optional<int> grid = k % 2 == 0 ? std::nullopt : std::optional<int>(forced);
                  const int lanes = lanes_for(k / 2);
                  const check::Context context("random scene ", k, ", grid ", grid.value_or(0),
                                               " (0: sized from the motion), ", threads, " threads, ", lanes, " lanes");
                  CHECK(same_candidates_every_step(scene, grid, threads, lanes));
                  // Whole runs, hashed after every step: brute on 1 thread against the
                  // grid (auto and forced) and brute on several threads.
                  const std::uint64_t reference =
                      run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = 1});
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::grid, .threads = threads}), reference);
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::grid,
                                            .grid_cells = forced,
                                            .threads = thread_counts[k % 4]}),
                           reference);
                  CHECK_EQ(run_hash(scene, {.threads = threads}), reference);
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = threads}), reference);
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::paths, .threads = threads}), reference);
              }
          }},
         // The rules' density and speeds at 6000 disks: each slice's scans
         // test lines, and its box records (over 4096) are turned into rows
         // in more than one block.
         {"many box records in a slice",
          [] {
              NamedScene scene{"6000 at the rules' density", World{20000.0 * std::sqrt(6.0), 1.0}, 2, {}};
              scene.particles = make_random_particles(6000, scene.world, {11, SpeedRange{2500.0, 5000.0}});
              for (std::uint64_t k = 0; k < 3; ++k) {
                  const int lanes = lanes_for(k);
                  const int threads = k == 0 ? 1 : 2;
                  const check::Context context(lanes, " lanes, ", threads, " threads");
                  CHECK(same_candidates_every_step(scene, std::nullopt, threads, lanes));
              }
          }},
         // Clusters of fast particles crowd a few cells, and many of their paths
         // are too long for a cell: cut into pieces, set aside as large boxes, or
         // (when the pieces would overflow the buffers) recounted as large.
         // The paths search over more than 1024 micro-steps (its lines made
         // afresh), with substeps, and with the particles stored sorted by
         // position every few steps (its lines forgotten).
         {"paths search over long runs",
          [] {
              for (std::uint64_t k = 0; k < 6; ++k) {
                  NamedScene scene = random_scenes::make(k * 7 + 3);
                  scene.particles.resize(std::min<std::size_t>(scene.particles.size(), 60));
                  scene.steps = 1100;
                  const int threads = thread_counts[k % 4];
                  const check::Context context("scene ", k * 7 + 3, ", ", threads, " threads");
                  const std::uint64_t reference =
                      run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = 1});
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::paths, .threads = threads}), reference);
                  CHECK_EQ(
                      run_hash(scene,
                               {.pair_search = PairSearch::paths, .threads = threads, .sort_by_position_every = 5}),
                      reference);
                  scene.steps = 400;
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::paths, .threads = threads, .substeps = 3}),
                           run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = 1, .substeps = 3}));
              }
          }},
         // Relative speeds whose squares underflow (dv of 1e-200 and 1e-170):
         // overlapping pairs that approach, recede or move together, beside
         // ordinary disks; the paths search watches them until a line changes.
         {"paths search at tiny relative speeds",
          [] {
              NamedScene scene{"", World{100.0, 1.0}, 60, {}};
              for (int k = 0; k < 6; ++k) {
                  const Vec2 v(0.7 - 0.3 * k, 0.4 + 0.1 * k);
                  const Vec2 at(10.0 + 14.0 * k, 20.0 + 11.0 * k);
                  const double tiny = k % 2 == 0 ? 1e-200 : 1e-170;
                  const Vec2 apart = k % 3 == 0 ? Vec2(1.5, 0.0) : Vec2(1.0, 1.0);  // overlapping
                  const Vec2 drift = k < 2 ? Vec2(-tiny, 0.0) : k < 4 ? Vec2(tiny, 0.0) : Vec2(0.0, 0.0);
                  scene.particles.push_back({at, v, 0, 0});
                  scene.particles.push_back({at + apart, v + drift, 0, 0});
              }
              for (int k = 0; k < 40; ++k) {
                  scene.particles.push_back({Vec2(3.0 + 2.3 * k, 90.0 - 1.7 * k), Vec2(0.9 - 0.05 * k, 0.3), 0, 0});
              }
              CHECK(same_candidates_every_step(scene, std::nullopt, 1));
              CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::paths, .threads = 2}),
                       run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = 1}));
          }},
         // Sparse scenes of fast particles, which the grid cuts into 4 to 64
         // slices: the selection decided in stages between them, the decided
         // particles left out of the later slices, against one selection of
         // the brute force's candidates.
         {"selection in stages between the slices",
          [] {
              int stages = 0;
              std::uint64_t staged_tests = 0;
              std::uint64_t unstaged_tests = 0;
              for (std::uint64_t k = 0; k < 24; ++k) {
                  SplitMix64 rng(7000 + k);
                  const double box_size = 5000.0;
                  const std::size_t count = 400 + rng.next() % 2600;
                  const double top_speed = k % 3 == 0 ? 2.0 * box_size : box_size / 2.0;
                  NamedScene scene{"", World{box_size, 3.0}, 5, {}};
                  scene.particles =
                      make_random_particles(count, scene.world, {k, SpeedRange{box_size / 8.0, top_speed}});
                  const int threads = thread_counts[k % 3];
                  const check::Context context("sparse scene ", k, ", ", count, " particles, ", threads, " threads");
                  CHECK(same_selection_every_step(scene, threads, stages, staged_tests, unstaged_tests));
                  if (k % 4 == 0) {
                      CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::grid, .threads = threads}),
                               run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = 1}));
                  }
              }
              // The stages ran, and the slices after them left particles out.
              CHECK(stages > 24 * 5);
              CHECK(staged_tests < unstaged_tests * 17 / 20);
          }},
         // Piled disks make a candidate at t = 0 of every approaching pair;
         // past a budget the searches drop them and the selection decides
         // those pairs from the particles, in the user's order or stored out
         // of it: the same collisions as from every candidate.
         {"pairs at t = 0 decided from the particles",
          [] {
              int stages = 0;
              std::uint64_t staged_tests = 0;
              std::uint64_t unstaged_tests = 0;
              int steps = 0;
              int overflowed = 0;
              for (std::uint64_t k = 0; k < 12; ++k) {
                  SplitMix64 rng(7100 + k);
                  const NamedScene scene = piled_disks(k, 20 + rng.next() % 300, rng.next() % 1500);
                  std::vector<std::uint32_t> user_index(scene.particles.size());
                  for (std::uint32_t i = 0; i < user_index.size(); ++i) user_index[i] = i;
                  if (k % 2 == 1) {
                      for (std::size_t i = user_index.size() - 1; i > 0; --i)
                          std::swap(user_index[i], user_index[rng.next() % (i + 1)]);
                  }
                  ImmediatePairs immediate{
                      static_cast<std::size_t>(k % 3 == 0 ? 0 : rng.next() % 200),
                      k % 2 == 1 ? std::span<const std::uint32_t>(user_index) : std::span<const std::uint32_t>{}};
                  const int threads = thread_counts[k % 3];
                  const check::Context context("piles ", k, ", ", scene.particles.size(), " particles, kept ",
                                               immediate.kept, ", ", threads, " threads");
                  CHECK(same_selection_every_step(scene, threads, stages, staged_tests, unstaged_tests, &immediate));
                  steps += static_cast<int>(scene.steps);
                  overflowed += immediate.overflowed;
              }
              // Of the two budgeted selections a step, more than one in four
              // decided the pairs at t = 0 from the particles (the piles
              // spread out after their first step), and the stages ran.
              CHECK(overflowed > steps / 2);
              CHECK(stages > 0);
              // A pile of 1000 disks crowds the grid's first slice: the
              // pairs at t = 0 are decided before its scan, whatever the
              // budget.
              int crowded = 0;
              for (const int threads : {1, 2}) {
                  ImmediatePairs unlimited{std::numeric_limits<std::size_t>::max(), {}};
                  NamedScene pile = piled_disks(98, 2000, 500);
                  pile.steps = 2;
                  const check::Context context("a pile of 1000, ", threads, " threads");
                  CHECK(same_selection_every_step(pile, threads, stages, staged_tests, unstaged_tests, &unlimited,
                                                  &crowded));
              }
              CHECK(crowded >= 2);
              // The engine: every search and thread count, stored in the
              // user's order or sorted by position at every step, where a
              // pile of 3000 disks overflows the budget.
              const NamedScene scene = piled_disks(99, 3000, 1000);
              const std::uint64_t reference = run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = 1});
              for (const PairSearch search : {PairSearch::brute_force, PairSearch::grid, PairSearch::paths}) {
                  for (const int threads : {1, 2}) {
                      for (const std::optional<int> sort : {std::optional<int>{}, std::optional<int>{1}}) {
                          const check::Context context(pair_search_name(search), ", ", threads, " threads",
                                                       sort ? ", sorted" : "");
                          CHECK_EQ(
                              run_hash(scene,
                                       {.pair_search = search, .threads = threads, .sort_by_position_every = sort}),
                              reference);
                      }
                  }
              }
          }},
         // Contacts just after every edge a slicing can have, each beside a
         // later one that the slice before the edge finds.
         {"contacts at the slices' edges",
          [] {
              const NamedScene scene = slice_edge_contacts();
              int stages = 0;
              std::uint64_t staged_tests = 0;
              std::uint64_t unstaged_tests = 0;
              for (const int threads : {1, 2}) {
                  const check::Context context(threads, " threads");
                  CHECK(same_selection_every_step(scene, threads, stages, staged_tests, unstaged_tests));
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::grid, .threads = threads}),
                           run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = 1}));
              }
              CHECK(stages > 0);
          }},
         // A lane count is the widest the processor has, or one it asks for and has.
         {"lane counts",
          [] {
              CHECK(GridSearch::supports_lanes(4));
              CHECK(!GridSearch::supports_lanes(5));
              bool refused = false;
              try {
                  GridSearch odd(5);
              } catch (const std::invalid_argument&) {
                  refused = true;
              }
              CHECK(refused);
          }},
         // Pairs that pass just inside and just outside a contact distance,
         // at scales from 2^-150 to 2^150 times L = 1000, in every lane width:
         // the line test in float keeps every pair that collides.
         {"pairs passing at a contact distance",
          [] {
              std::uint64_t seed = 1;
              for (const int exponent : {-150, -20, 0, 24, 150}) {
                  int built = 0;
                  const NamedScene scene = passing_pairs(std::ldexp(1000.0, exponent), seed++, built);
                  const PairSearchInput first_step{scene.particles, std::vector<double>(scene.particles.size(), never),
                                                   Box::of(scene.world), 1.0};
                  // The pairs built to collide are candidates of the brute force (unless a
                  // wall or another disk comes first), those built to pass are not.
                  int found = 0;
                  for (const Collision& c : pair_candidates(first_step, std::nullopt, true, 1)) {
                      if (c.i >= 150 && (c.i - 150) % 2 == 0 && c.j == c.i + 1)
                          found += (c.i - 150) % 4 == 0 ? 1 : -1000;
                  }
                  for (int lanes = 4; lanes <= 16; lanes *= 2) {
                      if (!GridSearch::supports_lanes(lanes)) continue;
                      const check::Context context("L = 1000 x 2^", exponent, ", ", lanes, " lanes");
                      CHECK(found >= built * 3 / 4);
                      CHECK(same_candidates_every_step(scene, std::nullopt, 1, lanes));
                      CHECK(same_candidates_every_step(scene, std::nullopt, 2, lanes));
                  }
              }
          }},
         {"clustered scenes", [] {
              for (std::uint64_t k = 0; k < 12; ++k) {
                  const NamedScene scene = random_scenes::make_clustered(k);
                  const int threads = thread_counts[k % 4];
                  const check::Context context("clustered scene ", k, ", ", threads, " threads");
                  CHECK(same_candidates_every_step(scene, std::nullopt, threads));
                  const std::uint64_t reference =
                      run_hash(scene, {.pair_search = PairSearch::brute_force, .threads = 1});
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::grid, .threads = threads}), reference);
                  CHECK_EQ(run_hash(scene, {.pair_search = PairSearch::paths, .threads = threads}), reference);
              }
          }}});
}
