#include "mpi_launch.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

namespace simcli {

bool started_by_mpi_launcher() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"}) {
        if (std::getenv(variable) != nullptr) return true;
    }
    return false;
}

namespace {

// This program's own file: Linux names it; elsewhere argv[0], when it is a path.
std::filesystem::path own_file(const char* argv0) {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) return self;
    return argv0 != nullptr ? std::filesystem::path(argv0) : std::filesystem::path();
}

}  // namespace

void become_sibling(const char* name, char** argv) {
    const std::filesystem::path sibling = own_file(argv[0]).parent_path() / name;
    execv(sibling.c_str(), argv);  // returns only on failure
    std::fprintf(stderr, "simcli: started by an MPI launcher, but cannot start %s: %s\n", sibling.c_str(),
                 std::strerror(errno));
}

}  // namespace simcli
