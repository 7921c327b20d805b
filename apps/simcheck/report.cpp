#include "report.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace simcheck {

namespace {

using particlesim::Particle;

// Printed as the output prints numbers, with one more digit where it helps.
std::string number(double value) {
    char text[64];
    std::snprintf(text, sizeof text, std::fabs(value) < 1e15 ? "%.9f" : "%.17g", value);
    return text;
}

std::string state_text(const Particle& p) {
    return "x " + number(p.position.x()) + "  y " + number(p.position.y()) + "  vx " + number(p.velocity.x()) +
           "  vy " + number(p.velocity.y());
}

// A printed number's rounding from this fraction of a radius on makes a
// contact's decision a matter of rounding: the report says so.
constexpr double coarse_rounding_in_radii = 0.01;

// The printed numbers' rounding against the scene's radius (0 when exact).
double uncertainty_in_radii(const Report& report) {
    return report.radius > 0.0 ? report.uncertainty / report.radius : 0.0;
}

// How the printed numbers are taken: within half their last digit, or, in
// the shortest form that reads back (--exact-numbers), as the doubles
// themselves, whose last bits still round in any program's arithmetic.
std::string how_numbers_are_read(double uncertainty) {
    if (uncertainty > 0.0) {
        char text[64];
        std::snprintf(text, sizeof text, "known within %g", uncertainty);
        return text;
    }
    return "the exact doubles";
}

}  // namespace

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned char>(c));
            out += escaped;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

namespace {

std::string json_number(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string json_state(const Particle& p) {
    std::string out = "[";
    for (const double value : {p.position.x(), p.position.y(), p.velocity.x(), p.velocity.y()}) {
        if (out.size() > 1) out += ", ";
        out += json_number(value);
    }
    return out + "]";
}

const char* verdict_name(const Judgement& judgement) {
    if (judgement.outcome == Outcome::shape) return "shape";
    switch (judgement.report.verdict) {
    case Verdict::conforms: return "conforms";
    case Verdict::breaks_rules: return "breaks_rules";
    case Verdict::no_verdict: return "no_verdict";
    }
    return "";
}

void write_deviations(std::FILE* out, const std::vector<std::string>& deviations) {
    for (const std::string& deviation : deviations) std::fprintf(out, "  - %s\n", deviation.c_str());
}

}  // namespace

void write_text_report(std::FILE* out, const Judgement& judgement, const ReportContext& context) {
    const Report& report = judgement.report;
    if (report.verdict == Verdict::breaks_rules) {
        const Finding& f = *report.finding;
        std::fprintf(out, "step %lld: %s\n", static_cast<long long>(f.step), f.what.c_str());
        if (f.line > 0) std::fprintf(out, "  at line %ld of %s\n", f.line, context.output_name.c_str());
        if (f.expected) std::fprintf(out, "  expected  %s\n", state_text(*f.expected).c_str());
        if (f.printed) std::fprintf(out, "  printed   %s\n", state_text(*f.printed).c_str());
        if (f.expected && f.printed) {
            std::fprintf(out,
                         "  (printed numbers are read as %s; \"expected\" is the middle of what the rules allow)\n",
                         how_numbers_are_read(report.uncertainty).c_str());
        }
        if (!judgement.deviations.empty()) {
            std::fprintf(out, "  (read despite deviations from io.md's shape:)\n");
            write_deviations(out, judgement.deviations);
        }
        return;
    }
    if (report.verdict == Verdict::no_verdict) {
        std::fprintf(out, "no verdict: %s\n", report.reason.c_str());
        write_deviations(out, judgement.deviations);
        return;
    }
    if (judgement.outcome == Outcome::shape) {
        std::fprintf(out, "shape: the physics conforms, but the output's shape deviates from io.md's:\n");
        write_deviations(out, judgement.deviations);
    }
    std::fprintf(out, judgement.outcome == Outcome::shape ? "physics:" : "conforms:");
    std::fprintf(out, " %zu particles, %lld steps, checked against %s", report.particles,
                 static_cast<long long>(report.steps), context.rules.c_str());
    std::fprintf(out, report.steps_checked > 0 ? " step by step" : " from the initial state");
    if (report.steps_checked > 0 && report.steps_judged < report.steps_checked) {
        std::fprintf(out, " (%lld of the %lld steps judged; below, why not the others)",
                     static_cast<long long>(report.steps_judged), static_cast<long long>(report.steps_checked));
    }
    std::fprintf(out, "; printed numbers read as %s\n", how_numbers_are_read(report.uncertainty).c_str());
    // Eight decimals of a box of 1e-50 print every number as 0, which any
    // run "conforms" to: say so where the rounding reaches a hundredth of a
    // radius, and how to print a sharper output.
    if (uncertainty_in_radii(report) >= coarse_rounding_in_radii) {
        std::fprintf(out,
                     "note: the printed numbers are known within %g, %.3g times the radius %g: this check "
                     "cannot tell apart paths closer than that; print every digit (simcli --exact-numbers) for "
                     "a sharper one\n",
                     report.uncertainty, uncertainty_in_radii(report), report.radius);
    }
    if (report.within_rounding_count > 0) {
        std::fprintf(out, "%zu decision(s) of the rules were within %s; either outcome was accepted:\n",
                     report.within_rounding_count,
                     report.uncertainty > 0.0 ? "that rounding" : "the rounding of the doubles' last bits");
        for (const auto& [step, what] : report.within_rounding) {
            std::fprintf(out, "  step %lld: %s\n", static_cast<long long>(step), what.c_str());
        }
        if (report.within_rounding_count > report.within_rounding.size()) std::fprintf(out, "  ...\n");
    }
}

void write_json_report(std::FILE* out, const Judgement& judgement, const ReportContext& context) {
    const Report& report = judgement.report;
    std::string json = "{\"verdict\": \"" + std::string(verdict_name(judgement)) + "\"";
    json += ", \"rules\": " + json_string(context.rules);
    json += ", \"particles\": " + std::to_string(report.particles);
    json += ", \"steps\": " + std::to_string(report.steps);
    json += ", \"steps_checked\": " + std::to_string(report.steps_checked);
    json += ", \"steps_judged\": " + std::to_string(report.steps_judged);
    json += ", \"uncertainty\": " + json_number(report.uncertainty);
    json += ", \"uncertainty_in_radii\": " + json_number(uncertainty_in_radii(report));
    if (report.finding) {
        const Finding& f = *report.finding;
        json += ", \"step\": " + std::to_string(f.step) + ", \"line\": " + std::to_string(f.line);
        json += ", \"message\": " + json_string("step " + std::to_string(f.step) + ": " + f.what);
        if (f.expected) json += ", \"expected\": " + json_state(*f.expected);
        if (f.printed) json += ", \"printed\": " + json_state(*f.printed);
    }
    if (report.verdict == Verdict::no_verdict) json += ", \"reason\": " + json_string(report.reason);
    json += ", \"within_rounding_count\": " + std::to_string(report.within_rounding_count);
    json += ", \"within_rounding\": [";
    for (std::size_t k = 0; k < report.within_rounding.size(); ++k) {
        if (k > 0) json += ", ";
        json += "{\"step\": " + std::to_string(report.within_rounding[k].first) +
                ", \"what\": " + json_string(report.within_rounding[k].second) + "}";
    }
    json += "], \"deviations\": [";
    for (std::size_t k = 0; k < judgement.deviations.size(); ++k) {
        json += (k > 0 ? ", " : "") + json_string(judgement.deviations[k]);
    }
    json += "], \"steps_within_rounding\": [";
    for (std::size_t k = 0; k < report.steps_within_rounding.size(); ++k) {
        json += (k > 0 ? ", " : "") + std::to_string(report.steps_within_rounding[k]);
    }
    json += "]}\n";
    std::fputs(json.c_str(), out);
}

void write_json_unreadable(std::FILE* out, const std::string& message) {
    std::fprintf(out, "{\"verdict\": \"unreadable\", \"message\": %s}\n", json_string(message).c_str());
}

}  // namespace simcheck
