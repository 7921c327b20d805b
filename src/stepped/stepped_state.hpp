#pragma once
// The text of a stepped run's saved state, written and read in one place:
// the one-process engine and the distributed engine save the same text, so
// that a checkpoint of either continues on either.

#include "particlesim/engine.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/saved_state.hpp"

#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace particlesim {

struct SteppedState {
    std::int64_t steps_done = 0;
    StepCounts totals;
    std::vector<Particle> particles;  // in the user's order
};

// The head; the particles follow, one write_stepped_state_particle() each.
inline void write_stepped_state_head(std::ostream& out, std::uint64_t count, std::int64_t steps_done,
                                     const StepCounts& totals) {
    out << "stepped-engine-state 1\n";
    save_number(out, count);
    save_number(out, static_cast<std::uint64_t>(steps_done));
    save_counts(out, totals);
    out << '\n';
}

inline void write_stepped_state_particle(std::ostream& out, const Particle& p) {
    save_particle(out, p);
    out << '\n';
}

// Throws std::invalid_argument with `refusal` for a damaged text. The
// particles grow with the input, whatever its head says.
inline SteppedState read_stepped_state(std::istream& saved, std::string refusal) {
    SavedStateReader in(saved, std::move(refusal));
    in.expect("stepped-engine-state");
    in.expect("1");
    const std::uint64_t count = in.count(0xfffffffeU);
    SteppedState state;
    state.steps_done = static_cast<std::int64_t>(in.count(INT64_MAX));
    state.totals = read_counts(in);
    for (std::uint64_t i = 0; i < count; ++i) state.particles.push_back(read_particle(in));
    return state;
}

}  // namespace particlesim
