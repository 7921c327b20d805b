// Run time against error: the stepped engine at K = 1, 2, 4, ..., 64 substeps
// and the exact engine, on the default scene and on a crowded box. The errors
// come from one recorded run per point (runs are deterministic); the run time
// is the median of plain runs. Also the exact engine's own speed.

#include "benchmarks.hpp"
#include "named_scene.hpp"
#include "statistics.hpp"

#include "particlesim/accuracy.hpp"
#include "particlesim/random_scene.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

using namespace particlesim;

namespace bench {

namespace {

template <typename MakeEngine>
double median_run_seconds(MakeEngine&& make_engine, std::int64_t steps, int repeats) {
    std::vector<double> seconds;
    for (int r = 0; r < repeats; ++r) {
        auto engine = make_engine();
        const auto start = std::chrono::steady_clock::now();
        particlesim::run(engine, steps);
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return median(seconds);
}

// Two runs that have diverged (chaos) count collisions of the same process
// like two independent samples: a rate error below about
// sqrt(1/n_run + 1/n_exact) is noise, not the rules.
double counting_noise(std::uint64_t run, std::uint64_t truth) {
    if (run == 0 || truth == 0) return 0.0;
    return std::sqrt(1.0 / static_cast<double>(run) + 1.0 / static_cast<double>(truth));
}

void print_row(const NamedScene& scene, const char* engine, int substeps, int threads, int repeats, double seconds,
               const RunRecord& run, const RunRecord& truth, const AccuracyReport& report) {
    std::printf("%s,%zu,%lld,%s,%d,%d,%d,%.6f,%llu,%llu,%.6g,%.6g,%.6g,%.6g,%.6g,%.3g,%.3g\n", scene.name.c_str(),
                scene.particles.size(), static_cast<long long>(scene.steps), engine, substeps, threads, repeats,
                seconds, static_cast<unsigned long long>(run.particle_collisions),
                static_cast<unsigned long long>(run.wall_collisions), report.particle_collision_rate_error,
                report.wall_collision_rate_error, report.overlap_fraction, report.position_error_at(1).value_or(0.0),
                report.position_error_at(10).value_or(0.0), run.largest_energy_drift,
                counting_noise(run.particle_collisions, truth.particle_collisions));
    std::fflush(stdout);
}

NamedScene crowded_box(std::int64_t steps) {
    // Area fraction 0.3, speeds 0.1 to 1 r per step (the dense gas, smaller).
    const std::size_t count = 2000;
    NamedScene scene{"crowded box", dense_gas_world(count), steps, {}};
    scene.particles = make_random_particles(count, scene.world, {3210, SpeedRange{0.1, 1.0}});
    return scene;
}

}  // namespace

void accuracy_benchmark(bool quick) {
    std::printf(
        "scene,n,steps,engine,substeps,threads,runs,median_s,particle_collisions,wall_collisions,"
        "particle_rate_error,wall_rate_error,overlap_fraction,position_error_1,position_error_10,energy_drift,"
        "particle_rate_noise\n");
    const std::int64_t steps = quick ? 100 : 1000;
    const int repeats = quick ? 1 : 3;
    const int threads = 2;
    NamedScene default_scene{"default", {20000.0, 1.0}, steps, {}};
    default_scene.particles = make_random_particles(1000, default_scene.world);
    for (const NamedScene& scene : {default_scene, crowded_box(steps)}) {
        const World& params = scene.world;
        ExactSimulation exact(params, scene.particles);
        const RunRecord truth = record_run(exact, steps);
        const double exact_seconds =
            median_run_seconds([&] { return ExactSimulation(params, scene.particles); }, steps, repeats);
        print_row(scene, "exact", 0, 1, repeats, exact_seconds, truth, truth, compare_to_exact(truth, truth, params));
        for (int k = 1; k <= 64; k *= 2) {
            const SteppedOptions options{.threads = threads, .substeps = k};
            SteppedSimulation stepped(params, scene.particles, options);
            const RunRecord run = record_run(stepped, steps);
            const double seconds =
                median_run_seconds([&] { return SteppedSimulation(params, scene.particles, options); }, steps, repeats);
            print_row(scene, "step", k, threads, repeats, seconds, run, truth, compare_to_exact(run, truth, params));
        }
    }
}

void exact_benchmark(bool quick) {
    std::printf("scene,n,steps,runs,median_s,particle_collisions,wall_collisions,collisions_per_s\n");
    const int repeats = quick ? 1 : 3;
    struct ExactCase {
        std::string name;
        std::size_t count;
        double box;
        std::int64_t steps;
        std::optional<SpeedRange> speeds;
    };
    std::vector<ExactCase> cases{{"default", 1000, 20000.0, quick ? 100 : 1000, {}}};
    for (const std::size_t n : {10000, 100000, 1000000}) {
        if (quick && n > 100000) break;
        // The dense gas: area fraction 0.3, speeds 0.1 to 1 r per step.
        cases.push_back({"dense gas", n, dense_gas_world(n).box_size,
                         static_cast<std::int64_t>(2e6 / static_cast<double>(n)) + 2, SpeedRange{0.1, 1.0}});
    }
    for (const ExactCase& c : cases) {
        const World params{c.box, 1.0};
        const std::vector<Particle> particles = make_random_particles(c.count, params, {3210, c.speeds});
        std::vector<double> seconds;
        std::uint64_t particle_collisions = 0;
        std::uint64_t wall_collisions = 0;
        for (int r = 0; r < repeats; ++r) {
            ExactSimulation exact(params, particles);
            const auto start = std::chrono::steady_clock::now();
            particlesim::run(exact, c.steps);
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            particle_collisions = exact.totals().particle_collisions;
            wall_collisions = exact.totals().wall_collisions;
        }
        const double time = median(seconds);
        std::printf("%s,%zu,%lld,%d,%.6f,%llu,%llu,%.4g\n", c.name.c_str(), c.count, static_cast<long long>(c.steps),
                    repeats, time, static_cast<unsigned long long>(particle_collisions),
                    static_cast<unsigned long long>(wall_collisions),
                    static_cast<double>(particle_collisions + wall_collisions) / time);
        std::fflush(stdout);
    }
}

}  // namespace bench
