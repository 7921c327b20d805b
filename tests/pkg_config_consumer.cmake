# The pkg-config files: installs particlesim into a scratch prefix, moves the
# installed tree elsewhere (the files find their prefix from their own
# place), then compiles with nothing but the compiler and `pkg-config
# --cflags --libs`: examples/library_usage.cpp (its output must equal the
# library_usage test's, byte for byte), a program using the step checker
# (particlesim-check) and, with the distributed engine built, the MPI
# consumer with mpicxx, run under mpiexec (particlesim-mpi).
# Says SKIPPED (the test is then skipped) without pkg-config.
# Inputs: BUILD_DIR, WORK_DIR, CXX, VERSION, LIBRARY_USAGE_SOURCE, LIBRARY_USAGE (the built example),
#         MPI_BUILT, MPI_CONSUMER_SOURCE, MPICXX, MPIEXEC.
find_program(PKG_CONFIG NAMES pkg-config pkgconf)
if(NOT PKG_CONFIG)
  message("SKIPPED: pkg-config is missing; install pkgconf (scripts/ensure-deps.sh pkgconf)")
  return()
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/run_step.cmake")
run_step(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
file(RENAME "${WORK_DIR}/prefix" "${WORK_DIR}/moved")
file(GLOB pc_files "${WORK_DIR}/moved/*/pkgconfig/particlesim.pc" "${WORK_DIR}/moved/*/*/pkgconfig/particlesim.pc")
list(LENGTH pc_files found)
if(NOT found EQUAL 1)
  message(FATAL_ERROR "particlesim.pc installed ${found} times: ${pc_files}")
endif()
get_filename_component(pc_path "${pc_files}" DIRECTORY)
set(pkg_config ${CMAKE_COMMAND} -E env "PKG_CONFIG_PATH=${pc_path}" ${PKG_CONFIG})

run_step(${pkg_config} --modversion particlesim)
string(STRIP "${last_output}" version)
if(NOT version STREQUAL VERSION)
  message(FATAL_ERROR "pkg-config says version ${version}, the project is ${VERSION}")
endif()

# flags_of(VARIABLE PACKAGE): the compile and link flags, as a list.
function(flags_of variable package)
  run_step(${pkg_config} --cflags --libs ${package})
  if(NOT last_output MATCHES "${WORK_DIR}/moved")
    message(FATAL_ERROR "${package}'s flags do not name the moved prefix: ${last_output}")
  endif()
  separate_arguments(flags UNIX_COMMAND "${last_output}")
  set(${variable} ${flags} PARENT_SCOPE)
endfunction()

flags_of(flags particlesim)
run_step(${CXX} -std=c++20 -O1 "${LIBRARY_USAGE_SOURCE}" -o "${WORK_DIR}/consumer" ${flags})
run_step("${WORK_DIR}/consumer")
set(consumer_output "${last_output}")
run_step("${LIBRARY_USAGE}")
if(NOT consumer_output STREQUAL last_output)
  message(FATAL_ERROR "built with pkg-config's flags it printed\n${consumer_output}\nthe library_usage test prints\n${last_output}")
endif()
message(STATUS "built with pkg-config's flags alone, from a moved prefix:\n${consumer_output}")

file(WRITE "${WORK_DIR}/checker.cpp" [=[
#include <particlesim/step_check.hpp>

#include <cstdio>
#include <vector>

int main() {
    using namespace particlesim;
    StepChecker checker(World{100.0, 1.0});
    const std::vector<Particle> at_rest{{Vec2(50.0, 50.0), Vec2(0.0, 0.0)}};
    const PrintedState state{.particles = at_rest};
    std::printf("a disk at rest stays: %s\n", checker.check(state, state).violation ? "no" : "yes");
}
]=])
flags_of(flags particlesim-check)
run_step(${CXX} -std=c++20 -O1 "${WORK_DIR}/checker.cpp" -o "${WORK_DIR}/checker" ${flags})
run_step("${WORK_DIR}/checker")
if(NOT last_output STREQUAL "a disk at rest stays: yes\n")
  message(FATAL_ERROR "the checker program printed: ${last_output}")
endif()
message(STATUS "particlesim-check: ${last_output}")

if(MPI_BUILT)
  flags_of(flags particlesim-mpi)
  run_step(${MPICXX} -std=c++20 -O1 "${MPI_CONSUMER_SOURCE}" -o "${WORK_DIR}/consumer_mpi" ${flags})
  run_step(${MPIEXEC} -np 2 "${WORK_DIR}/consumer_mpi")
  if(NOT last_output MATCHES "2 ranks: [0-9]+ particle collisions in 20 steps")
    message(FATAL_ERROR "unexpected output of the MPI consumer:\n${last_output}")
  endif()
  message(STATUS "particlesim-mpi with mpicxx under ${MPIEXEC}:\n${last_output}")
endif()
