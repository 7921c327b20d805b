// libFuzzer target: any bytes go to the scene reader; a small scene it accepts
// is run by every engine, search and thread count, and must keep the rules'
// invariants (every centre in [r, L - r], finite numbers, counters that add
// up) and the promise of identical bytes across searches and threads. Its
// output must be well-formed text (no NUL, one line per particle and step).
// The same bytes also go to both engines' restore(), which must refuse a
// damaged saved state cleanly; and a run saved halfway and restored must go
// on exactly like the uninterrupted one. And to simcli's checkpoint reader,
// whose settings and first part must write back to text that reads the same;
// and, as an output of two small scenes, to simcheck's readers and judgement.
// Build and run: scripts/fuzz.sh SECONDS.

#include "checkpoint.hpp"  // simcli's
#include "judge.hpp"       // simcheck's

#include "particlesim/particlesim.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

// Small enough that one input runs in milliseconds.
constexpr std::size_t max_particles = 48;
constexpr std::int64_t max_steps = 24;
constexpr double max_exact_events = 20000.0;
// The exact engine's runs, from a scene or a saved state, stop within this budget a step.
const ExactOptions budgeted_exact{.max_events_per_step = static_cast<std::uint64_t>(max_exact_events)};

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "fuzz_scene: %s\n", what);
    std::abort();
}

void require(bool condition, const char* what) {
    if (!condition) fail(what);
}

void check_state(const World& world, std::span<const Particle> particles) {
    for (const Particle& p : particles) {
        require(p.position.x() >= world.lower() && p.position.x() <= world.upper() && p.position.y() >= world.lower() &&
                    p.position.y() <= world.upper(),
                "a centre left [r, L - r]");
        require(std::isfinite(p.velocity.x()) && std::isfinite(p.velocity.y()), "a velocity is not finite");
    }
}

// The whole output of a run, as simcli would write it.
template <Engine E>
std::string output_of(E& engine, std::int64_t steps) {
    struct Buffer {
        char* text = nullptr;
        std::size_t size = 0;
        ~Buffer() { std::free(text); }
    } buffer;
    // Closed, then freed, on every path: a run may end in an exception (TooManyEvents).
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(open_memstream(&buffer.text, &buffer.size), &std::fclose);
    require(out != nullptr, "open_memstream failed");
    StateWriter writer(out.get());
    writer.write_state(0, engine.particles());
    std::uint64_t collisions = 0;
    run(engine, steps, [&](std::int64_t step, std::span<const Particle> particles) {
        check_state(engine.world(), particles);
        collisions += engine.last_step().particle_collisions;
        if (step < steps) writer.write_state(step, particles);
    });
    writer.write_final(steps, engine.particles());
    writer.flush();
    require(collisions == engine.totals().particle_collisions, "step counts do not add up to the totals");
    const std::string result(buffer.text, buffer.size);
    require(result.find('\0') == std::string::npos, "the output holds a NUL byte");
    const auto lines = static_cast<std::size_t>(std::count(result.begin(), result.end(), '\n'));
    // io.md: the initial block, one block per step 1 .. S - 1, the final block (also when S = 0).
    const auto blocks = static_cast<std::size_t>(std::max<std::int64_t>(steps, 1) + 1);
    require(lines == engine.particles().size() * blocks, "wrong number of lines");
    return result;
}

}  // namespace

// Any bytes as a saved state: refused with std::invalid_argument, or restored
// into an engine that then runs a step within the rules.
template <typename E, typename Options>
void restore_any(const std::string& bytes, const Options& options) {
    const World world{20.0, 1.0};
    std::istringstream saved(bytes);
    try {
        E engine = E::restore(world, saved, options);
        if (engine.particles().size() > max_particles) return;
        engine.step();
        check_state(world, engine.particles());
    } catch (const std::invalid_argument&) {
    } catch (const TooManyEvents&) {
    }
}

// Any bytes as simcli's checkpoint: refused with std::invalid_argument, or
// read into settings and a first part within their limits, which written
// back read the same: every number is written exactly, so the same text
// twice is the same values (a first format's checkpoint gains an empty
// first part).
void read_any_checkpoint(const std::string& bytes) {
    const auto read = [](const std::string& text) {
        return simcli::read_checkpoint(std::make_unique<std::istringstream>(text), "fuzz");
    };
    const auto written = [](const simcli::Checkpoint& checkpoint) {
        std::ostringstream text;
        simcli::write_settings(text, checkpoint.settings, checkpoint.first_part);
        return text.str();
    };
    simcli::Checkpoint checkpoint;
    try {
        checkpoint = read(bytes);
    } catch (const std::invalid_argument&) {
        return;
    }
    const simcli::FirstPart& part = checkpoint.first_part;
    require(part.files.size() <= 3, "a first part of more than three files");
    for (const simcli::KeptFile& file : part.files) {
        require(!file.path.empty() && file.path[0] == '/' && file.path.size() <= simcli::longest_recorded_path &&
                    file.path.find('\0') == std::string::npos,
                "a first part's path neither absolute nor within its limit");
    }
    require(!part.observables_row || (part.observables_row->step >= 0 && part.observables_row->step <= part.step),
            "an open row after the checkpoint's step");
    const std::string text = written(checkpoint);
    require(written(read(text)) == text, "a checkpoint's settings or first part read back otherwise");
}

// simcheck's judgement of an output (its shape reader, then the strict
// reader, and the rules' check of what they read), on the bytes as the
// output of two fixed scenes: one printing every step, one the last alone.
// It must end with a verdict or a malformed output that names its line.
void judge_any_output(const std::string& bytes) {
    if (bytes.empty()) return;
    static const Scene scenes[] = {
        [] {
            std::istringstream text("3 20 1 4 print\n0 5 5 1 0.5\n1 10 10 0 -1\n2 15 15 -1 0\n");
            return read_scene(text);
        }(),
        [] {
            std::istringstream text("2 12 1 3 perf\n0 3 6 2 0\n1 9 6 -2 0\n");
            return read_scene(text);
        }(),
    };
    for (const Scene& scene : scenes) {
        std::FILE* output = fmemopen(const_cast<char*>(bytes.data()), bytes.size(), "r");
        if (!output) fail("fmemopen");
        const simcheck::Judgement judgement = simcheck::judge_output(scene, output, "output", {});
        std::fclose(output);
        require(judgement.outcome != simcheck::Outcome::malformed || judgement.message.rfind("output:", 0) == 0,
                "a malformed output without its name and line");
        require(judgement.outcome != simcheck::Outcome::wrong || judgement.report.finding,
                "a wrong output without its finding");
    }
}

// A run saved after `first` steps and restored ends exactly where the whole run ends.
template <typename E, typename Make, typename Restore>
void check_save_and_restore(Make&& make, Restore&& restore, std::int64_t first, std::int64_t steps) {
    E whole = make();
    run(whole, steps);
    E part = make();
    run(part, first);
    std::stringstream saved;
    part.save(saved);
    E resumed = restore(saved);
    run(resumed, steps - first);
    const auto a = whole.particles();
    const auto b = resumed.particles();
    require(a.size() == b.size(), "a restored run lost particles");
    for (std::size_t i = 0; i < a.size(); ++i) {
        require(std::memcmp(&a[i].position, &b[i].position, sizeof(Vec2)) == 0 &&
                    std::memcmp(&a[i].velocity, &b[i].velocity, sizeof(Vec2)) == 0 &&
                    a[i].particle_collisions == b[i].particle_collisions,
                "a restored run went another way");
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    restore_any<SteppedSimulation>(bytes, SteppedOptions{});
    restore_any<ExactSimulation>(bytes, budgeted_exact);
    read_any_checkpoint(bytes);
    judge_any_output(bytes);
    std::istringstream input(bytes);
    Scene scene;
    try {
        scene = read_scene(input);
    } catch (const InputError&) {
        return 0;
    }
    if (scene.particle_count > max_particles || scene.steps > max_steps) return 0;
    std::vector<Particle> particles = scene.particles;
    if (scene.is_random()) {
        try {
            particles = make_random_particles(scene.particle_count, scene.world);
        } catch (const SceneTooFull&) {
            return 0;
        }
    }
    check_state(scene.world, particles);

    SteppedSimulation reference(scene.world, particles, {.pair_search = PairSearch::brute_force, .threads = 1});
    const std::string expected = output_of(reference, scene.steps);
    const SteppedOptions variants[] = {
        {.pair_search = PairSearch::grid, .threads = 1},
        {.pair_search = PairSearch::grid, .grid_cells = 3, .threads = 2},
        {.pair_search = PairSearch::grid, .threads = 2, .sort_by_position_every = 1},
        {.pair_search = PairSearch::automatic, .threads = 2},
    };
    for (const SteppedOptions& options : variants) {
        SteppedSimulation engine(scene.world, particles, options);
        require(output_of(engine, scene.steps) == expected, "a search or thread count changed the output");
    }
    SteppedSimulation substeps(scene.world, particles, {.pair_search = PairSearch::brute_force, .substeps = 3});
    SteppedSimulation substeps_grid(scene.world, particles, {.pair_search = PairSearch::grid, .substeps = 3});
    require(output_of(substeps, scene.steps) == output_of(substeps_grid, scene.steps),
            "the grid changed the output with substeps");

    const std::int64_t half = scene.steps / 2;
    check_save_and_restore<SteppedSimulation>(
        [&] { return SteppedSimulation(scene.world, particles, {.threads = 1, .substeps = 2}); },
        [&](std::istream& saved) {
            return SteppedSimulation::restore(scene.world, saved, {.threads = 2, .substeps = 2});
        },
        half, scene.steps);

    if (estimated_events_per_step(scene.world, particles) * static_cast<double>(scene.steps) <= max_exact_events) {
        try {
            ExactSimulation exact(scene.world, particles, budgeted_exact);
            output_of(exact, scene.steps);
            check_save_and_restore<ExactSimulation>(
                [&] { return ExactSimulation(scene.world, particles, budgeted_exact); },
                [&](std::istream& saved) { return ExactSimulation::restore(scene.world, saved, budgeted_exact); }, half,
                scene.steps);
        } catch (const OverlappingStart&) {
        } catch (const TooManyEvents&) {  // the runaway guard: a clear stop, not a hang
        }
    }
    return 0;
}
