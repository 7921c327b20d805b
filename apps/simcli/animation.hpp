#pragma once
// simcli --animate FILE.html: collects frames of a run and writes one
// self-contained page that plays it (the page's sources: apps/simcli/page/).
// The run's data sits in the page as four script elements:
//   run-meta    JSON: version (2: frames in units of `unit`), particles, box, radius,
//               unit, engine, substeps, steps, every, times (of each frame, in
//               steps), speedMin, speedMax, countMax
//   run-frames  base64 of little-endian float32: per frame, x y vx vy per particle, in
//               units of run-meta's `unit` (the power of two with L / unit in [0.5, 1):
//               float32 holds any accepted box, 1e-60 or 1e60, and the scaling is exact)
//   run-series  base64 of little-endian float64: per frame, the particle and
//               wall collisions since the frame before, the steps since it, and
//               the kinetic energy
//   run-hits    base64 of little-endian uint32: per frame, n and n triples
//               (particle, its particle collisions, its wall collisions) since the frame before
//   run-order   (--colour-by psi6 only) base64 of uint8: per frame, per particle, the phase of
//               its local psi6 ((arg + pi) / 2 pi x 255) and its modulus (x 255); then
//               run-meta also holds colourBy "psi6", psi6 (the global |psi6| of each frame)
//               and pressure (beta P (2r)^2 by the virial over the interval before each
//               frame, null where the engine gives none)

#include "colour_by.hpp"
#include "output_file.hpp"

#include "particlesim/engine.hpp"
#include "particlesim/observables.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace simcli {

// Pages stay under about this size unless --animate-every says otherwise.
inline constexpr double animation_page_budget = 50e6;

struct AnimationRequest {
    std::string path;
    // Steps from one frame to the next: a whole number, or (exact engine) a
    // fraction 1/k of a step. Empty: automatic, within the budget.
    std::optional<double> every;
};

class Animation {
public:
    // Opens the page's file at once (a path that cannot be written fails
    // before the run, not after it). Says on stderr when it keeps one frame in
    // K automatically.
    Animation(const AnimationRequest& request, const particlesim::World& world, std::size_t particles,
              std::int64_t steps, std::string engine, int substeps, ColourBy colour_by = ColourBy::speed,
              particlesim::Boundary boundary = particlesim::Boundary::walls);

    // Whole steps between frames (1 when frames are a fraction of a step apart).
    [[nodiscard]] std::int64_t stride() const { return stride_; }
    // Micro-frames per step: k for --animate-every 1/k, else 1.
    [[nodiscard]] int per_step() const { return per_step_; }
    [[nodiscard]] bool wants(std::int64_t step) const { return step % stride_ == 0 || step == steps_; }

    // A frame at `time` (in steps); `totals` are the run's collisions so far.
    // Velocities are divided by `velocity_scale` (a sampling run moves slower).
    // `sums` (the exact engine's) give the pressure over the interval since the
    // frame before.
    void add_frame(double time, std::span<const particlesim::Particle> particles, const particlesim::StepCounts& totals,
                   double velocity_scale = 1.0, const particlesim::CollisionSums* sums = nullptr);
    // Writes the page (atomically, like -o). Throws particlesim::OutputError.
    void write();

private:
    // --colour-by psi6: each disk's local psi6, the frame's |psi6| and pressure.
    void add_order(double time, std::span<const particlesim::Particle> particles, double kinetic_energy,
                   const particlesim::CollisionSums* sums);

    std::unique_ptr<OutputFile> file_;
    particlesim::World world_;
    double unit_;  // of the frames' lengths
    std::size_t count_;
    std::int64_t steps_;
    std::string engine_;
    int substeps_;
    ColourBy colour_by_;
    particlesim::Boundary boundary_;
    std::int64_t stride_ = 1;
    int per_step_ = 1;
    double every_ = 1.0;
    std::vector<double> times_;
    std::vector<float> frames_;
    std::vector<double> series_;
    std::vector<std::uint32_t> hits_;
    std::vector<unsigned char> order_;     // --colour-by psi6: phase and modulus bytes
    std::vector<double> psi6_, pressure_;  // per frame; pressure NaN where unknown
    std::optional<particlesim::CollisionSums> last_sums_;
    std::vector<std::uint64_t> last_counters_;  // per particle: pc, wc at the last frame
    particlesim::StepCounts last_totals_;
    double last_time_ = 0.0;
    double speed_min_ = 0.0;
    double speed_max_ = 0.0;
};

}  // namespace simcli
