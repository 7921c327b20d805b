# The C++ example in README.md must be examples/library_usage.cpp, verbatim,
# so that the compiled (and tested) file is what readers copy.
file(READ "${README}" readme)
file(READ "${EXAMPLE}" example)
string(FIND "${readme}" "${example}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md does not contain examples/library_usage.cpp verbatim")
endif()
# And the consumer CMakeLists.txt that the install test builds.
file(READ "${CONSUMER}" consumer)
string(FIND "${readme}" "${consumer}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md does not contain tests/consumer/CMakeLists.txt verbatim")
endif()
