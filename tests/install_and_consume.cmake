# Installs particlesim into a scratch prefix, then configures, builds and runs
# a consumer project that uses find_package(particlesim).
# Inputs: BUILD_DIR, WORK_DIR, CONSUMER_DIR, LIBRARY_USAGE_SOURCE.
file(REMOVE_RECURSE "${WORK_DIR}")
function(run_step)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGV}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
run_step(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
foreach(required include/particlesim/simulation.hpp include/particlesim/version.hpp lib/libparticlesim.a
                 lib/cmake/particlesim/particlesimConfig.cmake bin/simcli)
  if(NOT EXISTS "${WORK_DIR}/prefix/${required}")
    message(FATAL_ERROR "not installed: ${required}")
  endif()
endforeach()
run_step(${CMAKE_COMMAND} -S "${CONSUMER_DIR}" -B "${WORK_DIR}/build" -DCMAKE_BUILD_TYPE=Release
         "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-DLIBRARY_USAGE_SOURCE=${LIBRARY_USAGE_SOURCE}")
run_step(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run_step("${WORK_DIR}/build/consumer")
if(NOT last_output MATCHES "wall and [0-9]+ particle collisions in 100 steps\n100 0 [0-9.]+ ")
  message(FATAL_ERROR "unexpected consumer output:\n${last_output}")
endif()
message(STATUS "consumer ran:\n${last_output}")
