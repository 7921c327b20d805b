# The build options configure alone and together: none, each one, the apps
# without tests, and all (the sanitizers change flags, not what is built).
# The library alone is built by subdirectory_consumer.cmake.
# Inputs: SOURCE_DIR, WORK_DIR, GENERATOR (the main build's).
file(REMOVE_RECURSE "${WORK_DIR}")
set(options PARTICLESIM_BUILD_APPS PARTICLESIM_BUILD_TESTS PARTICLESIM_BUILD_BENCH PARTICLESIM_SANITIZE)
foreach(mask RANGE 15)
  if(NOT mask MATCHES "^(0|1|2|4|5|8|15)$")
    continue()
  endif()
  set(args "")
  set(name "")
  set(bit 1)
  foreach(option IN LISTS options)
    math(EXPR on "${mask} & ${bit}")
    if(on)
      list(APPEND args "-D${option}=ON")
      string(APPEND name "1")
    else()
      list(APPEND args "-D${option}=OFF")
      string(APPEND name "0")
    endif()
    math(EXPR bit "${bit} * 2")
  endforeach()
  set(build_dir "${WORK_DIR}/${name}")
  execute_process(COMMAND ${CMAKE_COMMAND} -G "${GENERATOR}" -S "${SOURCE_DIR}" -B "${build_dir}" ${args} -DCMAKE_BUILD_TYPE=Debug RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "configure failed with ${args}:\n${err}")
  endif()
  message(STATUS "configured: ${args}")
  file(REMOVE_RECURSE "${build_dir}")
endforeach()

# The distributed engine: with MPI it configures; without, it stops with a
# message that names the packages.
execute_process(COMMAND ${CMAKE_COMMAND} -G "${GENERATOR}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/mpi" -DPARTICLESIM_MPI=ON
                        -DPARTICLESIM_BUILD_TESTS=OFF -DPARTICLESIM_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(status EQUAL 0)
  message(STATUS "configured: -DPARTICLESIM_MPI=ON")
elseif(err MATCHES "libopenmpi-dev openmpi-bin")
  message(STATUS "without MPI, -DPARTICLESIM_MPI=ON says what to install")
else()
  message(FATAL_ERROR "configure failed with -DPARTICLESIM_MPI=ON, without naming the packages:\n${err}")
endif()
file(REMOVE_RECURSE "${WORK_DIR}/mpi")

# The profile-guided build: on by default for a GCC Release build, off for
# any other build type, and configurable on in one.
foreach(case "Release:none:ON" "Debug:none:OFF" "Debug:-DPARTICLESIM_PROFILE_GUIDED=ON:ON")
  string(REPLACE ":" ";" case "${case}")
  list(GET case 0 type)
  list(GET case 1 setting)
  list(GET case 2 expected)
  if(setting STREQUAL "none")
    set(setting "")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -G "${GENERATOR}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/profiled"
                          -DCMAKE_CXX_COMPILER=g++ -DCMAKE_BUILD_TYPE=${type} ${setting}
                          -DPARTICLESIM_BUILD_TESTS=OFF -DPARTICLESIM_BUILD_BENCH=OFF
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "configure failed with ${type} ${setting}:\n${err}")
  endif()
  file(STRINGS "${WORK_DIR}/profiled/CMakeCache.txt" cached REGEX "^PARTICLESIM_PROFILE_GUIDED:BOOL=")
  if(NOT cached STREQUAL "PARTICLESIM_PROFILE_GUIDED:BOOL=${expected}")
    message(FATAL_ERROR "${type} ${setting}: ${cached}, expected ${expected}")
  endif()
  message(STATUS "configured: ${type} ${setting}: profile-guided ${expected}")
  file(REMOVE_RECURSE "${WORK_DIR}/profiled")
endforeach()

# Forced on with a compiler other than GCC, it stops with one message.
find_program(clang_compiler clang++)
if(clang_compiler)
  execute_process(COMMAND ${CMAKE_COMMAND} -G "${GENERATOR}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/profiled_clang"
                          -DCMAKE_CXX_COMPILER=${clang_compiler} -DCMAKE_BUILD_TYPE=Release
                          -DPARTICLESIM_PROFILE_GUIDED=ON
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
  if(status EQUAL 0 OR NOT err MATCHES "needs GCC 11 or later")
    message(FATAL_ERROR "clang with -DPARTICLESIM_PROFILE_GUIDED=ON did not refuse with the message:\n${err}")
  endif()
  message(STATUS "clang with -DPARTICLESIM_PROFILE_GUIDED=ON refuses")
  file(REMOVE_RECURSE "${WORK_DIR}/profiled_clang")
else()
  message(STATUS "SKIPPED: clang++ is missing, so the profile-guided build's refusal of another compiler is not checked")
endif()
