#include "checkpoint.hpp"

#include "particlesim/saved_state.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace simcli {

namespace {

constexpr std::string_view magic = "particlesim-checkpoint";
constexpr std::string_view format_version = "1";

double finite_real(particlesim::SavedStateReader& in) {
    const double value = in.real();
    if (!std::isfinite(value)) in.fail("a bad number");
    return value;
}

}  // namespace

void write_settings(std::ostream& out, const RunSettings& s) {
    // The numbers as the engines' saved states write them (exact, shortest form).
    out << magic << ' ' << format_version << '\n' << "box-size ";
    particlesim::save_number(out, s.world.box_size);
    out << "radius ";
    particlesim::save_number(out, s.world.radius);
    out << "steps " << s.steps << " mode " << (s.mode == particlesim::OutputMode::print ? "print" : "perf")
        << " engine "
        << (s.engine == EngineChoice::step                  ? "step"
            : s.boundary == particlesim::Boundary::periodic ? "exact-periodic"
                                                            : "exact")
        << " substeps " << s.substeps << " numbers "
        << (s.numbers == particlesim::NumberFormat::shortest ? "shortest" : "fixed8") << '\n';
}

Checkpoint read_checkpoint(const std::string& path) {
    auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
    if (!*file) throw std::invalid_argument(path + ": cannot open the checkpoint");
    particlesim::SavedStateReader in(*file, path + ": not a checkpoint simcli can resume");
    in.expect(magic);
    in.expect(format_version);
    Checkpoint checkpoint;
    RunSettings& s = checkpoint.settings;
    in.expect("box-size");
    s.world.box_size = finite_real(in);
    in.expect("radius");
    s.world.radius = finite_real(in);
    in.expect("steps");
    s.steps = static_cast<std::int64_t>(in.count(INT64_MAX));
    in.expect("mode");
    const std::string mode = in.word();
    if (mode != "print" && mode != "perf") in.fail("an unknown output mode");
    s.mode = mode == "print" ? particlesim::OutputMode::print : particlesim::OutputMode::perf;
    in.expect("engine");
    const std::string engine = in.word();
    if (engine != "step" && engine != "exact" && engine != "exact-periodic") in.fail("an unknown engine");
    s.engine = engine == "step" ? EngineChoice::step : EngineChoice::exact;
    s.boundary = engine == "exact-periodic" ? particlesim::Boundary::periodic : particlesim::Boundary::walls;
    in.expect("substeps");
    s.substeps = static_cast<int>(in.count(1 << 20));
    if (s.substeps < 1) in.fail("substeps below 1");
    in.expect("numbers");
    const std::string numbers = in.word();
    // "exact" is what checkpoints of version 0.1.0 call the shortest form.
    if (numbers != "fixed8" && numbers != "shortest" && numbers != "exact") in.fail("an unknown number format");
    s.numbers = numbers == "fixed8" ? particlesim::NumberFormat::fixed8 : particlesim::NumberFormat::shortest;
    checkpoint.engine_state = std::move(file);
    return checkpoint;
}

}  // namespace simcli
