#pragma once
// The whole public API of particlesim in one include.

#include "particlesim/accuracy.hpp"
#include "particlesim/engine.hpp"
#include "particlesim/exact_simulation.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/scene.hpp"
#include "particlesim/scene_families.hpp"
#include "particlesim/state_writer.hpp"
#include "particlesim/step_check.hpp"
#include "particlesim/stepped_simulation.hpp"
#include "particlesim/version.hpp"
#include "particlesim/world.hpp"
