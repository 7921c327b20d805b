#include "checkpoint.hpp"

#include "common/input_path.hpp"
#include "particlesim/saved_state.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string_view>

namespace simcli {

namespace {

constexpr std::string_view magic = "particlesim-checkpoint";
// 2 adds the first part; 1 (0.1.0) is still read.
constexpr std::string_view format_version = "2";

double finite_real(particlesim::SavedStateReader& in) {
    const double value = in.real();
    if (!std::isfinite(value)) in.fail("a bad number");
    return value;
}

// A path as hexadecimal tokens of at most 64 digits (the reader's longest
// token): any bytes, spaces and newlines too.
constexpr std::size_t path_bytes_a_token = 32;

void write_path(std::ostream& out, const std::string& path) {
    constexpr char digits[] = "0123456789abcdef";
    out << path.size();
    for (std::size_t k = 0; k < path.size(); ++k) {
        if (k % path_bytes_a_token == 0) out << ' ';
        const auto byte = static_cast<unsigned char>(path[k]);
        out << digits[byte >> 4] << digits[byte & 15];
    }
    out << ' ';
}

std::string read_path(particlesim::SavedStateReader& in) {
    const std::size_t size = in.count(longest_recorded_path);
    std::string path;
    while (path.size() < size) {
        const std::string token = in.word();
        if (token.size() % 2 != 0 || token.size() / 2 > std::min(path_bytes_a_token, size - path.size())) {
            in.fail("a bad path");
        }
        for (std::size_t k = 0; k < token.size(); k += 2) {
            const auto digit = [&](char c) {
                if (c >= '0' && c <= '9') return c - '0';
                if (c >= 'a' && c <= 'f') return c - 'a' + 10;
                in.fail("a bad path");
            };
            path += static_cast<char>(digit(token[k]) * 16 + digit(token[k + 1]));
        }
    }
    if (path.empty() || path[0] != '/' || path.find('\0') != std::string::npos) in.fail("a bad path");
    return path;
}

void write_first_part(std::ostream& out, const FirstPart& part) {
    std::vector<const KeptFile*> files;  // a path that could not be read back is not recorded
    for (const KeptFile& file : part.files) {
        if (!file.path.empty() && file.path[0] == '/' && file.path.size() <= longest_recorded_path)
            files.push_back(&file);
    }
    out << "first-part " << part.step << " files " << files.size() << '\n';
    for (const KeptFile* kept : files) {
        const KeptFile& file = *kept;
        out << file.kind << ' ';
        particlesim::save_number(out, file.bytes);
        particlesim::save_number(out, file.device);
        particlesim::save_number(out, file.inode);
        write_path(out, file.path);
        out << '\n';
    }
    out << "observables-row ";
    if (part.observables_row) {
        const OpenRow& row = *part.observables_row;
        out << row.step << ' ';
        particlesim::save_counts(out, row.totals);
        particlesim::save_number(out, row.sums.pair_virial);
        particlesim::save_number(out, row.sums.wall_impulse);
    } else {
        out << "none";
    }
    out << '\n';
}

FirstPart read_first_part(particlesim::SavedStateReader& in) {
    FirstPart part;
    part.recorded = true;
    in.expect("first-part");
    part.step = static_cast<std::int64_t>(in.count(INT64_MAX));
    in.expect("files");
    const std::size_t files = in.count(3);
    for (std::size_t k = 0; k < files; ++k) {
        KeptFile file;
        file.kind = in.word();
        if (file.kind != "output" && file.kind != "trajectory" && file.kind != "observables")
            in.fail("an unknown file");
        file.bytes = in.count(INT64_MAX);
        file.device = in.count(UINT64_MAX);
        file.inode = in.count(UINT64_MAX);
        file.path = read_path(in);
        part.files.push_back(std::move(file));
    }
    in.expect("observables-row");
    const std::string step = in.word();
    if (step != "none") {
        OpenRow row;
        std::int64_t value = 0;
        const auto [end, error] = std::from_chars(step.data(), step.data() + step.size(), value);
        if (error != std::errc{} || end != step.data() + step.size() || value < 0 || value > part.step) {
            in.fail("a bad observables row");
        }
        row.step = value;
        row.totals = particlesim::read_counts(in);
        row.sums.pair_virial = finite_real(in);
        row.sums.wall_impulse = finite_real(in);
        part.observables_row = row;
    }
    return part;
}

}  // namespace

void write_settings(std::ostream& out, const RunSettings& s, const FirstPart& first_part) {
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
    write_first_part(out, first_part);
}

Checkpoint read_checkpoint(const std::string& path) {
    // "-": stdin, as for a scene.
    const std::string name = path == "-" ? "<stdin>" : path;
    if (apps_common::names_a_directory(path)) throw std::invalid_argument(name + ": is a directory");
    if (path == "-") return read_checkpoint(std::make_unique<std::istream>(std::cin.rdbuf()), name);
    auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
    if (!*file) throw std::invalid_argument(path + ": cannot open the checkpoint: " + std::strerror(errno));
    return read_checkpoint(std::move(file), path);
}

Checkpoint read_checkpoint(std::unique_ptr<std::istream> file, const std::string& path) {
    particlesim::SavedStateReader in(*file, path + ": not a checkpoint simcli can resume");
    in.expect(magic);
    const std::string version = in.word();
    if (version != format_version && version != "1") in.fail("an unknown format version");
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
    if (version == format_version) checkpoint.first_part = read_first_part(in);
    checkpoint.engine_state = std::move(file);
    return checkpoint;
}

}  // namespace simcli
