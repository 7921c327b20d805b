#pragma once
// The engines' public API in one include. The grader (the particlesim::check
// library) has its own header, particlesim/step_check.hpp.

#include "particlesim/accuracy.hpp"
#include "particlesim/engine.hpp"
#include "particlesim/exact_simulation.hpp"
#include "particlesim/observables.hpp"
#include "particlesim/output_reader.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/saved_state.hpp"
#include "particlesim/scene.hpp"
#include "particlesim/scene_families.hpp"
#include "particlesim/state_writer.hpp"
#include "particlesim/stepped_simulation.hpp"
#include "particlesim/version.hpp"
#include "particlesim/world.hpp"
