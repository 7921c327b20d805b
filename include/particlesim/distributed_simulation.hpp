#pragma once
// The stepped engine spread over the ranks of an MPI communicator
// (particlesim::mpi, built with -DPARTICLESIM_MPI=ON): each rank owns the
// particles of a strip of the box and steps them with copies of its
// neighbours' border particles; the run is SteppedSimulation's, byte for
// byte, for any number of ranks (docs/distributed.md).
//
// Every member function is collective: all ranks of the communicator call
// it, in the same order.

#include "particlesim/engine.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/stepped_simulation.hpp"
#include "particlesim/world.hpp"

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <istream>
#include <memory>
#include <ostream>
#include <span>
#include <string_view>
#include <vector>

namespace particlesim {

// What one rank's exchanges have cost since the engine was made: the
// inputs of the scaling model in docs/distributed.md.
struct ExchangeCounts {
    std::uint64_t micro_steps = 0;
    std::uint64_t selection_rounds = 0;   // summed over the micro-steps
    std::uint64_t ghosts_received = 0;    // copies of neighbours' particles
    std::uint64_t migrants_received = 0;  // particles that changed strips
    std::uint64_t messages_sent = 0;      // point to point, sizes included
    std::uint64_t bytes_sent = 0;
    std::uint64_t collectives = 0;    // all-reductions, of a few numbers each
    double seconds_exchanging = 0.0;  // in those messages and collectives, waiting included
};

class DistributedSimulation {
public:
    // The scene's particles come on rank 0 (the others pass none) and are
    // handed out in parts; no rank keeps more than its own strip's. Throws
    // std::invalid_argument on every rank for what SteppedSimulation refuses.
    // The pair search, threads (per rank) and substeps are SteppedOptions';
    // the paths search, which keeps each particle's line between steps,
    // becomes the grid on more than one rank (the same candidates).
    DistributedSimulation(MPI_Comm comm, const World& world, std::vector<Particle> particles_on_root,
                          const SteppedOptions& options = {});
    ~DistributedSimulation();
    // Movable; a moved-from DistributedSimulation may only be assigned to or destroyed.
    DistributedSimulation(DistributedSimulation&&) noexcept;
    DistributedSimulation& operator=(DistributedSimulation&&) noexcept;

    // Continues a state saved by save() or by SteppedSimulation::save() (the
    // same text), read on rank 0 from `saved_on_root` (others pass nullptr).
    static DistributedSimulation restore(MPI_Comm comm, const World& world, std::istream* saved_on_root,
                                         const SteppedOptions& options = {});
    // SteppedSimulation::save()'s text, handed to rank 0's `write` in
    // pieces of bounded size (a piece per part of the particles).
    using TextSink = std::function<void(std::string_view text)>;
    void save(const TextSink& write) const;

    // One whole step.
    void step();

    // Rank 0's `part` receives every particle in the user's order, in
    // consecutive parts of at most `part_size`: the index of the part's
    // first particle, and its particles.
    using PartSink = std::function<void(std::size_t first_index, std::span<const Particle> particles)>;
    void gather(const PartSink& part, std::size_t part_size = std::size_t{1} << 16) const;

    // The same on every rank.
    [[nodiscard]] const World& world() const;
    [[nodiscard]] std::uint64_t particle_count() const;
    [[nodiscard]] std::int64_t steps_done() const;
    [[nodiscard]] const StepCounts& last_step() const;  // summed over the ranks
    [[nodiscard]] const StepCounts& totals() const;
    [[nodiscard]] PairSearch pair_search() const;
    [[nodiscard]] int threads() const;  // per rank

    // This rank's share.
    [[nodiscard]] int rank() const;
    [[nodiscard]] int ranks() const;
    [[nodiscard]] std::size_t owned_count() const;
    // The most particles (owned and ghosts) this rank has held in a step.
    [[nodiscard]] std::size_t peak_local_count() const;
    [[nodiscard]] const ExchangeCounts& exchange_counts() const;

private:
    class Implementation;
    explicit DistributedSimulation(std::unique_ptr<Implementation> engine);
    std::unique_ptr<Implementation> engine_;
};

}  // namespace particlesim
