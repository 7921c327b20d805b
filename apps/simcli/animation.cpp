#include "animation.hpp"

#include "animation_page.hpp"
#include "particlesim/accuracy.hpp"
#include "particlesim/state_writer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <limits>

namespace simcli {

namespace {

using particlesim::OutputError;
using particlesim::Particle;

// Bytes of base64 for one frame of `count` particles at most: 4 float32 each,
// and 3 uint32 for each that collided since the frame before.
double frame_bytes(std::size_t count) { return static_cast<double>(count) * 28.0 * 4.0 / 3.0 + 64.0; }

template <typename T>
void append_little_endian(std::vector<unsigned char>& out, T value) {
    using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    const Bits bits = std::bit_cast<Bits>(value);
    for (std::size_t k = 0; k < sizeof(T); ++k) out.push_back(static_cast<unsigned char>(bits >> (8 * k)));
}

class PageWriter {
public:
    PageWriter(std::FILE* out, std::string path) : out_(out), path_(std::move(path)) {}

    void text(std::string_view text) {
        if (std::fwrite(text.data(), 1, text.size(), out_) != text.size()) fail();
    }
    // `bytes` as base64, in lines of 76 characters.
    void base64(const std::vector<unsigned char>& bytes) {
        static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        std::string line;
        for (std::size_t k = 0; k < bytes.size(); k += 3) {
            const std::uint32_t a = bytes[k];
            const std::uint32_t b = k + 1 < bytes.size() ? bytes[k + 1] : 0;
            const std::uint32_t c = k + 2 < bytes.size() ? bytes[k + 2] : 0;
            const std::uint32_t word = (a << 16) | (b << 8) | c;
            line += alphabet[(word >> 18) & 63];
            line += alphabet[(word >> 12) & 63];
            line += k + 1 < bytes.size() ? alphabet[(word >> 6) & 63] : '=';
            line += k + 2 < bytes.size() ? alphabet[word & 63] : '=';
            if (line.size() >= 76) {
                line += '\n';
                text(line);
                line.clear();
            }
        }
        line += '\n';
        text(line);
    }

private:
    [[noreturn]] void fail() const { throw OutputError(path_ + ": cannot write the page: " + std::strerror(errno)); }
    std::FILE* out_;
    std::string path_;
};

std::string number(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

}  // namespace

Animation::Animation(const AnimationRequest& request, const particlesim::World& world, std::size_t particles,
                     std::int64_t steps, std::string engine, int substeps, ColourBy colour_by,
                     particlesim::Boundary boundary)
    : file_(std::make_unique<OutputFile>(request.path)),
      world_(world),
      unit_(std::ldexp(1.0, std::ilogb(world.box_size) + 1)),
      count_(particles),
      steps_(steps),
      engine_(std::move(engine)),
      substeps_(substeps),
      colour_by_(colour_by),
      boundary_(boundary) {
    if (request.every && *request.every < 1.0) {
        per_step_ = static_cast<int>(std::lround(1.0 / *request.every));
        every_ = 1.0 / per_step_;
    } else if (request.every) {
        stride_ = static_cast<std::int64_t>(*request.every);
        every_ = static_cast<double>(stride_);
    } else {
        // Frames that fit the budget: the first, the last, and one every K steps.
        const double per_frame = frame_bytes(particles);
        const double fitting = std::max(2.0, std::floor(animation_page_budget / per_frame));
        const double needed = static_cast<double>(steps) + 1.0;
        if (needed > fitting) {
            stride_ = static_cast<std::int64_t>(std::ceil(static_cast<double>(steps) / (fitting - 1.0)));
            every_ = static_cast<double>(stride_);
        }
        // The first and the last frame alone may pass the budget (millions of
        // particles): then the note says so instead of promising the budget.
        const double kept = static_cast<double>(steps / stride_ + 1 + (steps % stride_ != 0 ? 1 : 0));
        if (kept * per_frame > animation_page_budget) {
            std::fprintf(stderr,
                         "simcli: --animate keeps %s, and the page may still reach about %.0f MB (%zu particles "
                         "take up to about %.0f MB a frame); --snapshot draws one state in a smaller file\n",
                         kept > 1.0 ? "only the first and the last frame" : "the one frame", kept * per_frame / 1e6,
                         particles, per_frame / 1e6);
        } else if (needed > fitting) {
            std::fprintf(stderr,
                         "simcli: --animate keeps one frame in %lld (%zu particles, %lld steps: the page stays under "
                         "about %.0f MB; --animate-every K sets it)\n",
                         static_cast<long long>(stride_), particles, static_cast<long long>(steps),
                         animation_page_budget / 1e6);
        }
    }
    last_counters_.assign(2 * particles, 0);
}

void Animation::add_frame(double time, std::span<const Particle> particles, const particlesim::StepCounts& totals,
                          double velocity_scale, const particlesim::CollisionSums* sums) {
    double energy_sum = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        const double vx = p.velocity.x() / velocity_scale;
        const double vy = p.velocity.y() / velocity_scale;
        for (const double value : {p.position.x(), p.position.y(), vx, vy})
            frames_.push_back(static_cast<float>(value / unit_));
        const double speed = std::hypot(vx, vy);
        if (times_.empty() && i == 0) speed_min_ = speed_max_ = speed;
        speed_min_ = std::min(speed_min_, speed);
        speed_max_ = std::max(speed_max_, speed);
        energy_sum += 0.5 * (vx * vx + vy * vy);
    }
    // What collided since the frame before.
    std::vector<std::uint32_t> frame_hits;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const std::uint64_t pc = particles[i].particle_collisions - last_counters_[2 * i];
        const std::uint64_t wc = particles[i].wall_collisions - last_counters_[2 * i + 1];
        if (pc == 0 && wc == 0) continue;
        constexpr std::uint64_t most = std::numeric_limits<std::uint32_t>::max();
        frame_hits.insert(frame_hits.end(),
                          {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(std::min(pc, most)),
                           static_cast<std::uint32_t>(std::min(wc, most))});
        last_counters_[2 * i] = particles[i].particle_collisions;
        last_counters_[2 * i + 1] = particles[i].wall_collisions;
    }
    hits_.push_back(static_cast<std::uint32_t>(frame_hits.size() / 3));
    hits_.insert(hits_.end(), frame_hits.begin(), frame_hits.end());
    const bool first = times_.empty();
    series_.push_back(first ? 0.0 : static_cast<double>(totals.particle_collisions - last_totals_.particle_collisions));
    series_.push_back(first ? 0.0 : static_cast<double>(totals.wall_collisions - last_totals_.wall_collisions));
    series_.push_back(first ? 0.0 : time - last_time_);
    series_.push_back(energy_sum);
    if (colour_by_ == ColourBy::psi6) add_order(time, particles, energy_sum, sums);
    last_totals_ = totals;
    last_time_ = time;
    times_.push_back(time);
}

void Animation::add_order(double time, std::span<const Particle> particles, double kinetic_energy,
                          const particlesim::CollisionSums* sums) {
    const std::vector<std::complex<double>> local = particlesim::local_hexatic_order(particles, world_, boundary_);
    for (const std::complex<double>& psi : local) {
        order_.push_back(static_cast<unsigned char>(std::lround(std::clamp(phase_turns(psi), 0.0, 1.0) * 255.0)));
        order_.push_back(static_cast<unsigned char>(std::lround(std::clamp(std::abs(psi), 0.0, 1.0) * 255.0)));
    }
    psi6_.push_back(particlesim::mean_hexatic_order(local));
    double pressure = std::numeric_limits<double>::quiet_NaN();
    if (sums && last_sums_ && time > last_time_) {
        const particlesim::CollisionSums interval = *sums - *last_sums_;
        pressure = particlesim::box_pressure(world_, boundary_, particles.size(), kinetic_energy,
                                             particlesim::total_momentum(particles), interval, time - last_time_)
                       .betaP_d2;
    }
    pressure_.push_back(pressure);
    if (sums) last_sums_ = *sums;
}

void Animation::write() {
    PageWriter page(file_->stream(), file_->path());
    page.text(page::before_data);

    std::uint64_t count_max = 0;
    for (std::size_t i = 0; i < count_; ++i)
        count_max = std::max(count_max, last_counters_[2 * i] + last_counters_[2 * i + 1]);
    std::string meta =
        "{\"version\": 2, \"particles\": " + std::to_string(count_) + ", \"box\": " + number(world_.box_size) +
        ", \"radius\": " + number(world_.radius) + ", \"unit\": " + number(unit_) + ", \"engine\": \"" + engine_ +
        "\", \"substeps\": " + std::to_string(substeps_) + ", \"steps\": " + std::to_string(steps_) +
        ", \"every\": " + number(every_) + ", \"speedMin\": " + number(speed_min_) +
        ", \"speedMax\": " + number(speed_max_) + ", \"countMax\": " + std::to_string(count_max) +
        ", \"periodic\": " + (boundary_ == particlesim::Boundary::periodic ? "true" : "false") + ", \"times\": [";
    for (std::size_t f = 0; f < times_.size(); ++f) meta += (f > 0 ? ", " : "") + number(times_[f]);
    meta += "]";
    if (colour_by_ == ColourBy::psi6) {
        // JSON has no NaN: an unknown pressure is null.
        const auto list = [](const std::vector<double>& values) {
            std::string text = "[";
            for (std::size_t f = 0; f < values.size(); ++f)
                text += (f > 0 ? ", " : "") + (std::isfinite(values[f]) ? number(values[f]) : std::string("null"));
            return text + "]";
        };
        meta += ", \"colourBy\": \"psi6\", \"psi6\": " + list(psi6_) + ", \"pressure\": " + list(pressure_);
    }
    meta += "}";
    page.text("<script id=\"run-meta\" type=\"application/json\">" + meta + "</script>\n");

    std::vector<unsigned char> bytes;
    bytes.reserve(frames_.size() * 4);
    for (const float value : frames_) append_little_endian(bytes, value);
    page.text("<script id=\"run-frames\" type=\"application/octet-stream\">\n");
    page.base64(bytes);
    page.text("</script>\n<script id=\"run-series\" type=\"application/octet-stream\">\n");
    bytes.clear();
    for (const double value : series_) append_little_endian(bytes, value);
    page.base64(bytes);
    page.text("</script>\n<script id=\"run-hits\" type=\"application/octet-stream\">\n");
    bytes.clear();
    for (const std::uint32_t value : hits_) append_little_endian(bytes, value);
    page.base64(bytes);
    page.text("</script>\n");
    if (colour_by_ == ColourBy::psi6) {
        page.text("<script id=\"run-order\" type=\"application/octet-stream\">\n");
        page.base64(order_);
        page.text("</script>\n");
    }
    page.text(page::after_data);
    file_->commit();
}

}  // namespace simcli
