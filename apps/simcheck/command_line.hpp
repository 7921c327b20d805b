#pragma once
// What both of simcheck's forms read from their command lines: the options
// that say which rules the output was made with, and the error for bad usage
// (exit 2).

#include "particlesim/step_check.hpp"

#include <charconv>
#include <stdexcept>
#include <string>

namespace simcheck {

class BadUsage : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The value of the option at argv[k], moving k onto it; BadUsage when there is none.
inline std::string option_value(int argc, char** argv, int& k) {
    if (k + 1 >= argc) throw BadUsage(std::string(argv[k]) + " needs a value");
    return argv[++k];
}

// Reads `--substeps K`, `--engine step|exact` or `--boundary walls|periodic`
// into `options` (value() takes the option's value); false for any other
// argument.
template <typename TakeValue>
bool read_rules_option(const std::string& arg, TakeValue&& value, particlesim::StepCheckOptions& options) {
    if (arg == "--substeps") {
        const std::string text = value();
        int substeps = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), substeps);
        if (error != std::errc() || end != text.data() + text.size() || substeps < 1 || substeps > 1000000) {
            throw BadUsage("--substeps needs a whole number from 1 to 1000000, not \"" + text + "\"");
        }
        options.substeps = substeps;
        return true;
    }
    if (arg == "--engine") {
        const std::string text = value();
        if (text == "exact") {
            options.rules = particlesim::CheckedRules::exact;
        } else if (text != "step") {
            throw BadUsage("--engine is step or exact, not \"" + text + "\"");
        }
        return true;
    }
    if (arg == "--boundary") {
        const std::string text = value();
        const std::optional<particlesim::Boundary> boundary = particlesim::boundary_named(text);
        if (!boundary) throw BadUsage("--boundary is walls or periodic, not \"" + text + "\"");
        options.boundary = *boundary;
        return true;
    }
    return false;
}

// The rules options that contradict each other.
inline void require_consistent_rules(const particlesim::StepCheckOptions& options, bool substeps_given) {
    if (substeps_given && options.rules == particlesim::CheckedRules::exact) {
        throw BadUsage("--substeps belongs to the step rules; the exact engine has none");
    }
    if (options.boundary == particlesim::Boundary::periodic && options.rules != particlesim::CheckedRules::exact) {
        throw BadUsage("--boundary periodic needs --engine exact: the step rules are those of a walled box");
    }
}

}  // namespace simcheck
