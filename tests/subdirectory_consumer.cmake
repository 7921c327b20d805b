# Builds tests/subdirectory_consumer (particlesim added with add_subdirectory,
# at -O0 and as a unity build of one file per target for speed: the one build of the suite that makes
# the library alone; a consumer may build it either way),
# runs it, then installs it and checks that only the consumer's own file was
# installed: no particlesim header, library or package file (PARTICLESIM_INSTALL
# defaults to off below the top level).
# Inputs: SOURCE_DIR, WORK_DIR, GENERATOR (the main build's), LIBRARY_USAGE_SOURCE.
file(REMOVE_RECURSE "${WORK_DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/run_step.cmake")
file(COPY "${SOURCE_DIR}/tests/subdirectory_consumer/CMakeLists.txt" DESTINATION "${WORK_DIR}/consumer")
configure_file("${LIBRARY_USAGE_SOURCE}" "${WORK_DIR}/consumer/main.cpp" COPYONLY)
run_step(${CMAKE_COMMAND} -G "${GENERATOR}" -S "${WORK_DIR}/consumer" -B "${WORK_DIR}/build" -DCMAKE_BUILD_TYPE=Debug
         -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=0
         "-DPARTICLESIM_SOURCE_DIR=${SOURCE_DIR}")
file(READ "${WORK_DIR}/build/CMakeCache.txt" cache)
if(cache MATCHES "PARTICLESIM_BUILD_(APPS|TESTS|BENCH)")
  message(FATAL_ERROR "a subproject's cache holds particlesim's top-level options")
endif()
# The consumer alone, and what it links: the other libraries of particlesim
# (the step checker) are not needed for it.
run_step(${CMAKE_COMMAND} --build "${WORK_DIR}/build" --target consumer -j 2)
run_step("${WORK_DIR}/build/consumer")
if(NOT last_output MATCHES "wall and [0-9]+ particle collisions in 100 steps\nexact engine: [0-9]+ particle collisions\n100 0 [0-9.]+ ")
  message(FATAL_ERROR "unexpected consumer output:\n${last_output}")
endif()
set(prefix "${WORK_DIR}/prefix")
run_step(${CMAKE_COMMAND} --install "${WORK_DIR}/build" --prefix "${prefix}")
file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
if(NOT installed STREQUAL "bin/consumer")
  message(FATAL_ERROR "installing the consumer installed:\n  ${installed}\nexpected only bin/consumer")
endif()
message(STATUS "consumer ran and installed only itself:\n${last_output}")
