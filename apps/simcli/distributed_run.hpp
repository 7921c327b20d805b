#pragma once
// simcli under mpirun (or srun): with more than one rank, the scene runs on
// the distributed engine and writes the bytes one process writes. Rank 0
// reads the input and writes every file; every message is printed once, by
// the rank it concerns, and every rank exits with the same status.
// Built only with PARTICLESIM_MPI, into simcli-mpi (mpi_launch.hpp).

namespace simcli {

// Initialises MPI and runs simcli as one of its ranks; with one rank, runs
// `one_process` (simcli as without MPI). Returns the exit status.
int run_under_mpi(int argc, char** argv, int (*one_process)(int, char**));

}  // namespace simcli
