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

// A block of the output: lines of one step, its particles in order or not,
// as bytes [begin, end) of the text.
struct ShapedBlock {
    std::size_t begin = 0;
    std::size_t end = 0;
    long first_line = 0;  // the output's line numbers of its first and last line
    long last_line = 0;
    std::int64_t step = 0;
    std::size_t lines = 0;
    bool in_order = true;  // line k of the block is particle k
    bool all_counters = true;
    bool no_counters = true;
};

// The output, kept as text, and what is read of it in io.md's shape: the
// blocks kept, in order, each read again from the text as it is checked
// (a parsed line takes several times its text's bytes).
struct ShapedOutput {
    std::string text;
    const particlesim::Scene* scene = nullptr;
    bool scene_for_step_zero = false;     // no step-0 block: the scene's particles stand in for it
    std::vector<ShapedBlock> blocks;      // kept, in io.md's order
    bool counters_on_final_only = false;  // counters printed on every block: those before the final one set aside
    std::vector<std::string> deviations;  // in words, in the order found
    double uncertainty = 0.0;             // of each printed number
    ShapeAllowance allowance;
    std::string unreadable;  // not empty: the output cannot be read one way only (why)
};

ShapedOutput read_shape(std::string text, const particlesim::Scene& scene);

// The shaped lines, one at a time, for check_output.
class ShapedLines : public LineSource {
public:
    explicit ShapedLines(const ShapedOutput& shaped) : shaped_(shaped) {}
    bool next(particlesim::OutputLine& out) override;
    [[nodiscard]] long lines_read() const override { return last_line_; }
    [[nodiscard]] double uncertainty() const override { return shaped_.uncertainty; }

private:
    const ShapedOutput& shaped_;
    std::size_t scene_particle_ = 0;  // the next of the scene's particles standing in for step 0
    std::size_t block_ = 0;           // the block being read, and where in the text
    std::size_t at_ = 0;
    long line_ = 0;  // the output's line number of the line before at_
    long last_line_ = 0;
    bool started_ = false;
    std::vector<std::string_view> tokens_;
};

}  // namespace simcheck
