# particlesim_require_determinism(DIR): every library and executable defined
# in DIR and below must link particlesim_determinism, directly or through
# particlesim_internals or particlesim_test_support; configuring fails
# otherwise, naming the target. A target that forgets it would compile the
# physics with the compiler's default FMA contraction and could print other
# bytes on another machine.
function(particlesim_require_determinism dir)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$")
      continue()
    endif()
    get_target_property(links ${target} LINK_LIBRARIES)
    if(NOT links MATCHES "particlesim_(determinism|internals|test_support)")
      message(FATAL_ERROR "target ${target} does not link particlesim_determinism: its floating point could "
                          "differ from the library's (see cmake/require_determinism.cmake)")
    endif()
  endforeach()
  get_property(subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    particlesim_require_determinism("${subdir}")
  endforeach()
endfunction()
