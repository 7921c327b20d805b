#pragma once
// simcli under an MPI launcher (mpirun, srun). simcli links no MPI, so that
// a run outside a launcher never loads it: OpenMPI and its libraries cost
// about 4 ms of CPU to load at every start, some 6 % of the default scene's
// run. A build with the distributed engine puts simcli-mpi beside simcli: the
// same program, linked with MPI (distributed_run.*). simcli started by a
// launcher replaces itself with it, in the same process, so the launcher
// sees no difference. A build without MPI refuses to run on several ranks,
// each of which would run the whole scene.

namespace simcli {

// Whether an MPI launcher started this process (its environment says so).
bool started_by_mpi_launcher();

// The ranks the launcher started, as its environment names them (Open MPI,
// MPICH, Slurm's PMI); 0 when it names none.
long launched_ranks();

// Whether this process is the launcher's first rank (or names no rank).
bool first_launched_rank();

// Replaces this process by the program `name` in simcli's own directory,
// with the same arguments and environment. Returns only if it is not there
// or cannot be started, having printed why.
void become_sibling(const char* name, char** argv);

}  // namespace simcli
