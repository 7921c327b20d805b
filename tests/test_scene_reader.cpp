// The scene reader: valid scenes and every class of bad input, each with the
// line that names the problem.

#include "check.hpp"

#include "particlesim/scene.hpp"
#include "particlesim/scene_families.hpp"

#include <atomic>
#include <cstdlib>
#include <limits>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>

// The largest single allocation, to show that memory follows the input.
namespace {
std::atomic<std::size_t> largest_allocation{0};
}

void* operator new(std::size_t size) {
    std::size_t seen = largest_allocation.load();
    while (size > seen && !largest_allocation.compare_exchange_weak(seen, size)) {
    }
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace particlesim;

namespace {

struct Outcome {
    bool ok = false;
    long line = 0;
    std::string message;
    Scene scene;
};

Outcome read(const std::string& text) {
    std::istringstream in(text);
    Outcome outcome;
    try {
        outcome.scene = read_scene(in);
        outcome.ok = true;
    } catch (const InputError& e) {
        outcome.line = e.line();
        outcome.message = e.what();
    }
    return outcome;
}

void expect_error(const std::string& text, long line, const std::string& fragment) {
    const Outcome o = read(text);
    CHECK(!o.ok);
    CHECK_EQ(o.line, line);
    const bool mentions = o.message.find(fragment) != std::string::npos;
    CHECK(mentions);
    if (!mentions) std::fprintf(stderr, "  message was: %s\n", o.message.c_str());
}

void valid_scenes() {
    const Outcome random = read("1000\n20000\n1\n1000\nperf\n");
    CHECK(random.ok);
    CHECK(random.scene.is_random());
    CHECK_EQ(random.scene.particle_count, 1000U);
    CHECK_EQ(random.scene.steps, 1000);
    CHECK(random.scene.mode == OutputMode::perf);

    // Particles in any order, blank lines, tabs, CRLF, header on one line.
    const Outcome listed = read("2 20 1 5 print\n\n1\t15 12 -0.5 0\r\n0 5 5 1e-1 -0\n\n");
    CHECK(listed.ok);
    CHECK(!listed.scene.is_random());
    CHECK_EQ(listed.scene.particles[0].position.x(), 5.0);
    CHECK_EQ(listed.scene.particles[0].velocity.x(), 0.1);
    CHECK(!std::signbit(listed.scene.particles[0].velocity.y()));
    CHECK_EQ(listed.scene.particles[1].position.y(), 12.0);
    CHECK(listed.scene.mode == OutputMode::print);

    // Listed in index order or not: the same particles, each with its own
    // line (the reader hands a list in index order over as it is).
    const auto with_lines = [](const std::string& text, SceneLines& lines) {
        std::istringstream in(text);
        return read_scene(in, &lines);
    };
    SceneLines in_order_lines;
    SceneLines shuffled_lines;
    const Scene in_order = with_lines("3 20 1 5 print\n0 5 5 0 0\n1 10 10 1 0\n2 15 15 0 1\n", in_order_lines);
    const Scene shuffled = with_lines("3 20 1 5 print\n2 15 15 0 1\n0 5 5 0 0\n1 10 10 1 0\n", shuffled_lines);
    CHECK_EQ(in_order.particles.size(), 3U);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(in_order.particles[i].position == shuffled.particles[i].position);
        CHECK(in_order.particles[i].velocity == shuffled.particles[i].velocity);
    }
    CHECK_EQ(in_order.particles[2].velocity.y(), 1.0);
    CHECK(in_order_lines.particles == std::vector<long>({2, 3, 4}));
    CHECK(shuffled_lines.particles == std::vector<long>({3, 4, 2}));

    // Boundaries are valid: x = r, x = L - r, 2r = L, N = 0, S = 0.
    CHECK(read("1 2 1 0 perf\n0 1 1 0 0\n").ok);
    CHECK(read("1 20 1 3 perf\n0 1 19 0 0\n").ok);
    CHECK(read("0 20 1 3 perf\n").ok);
}

void bad_headers() {
    expect_error("", 1, "missing N");
    expect_error("abc\n", 1, "expected a non-negative integer, found \"abc\"");
    expect_error("-5\n", 1, "expected a non-negative integer");
    expect_error("1.5\n", 1, "expected a non-negative integer");
    expect_error("99999999999999999999999\n", 1, "too large");
    expect_error("99999999999\n20000\n1\n1\nperf\n", 1, "more particles than this machine can hold");
    expect_error("10\n", 1, "missing L");
    expect_error("10\n-5\n", 2, "L = -5 must be > 0");
    expect_error("10\n0\n", 2, "L = 0 must be > 0");
    expect_error("10\nnan\n", 2, "expected a finite number");
    expect_error("10\ninf\n", 2, "expected a finite number");
    expect_error("10\n1e999\n", 2, "beyond the range of a double");
    expect_error("10\n1e200\n", 2, "L = 1e200 is beyond the accepted range (magnitudes at most 1e60");
    expect_error("10\n20\n0\n", 3, "r = 0 must be > 0");
    expect_error("10\n20\n10.5\n", 3, "2r must be <= L = 20");
    expect_error("10\n20\n1\n-1\n", 4, "S: expected a non-negative integer");
    expect_error("10\n20\n1\n5\n", 4, "missing the output mode");
    expect_error("10\n20\n1\n5\npint\n", 5, "expected print or perf, found \"pint\"");
    expect_error("1 20 1 5 perf 0 5 5 0 0\n", 1, "unexpected text after the output mode");
}

void bad_particles() {
    const std::string header = "3\n20\n1\n5\nperf\n";
    expect_error(header + "0 5 5 0\n", 6, "5 fields");
    expect_error(header + "0 5 5 0 0 7\n", 6, "this one has 6");
    expect_error(header + "3 5 5 0 0\n", 6, "particle index 3 is outside [0, 2]");
    expect_error(header + "x 5 5 0 0\n", 6, "particle index: expected a non-negative integer");
    expect_error(header + "0 5 5 0 0\n1 6 6 0 0\n0 7 7 0 0\n", 8, "particle 0 is listed twice (first on line 6)");
    expect_error(header + "0 -2 5 0 0\n", 6, "particle 0: x = -2 is outside [1, 19]");
    expect_error(header + "0 5 19.5 0 0\n", 6, "particle 0: y = 19.5 is outside [1, 19]");
    expect_error(header + "0 5 5 nan 0\n", 6, "particle 0: vx: expected a finite number");
    expect_error(header + "0 5 5 0 -inf\n", 6, "particle 0: vy: expected a finite number");
    expect_error(header + "0 5 5 0 0x10\n", 6, "particle 0: vy: expected a finite number");
    expect_error(header + "0 5 5 0 0\n1 6 6 0 0\n", 7, "expected N = 3 particle lines or none, found 2");
    expect_error(header + "0 5 5 0 0\n1 6 6 0 0\n2 7 7 0 0\n2 8 8 0 0\n", 9, "more than N = 3");
    expect_error("0 20 1 5 perf\n0 5 5 0 0\n", 2, "N = 0, but a particle line follows");
    expect_error(header + std::string(5000, '1') + "\n", 6, "the line is longer than 4096 characters");
}

// The accepted range (docs/accepted-range.md).
void accepted_range() {
    CHECK(read("1 1e60 1e-60 1 perf\n0 5e59 5e59 1e60 -1e60\n").ok);
    expect_error("1 1e60 1e-61 1 perf\n", 1, "r = 1e-61 is below the accepted range (L and r at least 1e-60");
    expect_error("1 2e60 1 1 perf\n", 1, "L = 2e60 is beyond the accepted range");
    expect_error("1 1e-310 1e-311 1 perf\n", 1, "L = 1e-310 is below the accepted range");
    expect_error("1 20 1 1 perf\n0 5 5 1.5e60 0\n", 2, "particle 0: vx = 1.5e60 is beyond the accepted range");
    // Item 1: a random scene whose speeds (up to L/(8r)) would leave the range
    // is refused on the line of r, not run into infinities.
    expect_error("3\n20000\n1e-300\n1\nprint\n", 3, "r = 1e-300 is below the accepted range");
    expect_error("3\n20000\n1e-57\n1\nprint\n", 3, "draws speeds up to L/(8r) = 2.5e+60");
    expect_error("3\n1e10\n1e-60\n1\nprint\n", 3, "beyond the accepted range (at most 1e60)");
    // Listed particles may be that fast or slow; only the random draw is refused.
    CHECK(read("1\n20000\n1e-55\n1\nprint\n0 5 5 1e59 1e-300\n").ok);
    CHECK(read("3\n1\n1e-50\n1\nprint\n").ok);
}

// What every C and Python reader accepts, and messages a person can read.
void friendly_input() {
    const Outcome plus = read("+2 +20 +1 +5 print\n+0 +5 +5 +1e-1 -0\n1 15 12 +.5 0\n");
    CHECK(plus.ok);
    CHECK_EQ(plus.scene.particle_count, 2U);
    CHECK_EQ(plus.scene.particles[1].velocity.x(), 0.5);
    expect_error("++2 20 1 5 perf\n", 1, "found \"++2\"");
    expect_error("+-2 20 1 5 perf\n", 1, "found \"+-2\"");
    expect_error("1 20 1 5 perf\n0 5 5 +-1 0\n", 2, "vx: expected a finite number, found \"+-1\"");

    const Outcome marked = read(
        "\xEF\xBB\xBF"
        "1 20 1 5 perf\n0 5 5 0 0\n");
    CHECK(marked.ok);
    // Only at the start of the file; elsewhere the bytes are shown escaped.
    expect_error(
        "1 20 1 5 perf\n\xEF\xBB\xBF"
        "0 5 5 0 0\n",
        2, "found \"\\xEF\\xBB\\xBF0\"");
    expect_error(std::string("1 2\0"
                             "0 1 5 perf\n",
                             15),
                 1, "L: expected a finite number, found \"2\\x000\"");
    expect_error("1 20 1 5 p\x01rint\n", 1, "found \"p\\x01rint\"");

    // A line's length does not count its line ending.
    const std::string full_line = "0 5 5 0 0" + std::string(max_line_length - 9, ' ');
    CHECK_EQ(full_line.size(), max_line_length);
    CHECK(read("1 20 1 5 perf\n" + full_line + "\r\n").ok);
    CHECK(read("1 20 1 5 perf\n" + full_line + "\n").ok);
    expect_error("1 20 1 5 perf\n" + full_line + " \r\n", 2, "longer than 4096");
    expect_error("1 20 1 5 perf\n" + full_line + "\r\r\n", 2, "longer than 4096");

    // Numbers in messages are readable whatever their size.
    expect_error("1 20 1 5 perf\n0 1e-300 5 0 0\n", 2, "x = 1e-300 is outside [1, 19]");
}

// Memory follows the input, not the header's claim.
void memory_follows_the_input() {
    // A 43-byte file claiming N = 9e7 allocates nothing much larger than the
    // file before failing (not the 4.9 GB the claim would take).
    largest_allocation = 0;
    const Outcome o = read("90000000 20000 1 10 perf\n0 1 1 1 1\n");
    CHECK(largest_allocation.load() < (std::size_t{1} << 20));
    CHECK(!o.ok);
    CHECK(o.message.find("expected N = 90000000 particle lines or none, found 1") != std::string::npos);
    // Lines are remembered for messages about the scene.
    SceneLines lines;
    std::istringstream in("2 20 1 5 perf\n\n1 15 12 0 0\n0 5 5 0 0\n");
    const Scene scene = read_scene(in, &lines);
    CHECK_EQ(scene.particles.size(), 2U);
    CHECK_EQ(lines.particles.size(), 2U);
    CHECK_EQ(lines.particles[0], 4L);
    CHECK_EQ(lines.particles[1], 3L);
}

// write_scene() writes what read_scene() reads back to the same scene, a
// random one included, and refuses, writing nothing, what the reader would
// refuse.
void scenes_written_read_back() {
    for (const std::string text : {"1000\n20000\n1\n1000\nprint\n", "0\n10\n1\n0\nperf\n",
                                   "2\n10\n0.5\n3\nperf\n0 1 1 0.25 -0.125\n1 9 2.5 0 1e-3\n"}) {
        const check::Context context(text);
        const Outcome first = read(text);
        CHECK(first.ok);
        std::ostringstream written;
        write_scene(written, first.scene);
        const Outcome again = read(written.str());
        CHECK(again.ok);
        CHECK_EQ(again.scene.particle_count, first.scene.particle_count);
        CHECK_EQ(again.scene.is_random(), first.scene.is_random());
        CHECK_EQ(again.scene.world.box_size, first.scene.world.box_size);
        CHECK_EQ(again.scene.world.radius, first.scene.world.radius);
        CHECK_EQ(again.scene.steps, first.scene.steps);
        CHECK(again.scene.mode == first.scene.mode);
        CHECK_EQ(again.scene.particles.size(), first.scene.particles.size());
        for (std::size_t i = 0; i < first.scene.particles.size(); ++i) {
            CHECK(again.scene.particles[i].position == first.scene.particles[i].position);
            CHECK(again.scene.particles[i].velocity == first.scene.particles[i].velocity);
        }
    }
    CHECK_EQ(read("1000\n20000\n1\n1000\nprint\n").scene.is_random(), true);

    const auto refusal = [](const Scene& scene) {
        std::ostringstream written;
        try {
            write_scene(written, scene);
        } catch (const std::invalid_argument& e) {
            CHECK_EQ(written.str(), "");
            return std::string(e.what());
        }
        return std::string();
    };
    Scene good = read("2\n10\n0.5\n3\nperf\n0 1 1 0.25 -0.125\n1 9 2.5 0 1e-3\n").scene;
    CHECK_EQ(refusal(good), "");
    Scene bad = good;
    bad.world.box_size = std::numeric_limits<double>::quiet_NaN();
    CHECK(refusal(bad).find("the box size and the radius") != std::string::npos);
    bad = good;
    bad.steps = -1;
    CHECK(refusal(bad).find("steps must be >= 0") != std::string::npos);
    bad = good;
    bad.mode = static_cast<OutputMode>(7);
    CHECK(refusal(bad).find("print or perf") != std::string::npos);
    bad = good;
    bad.particles[1].velocity.x() = std::numeric_limits<double>::infinity();
    CHECK_EQ(refusal(bad), "particlesim::write_scene: particle 1 has a number beyond the accepted range (or NaN)");
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_scene_reader",
                      {{"valid scenes", valid_scenes},
                       {"bad headers", bad_headers},
                       {"bad particles", bad_particles},
                       {"accepted range", accepted_range},
                       {"friendly input", friendly_input},
                       {"memory follows the input", memory_follows_the_input},
                       {"scenes written read back", scenes_written_read_back}});
}
