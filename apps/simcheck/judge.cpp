#include "judge.hpp"

#include "common/library_message.hpp"

#include "output_shape.hpp"

#include "particlesim/output_reader.hpp"

#include <stdexcept>
#include <utility>

namespace simcheck {

namespace {

Outcome outcome_of(const Report& report, bool deviations) {
    switch (report.verdict) {
    case Verdict::conforms: return deviations ? Outcome::shape : Outcome::conforms;
    case Verdict::breaks_rules: return Outcome::wrong;
    case Verdict::no_verdict: return Outcome::no_verdict;
    }
    return Outcome::no_verdict;
}

// check_output, with the rules' own refusals (the exact engine refuses the
// printed state, a step needs millions of events, ...) as no verdict.
Report checked(const particlesim::Scene& scene, LineSource& lines, const particlesim::StepCheckOptions& options,
               const ShapeAllowance& allowance) {
    try {
        return check_output(scene, lines, options, allowance);
    } catch (const particlesim::InputError&) {
        throw;
    } catch (const std::exception& e) {
        Report report;
        report.verdict = Verdict::no_verdict;
        report.reason = apps_common::without_library_names(e.what());
        return report;
    }
}

bool read_all(std::FILE* file, std::string& text) {
    if (std::fseek(file, 0, SEEK_END) != 0) return false;
    const long size = std::ftell(file);
    if (size < 0 || size > largest_shaped_output || std::fseek(file, 0, SEEK_SET) != 0) return false;
    text.resize(static_cast<std::size_t>(size));
    const bool whole = std::fread(text.data(), 1, text.size(), file) == text.size();
    std::rewind(file);
    return whole;
}

}  // namespace

Judgement judge_output(const particlesim::Scene& scene, std::FILE* output, const std::string& output_name,
                       const particlesim::StepCheckOptions& options) {
    Judgement judgement;
    std::string text;
    if (read_all(output, text)) {
        const ShapedOutput shaped = read_shape(std::move(text), scene);
        if (shaped.unreadable.empty() && !shaped.deviations.empty()) {
            ShapedLines lines(shaped);
            try {
                judgement.report = checked(scene, lines, options, shaped.allowance);
                judgement.outcome = outcome_of(judgement.report, true);
                judgement.deviations = shaped.deviations;
                return judgement;
            } catch (const particlesim::InputError&) {
                // Not readable after all: the strict reader names why.
            }
        }
    }
    std::rewind(output);
    particlesim::OutputReader reader(output, output_name);
    FileLines lines(reader);
    try {
        judgement.report = checked(scene, lines, options, {});
        judgement.outcome = outcome_of(judgement.report, false);
    } catch (const particlesim::InputError& e) {
        judgement.outcome = Outcome::malformed;
        judgement.message = output_name + ":" + std::to_string(e.line()) + ": " + e.what();
    }
    return judgement;
}

}  // namespace simcheck
