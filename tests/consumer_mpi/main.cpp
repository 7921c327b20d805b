// The distributed engine from an installed package: a random scene on every
// rank of MPI_COMM_WORLD, its collisions printed by rank 0.
#include <particlesim/distributed_simulation.hpp>
#include <particlesim/random_scene.hpp>

#include <mpi.h>

#include <cstdio>

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    {
        const particlesim::World world{200.0, 1.0};
        std::vector<particlesim::Particle> particles;
        if (rank == 0) particles = particlesim::make_random_particles(2000, world, {});
        particlesim::DistributedSimulation simulation(MPI_COMM_WORLD, world, std::move(particles));
        for (int step = 0; step < 20; ++step) simulation.step();
        if (rank == 0) {
            std::printf("%d ranks: %llu particle collisions in 20 steps\n", simulation.ranks(),
                        static_cast<unsigned long long>(simulation.totals().particle_collisions));
        }
    }
    MPI_Finalize();
}
