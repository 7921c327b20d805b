// simcli's pictures in a real browser: pages written by --animate are opened
// in headless Chromium, which drives them through their self-test hook and
// reports back: the colour under each disk of the chosen frame (at positions
// taken from simcli's own print output, so a wrong frame, axis or scale shows),
// what play, the scrubber and the keys did, the collision counts the plot
// shows (against the library's per-step counts), console errors and network
// requests. Also the SVG of --snapshot: the state in pixels, the same
// picture for a scene scaled by 2^k, drawn at any scale with its caption
// inside it. Exit 77 (skipped) without Chromium.

#include "check.hpp"
#include "mini_json.hpp"
#include "run_process.hpp"
#include "scaled_by_power_of_two.hpp"

#include "particlesim/particlesim.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

const std::string simcli = SIMCLI_PATH;

std::string work_dir() {
    static const std::string dir = [] {
        char name[] = "/tmp/particlesim-animation-XXXXXX";
        return std::string(mkdtemp(name));
    }();
    return dir;
}

std::string chromium_path() {
    if (const char* given = std::getenv("CHROMIUM")) return given;
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
            const std::string candidate = dir + "/" + name;
            if (access(candidate.c_str(), X_OK) == 0) return candidate;
        }
    }
    return "";
}

// Each step's particles, from a print-mode output.
std::vector<std::vector<Particle>> read_states(const std::string& output) {
    std::vector<std::vector<Particle>> states;
    std::istringstream in(output);
    std::int64_t step = 0;
    std::size_t index = 0;
    Particle p;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        fields >> step >> index >> p.position.x() >> p.position.y() >> p.velocity.x() >> p.velocity.y();
        if (static_cast<std::size_t>(step) >= states.size()) states.resize(static_cast<std::size_t>(step) + 1);
        states[static_cast<std::size_t>(step)].push_back(p);
    }
    return states;
}

std::string percent_encoded(const std::string& text) {
    std::string out;
    for (const unsigned char c : text) {
        if (std::isalnum(c)) {
            out += static_cast<char>(c);
        } else {
            char code[4];
            std::snprintf(code, sizeof code, "%%%02X", c);
            out += code;
        }
    }
    return out;
}

std::string point(const Vec2& at) {
    char text[80];
    std::snprintf(text, sizeof text, "[%.9g,%.9g]", at.x(), at.y());
    return text;
}

std::string points(const std::vector<Vec2>& list) {
    std::string out = "[";
    for (std::size_t k = 0; k < list.size(); ++k) out += (k ? "," : "") + point(list[k]);
    return out + "]";
}

struct PageRun {
    mini_json::Value report;
    double seconds = 0.0;
    std::string log;
};

// Opens `page` with the self-test request; what the page reports about itself.
// `window`: Chromium's --window-size (empty: its default).
PageRun open_page(const std::string& page, const std::string& request, int budget_ms = 8000,
                  const std::string& window = "") {
    const std::string profile = work_dir() + "/profile";
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::string> args{"--headless",
                                  "--no-sandbox",
                                  "--disable-gpu",
                                  "--no-first-run",
                                  "--user-data-dir=" + profile,
                                  "--enable-logging=stderr",
                                  "--v=0",
                                  "--virtual-time-budget=" + std::to_string(budget_ms)};
    if (!window.empty()) args.push_back("--window-size=" + window);
    args.insert(args.end(), {"--dump-dom", "file://" + page + "#selftest=" + percent_encoded(request)});
    const run_process::Result r = run_process::run(chromium_path(), args);
    PageRun run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.log = r.err;
    const std::string opening = "<pre id=\"selftest\">";
    const std::size_t begin = r.out.find(opening);
    const std::size_t end = begin == std::string::npos ? begin : r.out.find("</pre>", begin);
    if (end == std::string::npos) {
        std::fprintf(stderr, "no self-test report from %s (status %d)\n%s\n", page.c_str(), r.status,
                     r.err.substr(0, 2000).c_str());
        CHECK(false);
        return run;
    }
    // The DOM dump escapes quotes as &quot;.
    std::string json;
    for (std::size_t at = begin + opening.size(); at < end;) {
        if (r.out.compare(at, 6, "&quot;") == 0) {
            json += '"';
            at += 6;
        } else {
            json += r.out[at++];
        }
    }
    run.report = mini_json::parse(json);
    return run;
}

bool colour_is(const mini_json::Value& pixel, int red, int green, int blue) {
    return pixel[0].number == red && pixel[1].number == green && pixel[2].number == blue;
}

// Points inside the box at least `clearance` from every centre.
std::vector<Vec2> empty_points(const std::vector<Particle>& particles, double box, double clearance,
                               std::size_t wanted) {
    std::vector<Vec2> found;
    for (int k = 1; k < 40 && found.size() < wanted; ++k) {
        for (int m = 1; m < 40 && found.size() < wanted; ++m) {
            const Vec2 point(box * k / 40.0, box * m / 40.0);
            bool clear = true;
            for (const Particle& p : particles) clear = clear && (p.position - point).norm() > clearance;
            if (clear) found.push_back(point);
        }
    }
    return found;
}

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = work_dir() + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

void the_page_shows_the_run() {
    // A small box (L = 24, r = 1: a disk is 60 pixels wide) with collisions and walls.
    const std::string scene = write_file("small.in",
                                         "6 24 1 12 print\n"
                                         "0 3 12 1.5 0\n1 12 12 0 0\n2 14 12 0 0\n3 16 12 0 0\n"
                                         "4 6 4 0.75 0.5\n5 20 20 -1 -0.25\n");
    const std::string page = work_dir() + "/small.html";
    const run_process::Result out = run_process::run(simcli, {scene, "--animate", page});
    CHECK_EQ(out.status, 0);
    const auto states = read_states(out.out);
    CHECK_EQ(states.size(), 13U);
    const int frame = 6, scrub = 9;
    std::vector<Vec2> on, scrubbed_on;
    for (const Particle& p : states[frame]) on.push_back(p.position);
    for (const Particle& p : states[scrub]) scrubbed_on.push_back(p.position);
    const std::vector<Vec2> off = empty_points(states[frame], 24.0, 1.4, 12);
    CHECK(off.size() >= 8);
    // A click on disk 4 chooses it.
    const int clicked = 4;
    const std::string request = "{\"frame\":" + std::to_string(frame) + ",\"on\":" + points(on) +
                                ",\"off\":" + points(off) + ",\"scrubTo\":" + std::to_string(scrub) +
                                ",\"scrubOn\":" + points(scrubbed_on) +
                                ",\"click\":" + point(states[frame][clicked].position) + "}";
    // In a window narrower than the box (headless Chromium makes one at
    // least 500 wide; the box is 722), which the box shrinks to fit: the
    // click goes through the drawn size.
    const PageRun run = open_page(page, request, 8000, "500,800");
    const mini_json::Value& r = run.report;
    if (r.kind != mini_json::Value::Kind::object) return;
    CHECK_EQ(r["chosen"].number, static_cast<double>(clicked));
    const mini_json::Value& layout = r["layout"];
    const double window_width = layout["windowWidth"].number;
    CHECK(window_width < 600.0);
    CHECK(layout["pageWidth"].number <= window_width);
    CHECK(layout["boxWidth"].number < window_width && layout["boxWidth"].number > 0.8 * window_width);
    CHECK(std::fabs(layout["boxWidth"].number - layout["boxHeight"].number) < 1.0);
    CHECK_EQ(r["frames"].number, 13.0);
    CHECK_EQ(r["shownFrame"].number, static_cast<double>(frame));
    int orange = 0, white = 0, scrubbed = 0;
    for (const auto& pixel : r["on"].items) orange += colour_is(pixel, 232, 89, 12);
    for (const auto& pixel : r["off"].items) white += colour_is(pixel, 255, 255, 255);
    for (const auto& pixel : r["scrubbedOn"].items) scrubbed += colour_is(pixel, 232, 89, 12);
    CHECK_EQ(orange, 6);
    CHECK_EQ(white, static_cast<int>(off.size()));
    CHECK_EQ(r["afterScrub"].number, static_cast<double>(scrub));
    CHECK_EQ(scrubbed, 6);
    CHECK_EQ(r["afterRight"].number, static_cast<double>(scrub + 1));
    CHECK_EQ(r["afterLeft"].number, static_cast<double>(scrub));
    CHECK(r["afterPlay"].number > 0);  // a second of play at 20 frames a second
    CHECK(r["errors"].items.empty());
    CHECK_EQ(r["resources"].number, 0.0);
    CHECK(run.log.find("Uncaught") == std::string::npos);
    // The collisions plot: the library's counts, step by step.
    std::istringstream in(run_process::slurp(scene));
    const Scene parsed = read_scene(in);
    SteppedSimulation engine(parsed.world, parsed.particles);
    const auto& shown = r["collisions"].items;
    CHECK_EQ(shown.size(), 12U);
    int matching = 0, busy = 0;
    for (std::size_t s = 0; s < shown.size(); ++s) {
        engine.step();
        matching += shown[s][0].number == static_cast<double>(engine.last_step().particle_collisions) &&
                    shown[s][1].number == static_cast<double>(engine.last_step().wall_collisions);
        busy += engine.last_step().particle_collisions + engine.last_step().wall_collisions > 0;
    }
    CHECK_EQ(matching, 12);
    CHECK(busy >= 4);
    // The label is the plot's key: each count in its line's colour.
    const auto& key = r["collisionsKey"].items;
    CHECK_EQ(key.size(), 2U);
    if (key.size() == 2) {
        CHECK(key[0][0].text.rfind("particles ", 0) == 0);
        CHECK_EQ(key[0][1].text, std::string("rgb(214, 51, 108)"));
        CHECK(key[1][0].text.rfind("walls ", 0) == 0);
        CHECK_EQ(key[1][1].text, std::string("rgb(28, 126, 214)"));
    }
    // The plot's ends are whole counts here, written as such ("0", not "0.00000").
    const auto& ends = r["collisionsPlot"].items;
    const auto& end_texts = r["collisionsPlotText"].items;
    CHECK_EQ(ends.size(), 2U);
    CHECK_EQ(end_texts.size(), 2U);
    if (ends.size() == 2 && end_texts.size() == 2) {
        CHECK(ends[1].number > ends[0].number);
        for (std::size_t i = 0; i < 2; ++i) {
            CHECK_EQ(ends[i].number, std::floor(ends[i].number));
            CHECK_EQ(end_texts[i].text, std::to_string(static_cast<long long>(ends[i].number)));
        }
    }
}

void exact_engine_between_steps() {
    // --animate-every 0.25: four frames a step; every fourth is a whole step of the run.
    const std::string scene = write_file("exact.in", "3 24 1 8 print\n0 3 12 1.5 0\n1 12 12 0 0\n2 14 12 0 0\n");
    const std::string page = work_dir() + "/exact.html";
    const run_process::Result out =
        run_process::run(simcli, {scene, "--engine", "exact", "--animate", page, "--animate-every", "0.25"});
    CHECK_EQ(out.status, 0);
    const auto states = read_states(out.out);
    std::vector<Vec2> on, scrubbed_on;
    for (const Particle& p : states[5]) on.push_back(p.position);
    for (const Particle& p : states[7]) scrubbed_on.push_back(p.position);
    const std::string request =
        "{\"frame\":20,\"on\":" + points(on) + ",\"off\":[],\"scrubTo\":28,\"scrubOn\":" + points(scrubbed_on) + "}";
    const mini_json::Value r = open_page(page, request).report;
    if (r.kind != mini_json::Value::Kind::object) return;
    CHECK_EQ(r["frames"].number, 33.0);
    int orange = 0;
    for (const auto& pixel : r["on"].items) orange += colour_is(pixel, 232, 89, 12);
    for (const auto& pixel : r["scrubbedOn"].items) orange += colour_is(pixel, 232, 89, 12);
    CHECK_EQ(orange, 6);
    CHECK(r["errors"].items.empty());
    // Refused where it means nothing: the step rules have no state between steps.
    CHECK_EQ(run_process::run(simcli, {scene, "--animate", page, "--animate-every", "0.25"}).status, 2);
    CHECK_EQ(run_process::run(simcli, {scene, "--animate-every", "2"}).status, 2);
    CHECK_EQ(run_process::run(simcli, {scene, "--engine", "exact", "--animate", page, "--animate-every", "0.3"}).status,
             2);
    // 1/k of a step for k up to 1000, and the refusal says so.
    const run_process::Result finer =
        run_process::run(simcli, {scene, "--engine", "exact", "--animate", page, "--animate-every", "0.0005"});
    CHECK_EQ(finer.status, 2);
    CHECK(finer.err.find("1/k of a step for k up to 1000") != std::string::npos);
}

void large_runs_stay_in_budget() {
    // The default scene (1000 particles, 1000 steps) keeps every frame and opens;
    // 100 000 particles render as points; a long run keeps one frame in K and says so.
    struct Case {
        const char* name;
        std::string scene;
    };
    const std::vector<Case> cases{{"default", "1000 20000 1 1000 perf\n"}, {"100k", "100000 40000 1 5 perf\n"}};
    for (const Case& c : cases) {
        const std::string page = work_dir() + "/" + c.name + ".html";
        const run_process::Result out = run_process::run(simcli, {"--animate", page, "-o", "/dev/null"}, c.scene);
        CHECK_EQ(out.status, 0);
        const auto size = std::filesystem::file_size(page);
        CHECK(size < 50'000'000);
        // Probe 20 disks of the first frame (from the same scene drawn again).
        std::istringstream in(c.scene);
        const Scene scene = read_scene(in);
        const auto particles = make_random_particles(scene.particle_count, scene.world);
        std::vector<Vec2> on;
        for (std::size_t i = 0; i < 20; ++i) on.push_back(particles[i * (particles.size() / 20)].position);
        const PageRun run = open_page(page, "{\"frame\":0,\"on\":" + points(on) + ",\"off\":[],\"scrubTo\":1}", 20000);
        const mini_json::Value& r = run.report;
        if (r.kind != mini_json::Value::Kind::object) continue;
        int orange = 0;
        for (const auto& pixel : r["on"].items) orange += colour_is(pixel, 232, 89, 12);
        CHECK_EQ(orange, 20);
        CHECK(r["errors"].items.empty());
        CHECK_EQ(r["resources"].number, 0.0);
        std::printf(
            "%s: page %.1f MB, %d frames, first frame drawn %.0f ms after the page began to load (script "
            "%.0f ms), a frame drawn in %.1f ms, chromium run %.1f s\n",
            c.name, static_cast<double>(size) / 1e6, static_cast<int>(r["frames"].number), r["openMs"].number,
            r["scriptMs"].number, r["drawMs"].number, run.seconds);
    }
    const std::string page = work_dir() + "/long.html";
    const run_process::Result out =
        run_process::run(simcli, {"--animate", page, "-o", "/dev/null"}, "50000 100000 1 40 perf\n");
    CHECK_EQ(out.status, 0);
    CHECK(out.err.find("simcli: --animate keeps one frame in ") != std::string::npos);
    CHECK(std::filesystem::file_size(page) < 50'000'000);

    // So many particles that the first and the last frame alone may pass the
    // budget: the note says how large the page may grow instead of promising
    // the budget, and its bound holds.
    const std::string crowded_page = work_dir() + "/crowded.html";
    const run_process::Result crowded =
        run_process::run(simcli, {"--animate", crowded_page, "-o", "/dev/null"}, "700000 300000 1 1 perf\n");
    CHECK_EQ(crowded.status, 0);
    CHECK(crowded.err.find("stays under") == std::string::npos);
    const std::string note =
        "simcli: --animate keeps only the first and the last frame, and the page may still reach about ";
    const std::size_t at = crowded.err.find(note);
    CHECK(at != std::string::npos);
    if (at != std::string::npos) {
        const double claimed_mb = std::strtod(crowded.err.c_str() + at + note.size(), nullptr);
        CHECK(claimed_mb > 50.0);
        CHECK(static_cast<double>(std::filesystem::file_size(crowded_page)) <= claimed_mb * 1e6 + 0.5e6);
    }
}

// The value of the attribute `name` of the SVG element at or after `from`
// (the first `name="` there): the text up to its closing quote.
std::string attribute(const std::string& svg_text, std::size_t from, const std::string& name) {
    const std::size_t start = svg_text.find(" " + name + "=\"", from - (from > 0 ? 1 : 0));
    if (start == std::string::npos) return {};
    const std::size_t value = start + name.size() + 3;
    return svg_text.substr(value, svg_text.find('"', value) - value);
}

void snapshot_is_the_state() {
    const std::string scene =
        write_file("snap.in", "5 20 1 12 print\n0 4 10 0.5 0\n1 8 10 0 0\n2 10 10 0 0\n3 12 10 0 0\n4 14 10 0 0\n");
    const std::string svg = work_dir() + "/snap.svg";
    const run_process::Result out = run_process::run(simcli, {scene, "--snapshot", svg, "--snapshot-step", "9"});
    CHECK_EQ(out.status, 0);
    const auto states = read_states(out.out);
    const std::string text = run_process::slurp(svg);
    // In pixels: the box of side 20 is 720 wide, y upwards.
    const double pixels = 720.0 / 20.0;
    std::size_t k = 0;
    for (std::size_t at = text.find("<circle "); at != std::string::npos; at = text.find("<circle ", at + 1), ++k) {
        CHECK(k < 5);
        if (k >= 5) break;
        CHECK_NEAR(std::stod(attribute(text, at, "cx")), pixels * states[9][k].position.x(), 1e-4);
        CHECK_NEAR(std::stod(attribute(text, at, "cy")), 720.0 - pixels * states[9][k].position.y(), 1e-4);
        CHECK_EQ(std::stod(attribute(text, at, "r")), pixels);
    }
    CHECK_EQ(k, 5U);
    CHECK(text.find(">step 9, 5 particles") != std::string::npos);
    CHECK_EQ(run_process::run(simcli, {scene, "--snapshot", svg, "--snapshot-step", "13"}).status, 2);
    CHECK_EQ(run_process::run(simcli, {scene, "--snapshot-step", "3"}).status, 2);
}

Scene scaled_scene(Scene scene, int k) {
    scale_by_power_of_two(scene.world, scene.particles, k);
    return scene;
}

std::string scene_file(const std::string& name, const Scene& scene) {
    std::ostringstream text;
    write_scene(text, scene);
    return write_file(name, text.str());
}

// 100 disks in a triangular lattice at 0.7 that fills a periodic box.
Scene periodic_lattice(std::int64_t steps) {
    SceneFamilyOptions o;
    o.particles = 100;
    o.area_fraction = 0.7;
    o.boundary = Boundary::periodic;
    o.steps = steps;
    return make_family_scene(SceneFamily::crystal, o);
}

// The lines of a snapshot but its caption (the <text> lines, which name L and r).
std::string without_caption(const std::string& svg_text) {
    std::istringstream lines(svg_text);
    std::string kept;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("<text ", 0) != 0) kept += line + "\n";
    }
    return kept;
}

// A scene scaled by 2^k runs to the scaled states (rules.md), so its
// snapshot is the same picture, byte for byte but for the caption's L and r:
// walled and coloured by speed, and periodic (images at the edges) by psi6.
void scaled_scene_draws_the_same_picture() {
    SceneFamilyOptions gas;
    gas.particles = 60;
    gas.steps = 5;
    SceneFamilyOptions crystal = gas;
    crystal.area_fraction = 0.6;
    crystal.boundary = Boundary::periodic;
    const std::vector<std::pair<Scene, std::vector<std::string>>> cases{
        {make_family_scene(SceneFamily::gas, gas), {}},
        {make_family_scene(SceneFamily::crystal, crystal),
         {"--engine", "exact", "--boundary", "periodic", "--colour-by", "psi6"}}};
    for (const auto& [scene, options] : cases) {
        std::string pictures[3];
        const int scales[3] = {0, -40, 40};
        for (int k = 0; k < 3; ++k) {
            const std::string svg = work_dir() + "/scaled-" + std::to_string(k) + ".svg";
            std::vector<std::string> args = options;
            args.insert(args.end(), {scene_file("scaled.in", scaled_scene(scene, scales[k])), "-o", "/dev/null",
                                     "--snapshot", svg});
            CHECK_EQ(run_process::run(simcli, args).status, 0);
            pictures[k] = run_process::slurp(svg);
        }
        const check::Context context(options.empty() ? "the gas" : "the crystal, by psi6");
        CHECK(pictures[0].find("<circle ") != std::string::npos);
        CHECK(without_caption(pictures[1]) == without_caption(pictures[0]));
        CHECK(without_caption(pictures[2]) == without_caption(pictures[0]));
        CHECK(pictures[1].find(">step 5, 60 particles, L = ") != std::string::npos);
    }
}

// The page of a scene scaled by 2^k shows each disk of the chosen frame
// where simcli printed it (--exact-numbers: eight decimals print 0 for
// all), nothing where no disk is, and no overlap: at
// 2^-170 (a box of 1.7e-50, whose float32 frames once rounded to 0 and
// stacked every disk at the origin) and at 2^166 as at 2^0.
void page_draws_at_any_scale() {
    Scene three;
    three.world = World{20.0, 0.5};
    three.steps = 2;
    three.mode = OutputMode::print;
    three.particle_count = 3;
    for (const auto& [x, y, vx, vy] :
         std::vector<std::array<double, 4>>{{4.0, 10.0, 0.6, 0.02}, {16.0, 10.0, -0.6, 0.0}, {10.0, 4.0, 0.0, 0.2}}) {
        Particle p;
        p.position = Vec2(x, y);
        p.velocity = Vec2(vx, vy);
        three.particles.push_back(p);
    }
    for (const int k : {0, -170, 166}) {
        const Scene scene = scaled_scene(three, k);
        const std::string page = work_dir() + "/scaled.html";
        const run_process::Result out =
            run_process::run(simcli, {scene_file("scaled-three.in", scene), "--exact-numbers", "--animate", page});
        CHECK_EQ(out.status, 0);
        const auto states = read_states(out.out);
        if (states.size() != 3) continue;
        std::vector<Vec2> on;
        for (const Particle& p : states[2]) on.push_back(p.position);
        const double L = scene.world.box_size;
        const std::vector<Vec2> off{{0.5 * L, 0.9 * L}, {0.9 * L, 0.9 * L}, {0.1 * L, 0.1 * L}};
        const mini_json::Value r =
            open_page(page, "{\"frame\":2,\"on\":" + points(on) + ",\"off\":" + points(off) + ",\"scrubTo\":1}").report;
        if (r.kind != mini_json::Value::Kind::object) continue;
        const check::Context context("the scene scaled by 2^" + std::to_string(k));
        for (const mini_json::Value& pixel : r["on"].items) CHECK(colour_is(pixel, 232, 89, 12));
        for (const mini_json::Value& pixel : r["off"].items) CHECK(colour_is(pixel, 255, 255, 255));
        CHECK_EQ(r["overlapLabel"].text, std::string());
        CHECK(r["errors"].items.empty());
    }
}

// Snapshots in Chromium, drawn into a canvas: each disk's centre shows a
// disk, not the background, and each caption line lies inside the picture,
// below the box and below the line before. The longest captions (psi6's
// legend; speeds and lengths in exponent notation), and boxes of 1e-7 and
// 1.2e7, which once drew nothing, and a caption too small to see.
void snapshot_draws_at_any_scale() {
    const std::string lattice = scene_file("any-lattice.in", periodic_lattice(2));
    const std::string wide = write_file("any-wide.in",
                                        "2 1.23456e+07 0.000123456 123456 perf\n"
                                        "0 1.1e6 2.2e6 0.000123456 -1.5e-5\n"
                                        "1 3.3e6 4.4e6 -1.23456e+06 0\n");
    const std::string tiny = write_file("any-tiny.in",
                                        "3 1e-7 1e-9 2 print\n0 2e-8 5e-8 3e-9 1e-10\n"
                                        "1 8e-8 5e-8 -3e-9 0\n2 5e-8 2e-8 0 1e-9\n");
    const std::string huge = write_file("any-huge.in",
                                        "3 1.2e7 1e5 2 print\n0 2e6 5e6 3e5 1e4\n"
                                        "1 8e6 5e6 -3e5 0\n2 5e6 2e6 0 1e5\n");
    const std::vector<std::vector<std::string>> runs{
        {lattice, "--engine", "exact", "--boundary", "periodic", "--colour-by", "psi6"}, {wide}, {tiny}, {huge}};
    for (const std::vector<std::string>& run : runs) {
        const std::string svg = work_dir() + "/any.svg";
        std::vector<std::string> args = run;
        args.insert(args.end(), {"-o", "/dev/null", "--snapshot", svg});
        CHECK_EQ(run_process::run(simcli, args).status, 0);
        const std::string svg_text = run_process::slurp(svg);
        // The picture inline (for the caption's boxes) and as an image
        // drawn into a canvas (for the pixels), in a page that reports as
        // the animation pages do.
        const std::string page = write_file(
            "any.html",
            "<!doctype html><html><body style=\"margin:0\">" + svg_text +
                "<pre id=\"selftest\"></pre><script>\n"
                "const svg = document.querySelector('svg'), view = svg.viewBox.baseVal;\n"
                "const frame = svg.querySelector('rect').getBoundingClientRect(), at = svg.getBoundingClientRect();\n"
                "const lines = [...svg.querySelectorAll('text')].map(t => { const b = t.getBoundingClientRect();\n"
                "  return [b.left - at.left, b.top - at.top, b.right - at.left, b.bottom - at.top]; });\n"
                "const disks = [...svg.querySelectorAll('circle')].map(c => { const b = c.getBoundingClientRect();\n"
                "  return [(b.left + b.right) / 2 - at.left, (b.top + b.bottom) / 2 - at.top, b.width / 2,\n"
                "          c.getAttribute('fill')]; })\n"
                "  .filter(([x, y]) => x > frame.left - at.left && x < frame.right - at.left &&\n"
                "                      y > frame.top - at.top && y < frame.bottom - at.top);\n"
                "const image = new Image();\n"
                "image.onload = () => {\n"
                "  const canvas = document.createElement('canvas');\n"
                "  canvas.width = at.width; canvas.height = at.height;\n"
                "  const context = canvas.getContext('2d');\n"
                "  context.drawImage(image, 0, 0, at.width, at.height);\n"
                "  const centres = disks.map(([x, y, radius, fill]) =>\n"
                "    [...context.getImageData(Math.floor(x), Math.floor(y), 1, 1).data, radius, fill]);\n"
                "  document.getElementById('selftest').textContent = JSON.stringify({width: at.width,\n"
                "    height: at.height, boxBottom: frame.bottom - at.top, lines, centres});\n"
                "};\n"
                "image.src = URL.createObjectURL(new Blob([svg.outerHTML], {type: 'image/svg+xml'}));\n"
                "</script></body></html>\n");
        const mini_json::Value r = open_page(page, "{}").report;
        if (r.kind != mini_json::Value::Kind::object) continue;
        const check::Context context(run.front());
        const std::vector<mini_json::Value>& lines = r["lines"].items;
        CHECK_EQ(lines.size(), std::size_t{2});
        double above = r["boxBottom"].number;
        for (const mini_json::Value& line : lines) {
            CHECK(line[0].number >= 0.0);
            CHECK(line[2].number <= r["width"].number);  // the right edge, which one line ran past
            CHECK(line[1].number >= above);              // below the box, and below the line before
            CHECK(line[3].number <= r["height"].number);
            CHECK(line[3].number - line[1].number >= 10.0);  // a 13-pixel font, not shrunk
            above = line[3].number;
        }
        // Each centre's pixel in the box (a periodic image's centre may lie
        // outside, clipped) [red, green, blue, alpha, radius, fill]: opaque,
        // not the background, and the disk's own fill where the disk is
        // wider than the pixel (a dot of 0.75 pixels blends into the white).
        const std::vector<mini_json::Value>& centres = r["centres"].items;
        CHECK(!centres.empty());
        for (const mini_json::Value& centre : centres) {
            CHECK_EQ(centre[3].number, 255.0);
            CHECK(!colour_is(centre, 255, 255, 255));
            if (centre[4].number >= 2.0) {
                const std::string drawn = "rgb(" + std::to_string(static_cast<int>(centre[0].number)) + "," +
                                          std::to_string(static_cast<int>(centre[1].number)) + "," +
                                          std::to_string(static_cast<int>(centre[2].number)) + ")";
                CHECK_EQ(drawn, centre[5].text);
            }
        }
    }
}

// Each disk's fill in a snapshot, in the order drawn.
std::vector<std::string> disk_colours(const std::string& svg_text) {
    std::vector<std::string> colours;
    for (std::size_t at = svg_text.find("fill=\"rgb("); at != std::string::npos;
         at = svg_text.find("fill=\"rgb(", at + 1)) {
        colours.push_back(attribute(svg_text, at, "fill"));
    }
    return colours;
}

// --colour-by psi6: in a lattice that fills a periodic box every disk sees
// the same neighbourhood, so one psi6 and one colour everywhere, in the
// picture and on the page; a gas many colours; the page plots |psi6| and the
// pressure.
void order_is_seen() {
    const std::string lattice = scene_file("lattice.in", periodic_lattice(4));
    const std::string svg = work_dir() + "/order.svg", page = work_dir() + "/order.html";
    const run_process::Result out =
        run_process::run(simcli, {lattice, "--engine", "exact", "--boundary", "periodic", "--colour-by", "psi6",
                                  "--snapshot", svg, "--snapshot-step", "0", "--animate", page});
    CHECK_EQ(out.status, 0);
    const std::string text = run_process::slurp(svg);
    const std::vector<std::string> lattice_colours = disk_colours(text);
    CHECK(lattice_colours.size() >= std::size_t{100});  // the disks, and the images of those across an edge
    CHECK(std::all_of(lattice_colours.begin(), lattice_colours.end(),
                      [&](const std::string& c) { return c == lattice_colours[0]; }));
    const std::size_t caption = text.find("|psi6| = ");
    CHECK(caption != std::string::npos && std::stod(text.substr(caption + 9)) > 0.9);

    const std::string gas = write_file("order-gas.in", "100 60 1 2 print\n");
    CHECK_EQ(run_process::run(simcli, {gas, "--colour-by", "psi6", "--snapshot", svg}).status, 0);
    std::vector<std::string> colours = disk_colours(run_process::slurp(svg));
    std::sort(colours.begin(), colours.end());
    colours.erase(std::unique(colours.begin(), colours.end()), colours.end());
    CHECK(colours.size() > 20);

    std::vector<Vec2> centres;
    const auto states = read_states(out.out);
    for (const Particle& p : states[0]) centres.push_back(p.position);
    centres.resize(10);
    const mini_json::Value r =
        open_page(page, "{\"frame\":0,\"on\":" + points(centres) + ",\"off\":[],\"scrubTo\":1}").report;
    if (r.kind != mini_json::Value::Kind::object) return;
    const auto& first = r["psi6Colours"][0];
    int alike = 0;
    for (const auto& pixel : r["psi6Colours"].items) {
        alike += colour_is(pixel, static_cast<int>(first[0].number), static_cast<int>(first[1].number),
                           static_cast<int>(first[2].number));
    }
    CHECK_EQ(alike, 10);
    CHECK(!colour_is(first, 255, 255, 255));  // a disk's colour, not the background
    CHECK_EQ(r["psi6Shown"].number, 1.0);
    CHECK_EQ(r["pressureShown"].number, 1.0);
    CHECK(r["psi6"].number > 0.0 && r["psi6"].number <= 1.0);
    CHECK(r["pressure"].number > 0.0);
    // The psi6 plot starts at the first frame (the lattice, |psi6| near 1),
    // and the energy, kept by the exact engine to rounding, draws flat: its
    // plot spans a millionth of it, not the rounding's noise.
    const double psi6_first = r["psi6First"].number;
    CHECK(psi6_first > 0.9);
    CHECK(r["psi6Plot"][0].number <= psi6_first && psi6_first <= r["psi6Plot"][1].number);
    const double energy = r["energy"].number;
    const double energy_span = r["energyPlot"][1].number - r["energyPlot"][0].number;
    CHECK(energy_span >= 0.99e-6 * energy);
    CHECK(r["energyPlot"][0].number <= energy && energy <= r["energyPlot"][1].number);
    // Its end labels differ, in as few digits as tell them apart, none a trailing zero.
    const std::string low_text = r["energyPlotText"][0].text, high_text = r["energyPlotText"][1].text;
    CHECK(low_text != high_text);
    for (const std::string& text : {low_text, high_text}) {
        CHECK(text.find('.') == std::string::npos || text.back() != '0');
        CHECK(std::fabs(std::stod(text) - energy) <= energy_span);
    }
    CHECK(r["errors"].items.empty());
    CHECK_EQ(run_process::run(simcli, {gas, "--colour-by", "psi6"}).status, 2);
    CHECK_EQ(run_process::run(simcli, {gas, "--colour-by", "phase", "--snapshot", svg}).status, 2);
}

// In a periodic box a disk across an edge is drawn on both sides, clipped
// to the box, on the page and in the picture: a disk at x = 19.5 of 20
// shows its image's sliver [0, 0.5] at the left edge, a corner disk at four
// places.
void periodic_images_are_drawn() {
    // Disks 0 to 2 at rest across the edges; disk 3 goes up from y = 19.5
    // through the top edge, to 0.5 and 1.5.
    const std::string scene =
        write_file("edges.in", "4 20 1 2 print\n0 19.5 10 0 0\n1 0.25 19.75 0 0\n2 10 5 0 0\n3 15 19.5 0 1\n");
    const std::string page = work_dir() + "/edges.html", svg = work_dir() + "/edges.svg";
    const run_process::Result out =
        run_process::run(simcli, {scene, "--engine", "exact", "--boundary", "periodic", "--animate", page, "--snapshot",
                                  svg, "--snapshot-step", "0"});
    CHECK_EQ(out.status, 0);
    // At frame 2: the corner disk's images lie at (20.25, 19.75), (0.25, -0.25) and (20.25, -0.25).
    const std::vector<Vec2> on{{0.25, 10.0}, {19.9, 19.9}, {0.1, 0.1}, {19.9, 0.1}, {10.0, 5.0}, {15.0, 1.5}};
    // Disk 3's trail breaks where it wraps: no line across the box at x = 15.
    const std::vector<Vec2> off{{0.25, 13.0}, {19.9, 14.0}, {5.0, 0.1},  {10.0, 19.9},
                                {15.0, 5.0},  {15.0, 10.0}, {15.0, 15.0}};
    // A click at (0.2, 10) lands on disk 0's image at (-0.5, 10), nearer than
    // any disk itself, and chooses disk 0. Its ring (5 pixels outside the
    // disk: 40.4 pixels at 35.4 a unit, 1.1412 units) is drawn round the disk
    // and round the image: through (18.3588, 10) and (0.6412, 10).
    const std::vector<Vec2> on_ring{{18.3588, 10.0}, {0.6412, 10.0}}, off_ring{{1.0, 10.0}};
    const PageRun run = open_page(
        page, "{\"frame\":2,\"trails\":\"all\",\"on\":" + points(on) + ",\"off\":" + points(off) +
                  ",\"scrubTo\":1,\"click\":[0.2,10],\"clickedOn\":" + points({on_ring[0], on_ring[1], off_ring[0]}) +
                  "}");
    const mini_json::Value& r = run.report;
    if (r.kind == mini_json::Value::Kind::object) {
        int orange = 0, white = 0;
        for (const auto& pixel : r["on"].items) orange += colour_is(pixel, 232, 89, 12);
        for (const auto& pixel : r["off"].items) white += colour_is(pixel, 255, 255, 255);
        CHECK_EQ(orange, 6);
        CHECK_EQ(white, 7);
        CHECK_EQ(r["scale"].number, 35.4);  // the ring's points above assume it
        CHECK_EQ(r["chosen"].number, 0.0);
        const auto& ring = r["clickedOn"].items;
        CHECK_EQ(ring.size(), 3U);
        if (ring.size() == 3) {
            CHECK(colour_is(ring[0], 0, 0, 0));
            CHECK(colour_is(ring[1], 0, 0, 0));
            CHECK(colour_is(ring[2], 255, 255, 255));
        }
        CHECK(r["errors"].items.empty());
    }
    // The picture at step 0: 2 + 4 + 1 + 2 circles, and the box clips them.
    const auto circles = [](const std::string& text) {
        std::size_t found = 0;
        for (std::size_t at = text.find("<circle"); at != std::string::npos; at = text.find("<circle", at + 1)) ++found;
        return found;
    };
    const std::string text = run_process::slurp(svg);
    CHECK_EQ(circles(text), std::size_t{9});
    CHECK(text.find("cx=\"-18\" cy=\"360\"") != std::string::npos);  // (-0.5, 10) in pixels, 36 a unit
    CHECK(text.find("clip-path=\"url(#box)\"") != std::string::npos);
    // A walled box draws each disk once.
    const std::string walled = write_file("walled.in", "2 20 1 2 print\n0 19 10 0 0\n1 1 1 0 0\n");
    CHECK_EQ(run_process::run(simcli, {walled, "--snapshot", svg}).status, 0);
    const std::string walled_text = run_process::slurp(svg);
    CHECK(walled_text.find("clip-path") == std::string::npos);
    CHECK_EQ(circles(walled_text), std::size_t{2});
}

}  // namespace

int main(int argc, char** argv) {
    if (chromium_path().empty()) {
        std::printf("SKIPPED: no Chromium (install it with: apt-get install chromium; scripts/run-tests.sh does)\n");
        return 77;
    }
    const int status = check::run(argc, argv, "test_animation",
                                  {{"the page shows the run", the_page_shows_the_run},
                                   {"exact engine between steps", exact_engine_between_steps},
                                   {"large runs stay in budget", large_runs_stay_in_budget},
                                   {"periodic images are drawn", periodic_images_are_drawn},
                                   {"snapshot is the state", snapshot_is_the_state},
                                   {"scaled scene draws the same picture", scaled_scene_draws_the_same_picture},
                                   {"snapshot draws at any scale", snapshot_draws_at_any_scale},
                                   {"page draws at any scale", page_draws_at_any_scale},
                                   {"order is seen", order_is_seen}});
    std::filesystem::remove_all(work_dir());
    return status;
}
