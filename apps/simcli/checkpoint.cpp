#include "checkpoint.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <string_view>

namespace simcli {

namespace {

constexpr std::string_view magic = "particlesim-checkpoint";
constexpr std::string_view format_version = "1";

std::string exact_text(double value) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

class SettingsReader {
public:
    SettingsReader(std::istream& in, const std::string& path) : in_(in), path_(path) {}

    std::string word() {
        std::string token;
        if (!(in_ >> std::setw(65) >> token) || token.size() > 64) fail("it ends early or holds a huge token");
        return token;
    }
    void expect(std::string_view wanted) {
        if (word() != wanted) fail("expected \"" + std::string(wanted) + "\"");
    }
    double real() {
        const std::string token = word();
        double value = 0.0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc{} || end != token.data() + token.size() || !std::isfinite(value)) fail("a bad number");
        return value;
    }
    std::int64_t integer(std::int64_t max) {
        const std::string token = word();
        std::int64_t value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc{} || end != token.data() + token.size() || value < 0 || value > max) fail("a bad count");
        return value;
    }
    [[noreturn]] void fail(const std::string& why) const {
        throw std::invalid_argument(path_ + ": not a checkpoint simcli can resume (" + why + ")");
    }

private:
    std::istream& in_;
    const std::string& path_;
};

}  // namespace

void write_settings(std::ostream& out, const RunSettings& s) {
    out << magic << ' ' << format_version << '\n'
        << "box-size " << exact_text(s.world.box_size) << " radius " << exact_text(s.world.radius) << " steps "
        << s.steps << " mode " << (s.mode == particlesim::OutputMode::print ? "print" : "perf") << " engine "
        << (s.engine == EngineChoice::exact ? "exact" : "step") << " substeps " << s.substeps << " numbers "
        << (s.numbers == particlesim::NumberFormat::shortest ? "exact" : "fixed8") << '\n';
}

Checkpoint read_checkpoint(const std::string& path) {
    auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
    if (!*file) throw std::invalid_argument(path + ": cannot open the checkpoint");
    SettingsReader in(*file, path);
    in.expect(magic);
    in.expect(format_version);
    Checkpoint checkpoint;
    RunSettings& s = checkpoint.settings;
    in.expect("box-size");
    s.world.box_size = in.real();
    in.expect("radius");
    s.world.radius = in.real();
    in.expect("steps");
    s.steps = in.integer(INT64_MAX);
    in.expect("mode");
    const std::string mode = in.word();
    if (mode != "print" && mode != "perf") in.fail("an unknown output mode");
    s.mode = mode == "print" ? particlesim::OutputMode::print : particlesim::OutputMode::perf;
    in.expect("engine");
    const std::string engine = in.word();
    if (engine != "step" && engine != "exact") in.fail("an unknown engine");
    s.engine = engine == "exact" ? EngineChoice::exact : EngineChoice::step;
    in.expect("substeps");
    s.substeps = static_cast<int>(in.integer(1 << 20));
    if (s.substeps < 1) in.fail("substeps below 1");
    in.expect("numbers");
    const std::string numbers = in.word();
    if (numbers != "fixed8" && numbers != "exact") in.fail("an unknown number style");
    s.numbers = numbers == "exact" ? particlesim::NumberFormat::shortest : particlesim::NumberFormat::fixed8;
    checkpoint.engine_state = std::move(file);
    return checkpoint;
}

}  // namespace simcli
