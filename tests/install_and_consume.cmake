# Installs particlesim into a scratch prefix, checks that exactly the public
# headers are installed, then configures, builds and runs a consumer project
# (tests/consumer/CMakeLists.txt with examples/library_usage.cpp as its
# main.cpp) that finds the package with find_package(particlesim).
# With the distributed engine built (MPI_BUILT), a second consumer
# (tests/consumer_mpi) finds its component and runs under mpirun, and so
# does the installed simcli (through simcli-mpi beside it).
# Inputs: BUILD_DIR, WORK_DIR, GENERATOR (the main build's), CONSUMER_DIR, LIBRARY_USAGE_SOURCE, APPS_BUILT, MPI_BUILT,
# MPIEXEC.
file(REMOVE_RECURSE "${WORK_DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/run_step.cmake")
set(prefix "${WORK_DIR}/prefix")
run_step(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")

# The public API, and nothing else.
set(public_headers accuracy.hpp engine.hpp exact_simulation.hpp observables.hpp output_reader.hpp particle.hpp particlesim.hpp
                   random_scene.hpp saved_state.hpp scene.hpp scene_families.hpp state_writer.hpp step_check.hpp
                   stepped_simulation.hpp version.hpp world.hpp)
if(MPI_BUILT)
  list(APPEND public_headers distributed_simulation.hpp)
  list(SORT public_headers)
endif()
file(GLOB installed RELATIVE "${prefix}/include/particlesim" "${prefix}/include/particlesim/*")
list(SORT installed)
if(NOT installed STREQUAL public_headers)
  message(FATAL_ERROR "installed headers:\n  ${installed}\nexpected:\n  ${public_headers}")
endif()
set(required lib/libparticlesim.a lib/libparticlesim_check.a lib/cmake/particlesim/particlesimConfig.cmake)
if(APPS_BUILT)
  list(APPEND required bin/simcli bin/simgen bin/simcheck)
endif()
if(MPI_BUILT)
  list(APPEND required lib/libparticlesim_mpi.a)
  if(APPS_BUILT)
    list(APPEND required bin/simcli-mpi)  # what the installed simcli runs under a launcher
  endif()
endif()
foreach(file IN LISTS required)
  if(NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()

file(COPY "${CONSUMER_DIR}/CMakeLists.txt" DESTINATION "${WORK_DIR}/consumer")
configure_file("${LIBRARY_USAGE_SOURCE}" "${WORK_DIR}/consumer/main.cpp" COPYONLY)
run_step(${CMAKE_COMMAND} -G "${GENERATOR}" -S "${WORK_DIR}/consumer" -B "${WORK_DIR}/build" -DCMAKE_BUILD_TYPE=Release
         "-DCMAKE_PREFIX_PATH=${prefix}")
run_step(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run_step("${WORK_DIR}/build/consumer")
if(NOT last_output MATCHES "wall and [0-9]+ particle collisions in 100 steps\nexact engine: [0-9]+ particle collisions\n100 0 [0-9.]+ ")
  message(FATAL_ERROR "unexpected consumer output:\n${last_output}")
endif()
message(STATUS "consumer ran:\n${last_output}")

# Found twice, the second time with the grader's component: the config
# defines its targets once and knows the component.
file(WRITE "${WORK_DIR}/twice/CMakeLists.txt" [=[
cmake_minimum_required(VERSION 3.25)
project(particlesim_found_twice LANGUAGES CXX)
find_package(particlesim 0.1 REQUIRED)
find_package(particlesim 0.1 REQUIRED COMPONENTS check)
if(NOT TARGET particlesim::check)
  message(FATAL_ERROR "particlesim::check is missing")
endif()
]=])
run_step(${CMAKE_COMMAND} -G "${GENERATOR}" -S "${WORK_DIR}/twice" -B "${WORK_DIR}/twice-build" "-DCMAKE_PREFIX_PATH=${prefix}")
message(STATUS "found twice, with the check component")

if(MPI_BUILT)
  file(COPY "${CONSUMER_DIR}_mpi/CMakeLists.txt" "${CONSUMER_DIR}_mpi/main.cpp" DESTINATION "${WORK_DIR}/consumer_mpi")
  run_step(${CMAKE_COMMAND} -G "${GENERATOR}" -S "${WORK_DIR}/consumer_mpi" -B "${WORK_DIR}/build_mpi" -DCMAKE_BUILD_TYPE=Release
           "-DCMAKE_PREFIX_PATH=${prefix}")
  run_step(${CMAKE_COMMAND} --build "${WORK_DIR}/build_mpi")
  run_step(${MPIEXEC} -np 2 "${WORK_DIR}/build_mpi/consumer_mpi")
  if(NOT last_output MATCHES "2 ranks: [0-9]+ particle collisions in 20 steps")
    message(FATAL_ERROR "unexpected output of the MPI consumer:\n${last_output}")
  endif()
  message(STATUS "MPI consumer ran:\n${last_output}")

  if(APPS_BUILT)
    # The installed simcli under the launcher finds its sibling: the same bytes as one process.
    file(WRITE "${WORK_DIR}/scene.in" "300\n2000\n1\n20\nprint\n")
    run_step("${prefix}/bin/simcli" "${WORK_DIR}/scene.in")
    set(one_process "${last_output}")
    run_step(${MPIEXEC} -np 2 "${prefix}/bin/simcli" "${WORK_DIR}/scene.in")
    if(NOT last_output STREQUAL one_process OR one_process STREQUAL "")
      message(FATAL_ERROR "the installed simcli under ${MPIEXEC} -np 2 wrote other bytes than in one process")
    endif()
    message(STATUS "the installed simcli ran under ${MPIEXEC}, the same bytes as in one process")
  endif()
endif()
