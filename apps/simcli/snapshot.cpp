#include "snapshot.hpp"

#include "output_file.hpp"

#include "particlesim/state_writer.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace simcli {

namespace {

constexpr double picture_pixels = 720.0;
constexpr double caption_line_pixels = 18.0;  // a line of the 13-pixel caption

// The same viridis ramp as the page.
std::array<int, 3> ramp(double t) {
    static constexpr int stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
    const double s = std::clamp(t, 0.0, 1.0) * 4.0;
    const int k = std::min(static_cast<int>(s), 3);
    const double w = s - k;
    std::array<int, 3> rgb{};
    for (int c = 0; c < 3; ++c)
        rgb[c] = static_cast<int>(std::lround(stops[k][c] + (stops[k + 1][c] - stops[k][c]) * w));
    return rgb;
}

// Where a disk is drawn: at its centre, and in a periodic box also at its
// images across the edges it overlaps (up to four places at a corner).
std::vector<particlesim::Vec2> drawn_at(const particlesim::Vec2& centre, double radius, double L, bool periodic) {
    std::vector<particlesim::Vec2> places{centre};
    if (!periodic) return places;
    const auto shifts = [&](double coordinate) {
        std::vector<double> by{0.0};
        if (coordinate < radius) by.push_back(L);
        if (coordinate > L - radius) by.push_back(-L);
        return by;
    };
    for (const double dx : shifts(centre.x())) {
        for (const double dy : shifts(centre.y())) {
            if (dx != 0.0 || dy != 0.0) places.emplace_back(centre.x() + dx, centre.y() + dy);
        }
    }
    return places;
}

}  // namespace

void write_snapshot(const std::string& path, const particlesim::World& world,
                    std::span<const particlesim::Particle> particles, std::int64_t step, ColourBy colour_by,
                    particlesim::Boundary boundary) {
    OutputFile file(path);
    std::FILE* out = file.stream();
    const double L = world.box_size;
    // Written in pixels, the box picture_pixels wide whatever L: a scene
    // scaled by 2^k draws the same picture (x / L does not change), and a
    // renderer never meets a box of 1e-7 or 1e7 units (Chromium drew nothing
    // of the first, and shrank the caption's font of the second).
    const auto pixels = [&](double length) { return length / L * picture_pixels; };
    // Disks smaller than a pixel are drawn as pixel-sized dots.
    const double radius = std::max(pixels(world.radius), 0.75);
    const double drawn_radius = radius / picture_pixels * L;  // in the box's units, for its images
    const double margin = 4.0;
    double low = 0.0, high = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const double speed = particles[i].velocity.norm();
        low = i == 0 ? speed : std::min(low, speed);
        high = i == 0 ? speed : std::max(high, speed);
    }
    // Two lines below the box: the scene, then what the colours mean (one
    // line of both ran past the picture's right edge).
    const double caption = 2.0 * caption_line_pixels + 10.0;
    const double width = picture_pixels + 2.0 * margin;
    const double height = width + caption;
    std::fprintf(out,
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"%.7g %.7g %.7g "
                 "%.7g\">\n",
                 width, height, -margin, -margin, width, height);
    std::fprintf(out,
                 "<rect x=\"0\" y=\"0\" width=\"%.7g\" height=\"%.7g\" fill=\"#ffffff\" stroke=\"#59636e\" "
                 "stroke-width=\"1\"/>\n",
                 picture_pixels, picture_pixels);
    const bool periodic = boundary == particlesim::Boundary::periodic;
    if (periodic) {
        // A disk across an edge shows its part on each side: the box clips
        // its images.
        std::fprintf(out, "<clipPath id=\"box\"><rect x=\"0\" y=\"0\" width=\"%.7g\" height=\"%.7g\"/></clipPath>\n",
                     picture_pixels, picture_pixels);
    }
    std::fprintf(out, "<g%s>\n", periodic ? " clip-path=\"url(#box)\"" : "");
    const bool by_order = colour_by == ColourBy::psi6;
    const std::vector<std::complex<double>> order =
        by_order ? particlesim::local_hexatic_order(particles, world, boundary) : std::vector<std::complex<double>>{};
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const particlesim::Particle& p = particles[i];
        const double t = high > low ? (p.velocity.norm() - low) / (high - low) : 0.5;
        const auto [red, green, blue] = by_order ? psi6_colour(order[i]) : ramp(t);
        for (const particlesim::Vec2& at : drawn_at(p.position, drawn_radius, L, periodic)) {
            // y upwards, as in the box.
            std::fprintf(out, "<circle cx=\"%.7g\" cy=\"%.7g\" r=\"%.7g\" fill=\"rgb(%d,%d,%d)\"/>\n", pixels(at.x()),
                         picture_pixels - pixels(at.y()), radius, red, green, blue);
        }
    }
    std::fprintf(out, "</g>\n");
    char colour[160];
    if (by_order) {
        std::snprintf(colour, sizeof colour, "colour: local psi6, hue its phase, darker where small; |psi6| = %.3f",
                      particlesim::mean_hexatic_order(order));
    } else {
        std::snprintf(colour, sizeof colour, "colour: speed from %.4g (purple) to %.4g (yellow)", low, high);
    }
    char scene[160];
    std::snprintf(scene, sizeof scene, "step %lld, %zu particles, L = %.6g, r = %.6g", static_cast<long long>(step),
                  particles.size(), L, world.radius);
    const char* const lines[] = {scene, colour};
    for (int line = 0; line < 2; ++line) {
        std::fprintf(
            out, "<text x=\"0\" y=\"%.7g\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#1f2328\">%s</text>\n",
            picture_pixels + margin + (line + 1) * caption_line_pixels, lines[line]);
    }
    std::fprintf(out, "</svg>\n");
    if (std::ferror(out)) throw particlesim::OutputError(path + ": cannot write: " + std::strerror(errno));
    file.commit();
}

}  // namespace simcli
