#pragma once
// Reading an output whose shape deviates from io.md's in ways that leave its
// physics readable: trailing spaces or blank lines, numbers not in %.8f, no
// step-0 block, a block printed twice, counters missing from the final block
// or printed on every block, every step printed in a perf-mode run. Each
// deviation is named; the lines are put back into io.md's shape, so that the
// rules can still judge the physics (the verdict is then "shape", exit 4).
// An output that cannot be read one way only is left to the strict reader.

#include "output_check.hpp"

#include "particlesim/output_reader.hpp"
#include "particlesim/scene.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace simcheck {

struct ShapedOutput {
    std::vector<particlesim::OutputLine> lines;  // in io.md's shape; line numbers are the output's (0: made up)
    std::vector<std::string> deviations;         // in words, in the order found
    double uncertainty = 0.0;                    // of each printed number
    ShapeAllowance allowance;
    std::string unreadable;  // not empty: the output cannot be read one way only (why)
};

ShapedOutput read_shape(std::string_view text, const particlesim::Scene& scene);

// The shaped lines, one at a time, for check_output.
class ShapedLines : public LineSource {
public:
    explicit ShapedLines(const ShapedOutput& shaped) : shaped_(shaped) {}
    bool next(particlesim::OutputLine& out) override;
    [[nodiscard]] long lines_read() const override;
    [[nodiscard]] double uncertainty() const override { return shaped_.uncertainty; }

private:
    const ShapedOutput& shaped_;
    std::size_t next_ = 0;
};

}  // namespace simcheck
