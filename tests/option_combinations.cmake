# The build options configure alone and together: none, each one, the apps
# without tests, and all (the sanitizers change flags, not what is built); the
# library alone, which no other build of the suite makes, is also built (at
# -O0, for speed).
# Inputs: SOURCE_DIR, WORK_DIR.
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
  execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${build_dir}" ${args} -DCMAKE_BUILD_TYPE=Debug
                  "-DCMAKE_CXX_FLAGS_DEBUG=-O0" RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "configure failed with ${args}:\n${err}")
  endif()
  # 0000: the library alone.
  if(name STREQUAL "0000")
    execute_process(COMMAND ${CMAKE_COMMAND} --build "${build_dir}" -j 2 RESULT_VARIABLE status OUTPUT_VARIABLE out
                    ERROR_VARIABLE err)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "build failed with ${args}:\n${out}\n${err}")
    endif()
    message(STATUS "configured and built: ${args}")
  else()
    message(STATUS "configured: ${args}")
  endif()
  file(REMOVE_RECURSE "${build_dir}")
endforeach()
