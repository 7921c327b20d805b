#include "mpi_launch.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <initializer_list>
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

// The first of the variables that is set, as a whole number; -1 when none is
// (or it is no number).
long first_number(std::initializer_list<const char*> variables) {
    for (const char* variable : variables) {
        const char* value = std::getenv(variable);
        if (value == nullptr) continue;
        char* end = nullptr;
        const long number = std::strtol(value, &end, 10);
        return end != value && *end == '\0' && number >= 0 ? number : -1;
    }
    return -1;
}

// This program's own file: Linux names it; elsewhere argv[0], when it is a path.
std::filesystem::path own_file(const char* argv0) {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) return self;
    return argv0 != nullptr ? std::filesystem::path(argv0) : std::filesystem::path();
}

}  // namespace

long launched_ranks() { return std::max(first_number({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}), 0L); }

bool first_launched_rank() { return first_number({"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) <= 0; }

void become_sibling(const char* name, char** argv) {
    const std::filesystem::path sibling = own_file(argv[0]).parent_path() / name;
    execv(sibling.c_str(), argv);  // returns only on failure
    std::fprintf(stderr, "simcli: started by an MPI launcher, but cannot start %s: %s\n", sibling.c_str(),
                 std::strerror(errno));
}

}  // namespace simcli
