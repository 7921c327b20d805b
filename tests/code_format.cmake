# The code follows .clang-format: clang-format reports no change to any source.
# Inputs: SOURCE_DIR, CLANG_FORMAT (the program; empty when not found at
# configure time: looked for again here, since the test command installs it
# while the build compiles).
if(NOT CLANG_FORMAT)
  find_program(found_clang_format NAMES clang-format clang-format-14 clang-format-15 clang-format-16)
  set(CLANG_FORMAT "${found_clang_format}")
endif()
if(NOT CLANG_FORMAT)
  message(FATAL_ERROR "clang-format not found: install Debian's clang-format (scripts/run-tests.sh does, as root)")
endif()
file(GLOB_RECURSE sources "${SOURCE_DIR}/include/*.hpp" "${SOURCE_DIR}/src/*.hpp" "${SOURCE_DIR}/src/*.cpp"
     "${SOURCE_DIR}/apps/*.cpp" "${SOURCE_DIR}/tests/*.hpp" "${SOURCE_DIR}/tests/*.cpp" "${SOURCE_DIR}/bench/*.hpp"
     "${SOURCE_DIR}/bench/*.cpp" "${SOURCE_DIR}/examples/*.cpp" "${SOURCE_DIR}/profile/*.cpp")
execute_process(COMMAND "${CLANG_FORMAT}" --dry-run --Werror ${sources} RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "sources differ from .clang-format (run clang-format -i on them):\n${err}")
endif()
