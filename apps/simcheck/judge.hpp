#pragma once
// One output judged as a whole: read strictly as io.md writes it; where
// that fails or the shape deviates, read again with the deviations named
// (output_shape.hpp) and the physics judged all the same.

#include "output_check.hpp"

#include "particlesim/scene.hpp"
#include "particlesim/step_check.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace simcheck {

enum class Outcome {
    conforms,    // physics and shape
    shape,       // the physics conforms; the shape deviates (deviations)
    wrong,       // breaks the rules (report.finding)
    no_verdict,  // report.reason
    malformed,   // cannot be read (message)
};

struct Judgement {
    Outcome outcome = Outcome::conforms;
    Report report;
    std::vector<std::string> deviations;
    std::string message;  // malformed: "NAME:LINE: what"
};

// Outputs up to this size are also read for their shape; a larger one only
// strictly (and its deviations are not named).
inline constexpr std::int64_t largest_shaped_output = std::int64_t{64} << 20;

// `output`: an open file at its start. One that cannot be read again (not
// seekable: a long output on stdin) is read once, strictly.
Judgement judge_output(const particlesim::Scene& scene, std::FILE* output, const std::string& output_name,
                       const particlesim::StepCheckOptions& options);

}  // namespace simcheck
