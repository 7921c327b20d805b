#pragma once
// Checks a whole output against a scene, block by block: the initial state
// against the scene, each printed step against one step of the rules from the
// step before (particlesim::StepChecker), the final counters against the
// collisions the steps show, and the output's shape (every line, once, in
// order). A perf-mode output, with nothing between its first and last block,
// is judged from the initial state as long as the rules stay decided.

#include "particlesim/output_reader.hpp"

#include "particlesim/scene.hpp"
#include "particlesim/step_check.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace simcheck {

enum class Verdict { conforms, breaks_rules, no_verdict };

// The lines of an output, one at a time: read from a file as they come
// (FileLines), or from an output whose shape was repaired (output_shape.hpp).
class LineSource {
public:
    virtual ~LineSource() = default;
    // The next line, or false at the end; throws particlesim::InputError.
    virtual bool next(particlesim::OutputLine& out) = 0;
    [[nodiscard]] virtual long lines_read() const = 0;
    // Within how much each printed number is known, once a line has been read.
    [[nodiscard]] virtual double uncertainty() const = 0;
};

class FileLines : public LineSource {
public:
    explicit FileLines(particlesim::OutputReader& reader) : reader_(reader) {}
    bool next(particlesim::OutputLine& out) override { return reader_.next(out); }
    [[nodiscard]] long lines_read() const override { return reader_.lines_read(); }
    [[nodiscard]] double uncertainty() const override {
        return reader_.format() == particlesim::NumberFormat::fixed8 ? particlesim::fixed8_uncertainty : 0.0;
    }

private:
    particlesim::OutputReader& reader_;
};

// What the check lets pass, for an output whose shape deviates in a known way.
struct ShapeAllowance {
    bool final_block_without_counters = false;  // the counters are then not judged
};

struct Finding {
    std::int64_t step = 0;
    long line = 0;  // of the output, 0 when none applies
    std::string what;
    std::optional<particlesim::Particle> expected;
    std::optional<particlesim::Particle> printed;
};

struct Report {
    Verdict verdict = Verdict::conforms;
    std::optional<Finding> finding;  // breaks_rules
    std::string reason;              // no_verdict
    std::size_t particles = 0;
    std::int64_t steps = 0;
    std::int64_t steps_checked = 0;  // one by one (print mode)
    std::int64_t steps_judged = 0;   // of those, the steps the rules could be applied to (StepCheck::judged)
    double uncertainty = 0.0;        // of each printed number
    double radius = 0.0;             // the scene's, to weigh the uncertainty against
    std::vector<std::pair<std::int64_t, std::string>> within_rounding;  // the first few
    std::size_t within_rounding_count = 0;
    std::vector<std::int64_t> steps_within_rounding;  // every step with such a decision, ascending
};

Report check_output(const particlesim::Scene& scene, LineSource& output, const particlesim::StepCheckOptions& options,
                    const ShapeAllowance& allowance = {});

}  // namespace simcheck
