#pragma once
// The check of SteppedOptions that every engine taking them makes where they
// enter (SteppedSimulation, DistributedSimulation): the same refusals,
// whichever engine a program links.

#include "particlesim/stepped_simulation.hpp"

namespace particlesim {

// Throws std::invalid_argument naming "particlesim::SteppedOptions", the
// option and its value.
void require_valid_stepped_options(const SteppedOptions& options);

}  // namespace particlesim
