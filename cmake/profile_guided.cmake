# The library's profile-guided build (PARTICLESIM_PROFILE_GUIDED; GCC): the
# sources whose speed users wait on are compiled once instrumented into a
# training program (profile/), which runs at build time, and the library's
# own copies are then compiled from the profile it wrote: GCC lays out their
# branches and inlines their calls as the training run took them
# (docs/benchmarks.md, "The exact engine built from a profile"). No result
# changes: both compiles keep particlesim_determinism's flags.
#
# particlesim_profile_guided(LIBRARY <target> OBJECTS <object library of the rest>
#                            TRAINING <source with main()> SOURCES <profiled sources...>)
# The profiled sources must be LIBRARY's own sources, not in OBJECTS.
function(particlesim_profile_guided)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "LIBRARY;OBJECTS;TRAINING" "SOURCES")
  set(trainer particlesim_profile_training)
  set(profile_dir ${CMAKE_CURRENT_BINARY_DIR}/profile)
  set(included_copies)
  set(profiles)
  foreach(source IN LISTS arg_SOURCES)
    # One name for both compiles of a source: GCC names its profile after it,
    # and a function of internal linkage's identity in the profile too.
    string(REPLACE "/" "_" profile_name ${source})
    set(same_names -dumpdir ${profile_dir}/ -dumpbase ${profile_name})
    list(APPEND profiles ${profile_dir}/${profile_name}.gcda)
    # The training program compiles a file that includes the source, so that
    # the source's own properties (its profile, below) stay the library's.
    set(included_copy ${CMAKE_CURRENT_BINARY_DIR}/profile_training/${source})
    file(CONFIGURE OUTPUT ${included_copy} CONTENT "#include \"${CMAKE_CURRENT_SOURCE_DIR}/${source}\"\n")
    set_source_files_properties(${included_copy} PROPERTIES
      COMPILE_OPTIONS "-fprofile-generate;-fprofile-update=single;${same_names}")
    list(APPEND included_copies ${included_copy})
    # -fprofile-partial-training: code the training run never reached keeps
    # its ordinary optimisation instead of being compiled for size.
    # -fno-tracer: GCC 12 fails with an internal error on exact_simulation.cpp
    # with the tracer's tail duplication, which the profile turns on.
    set_source_files_properties(${source} PROPERTIES
      OBJECT_DEPENDS ${profile_dir}/${profile_name}.gcda
      COMPILE_OPTIONS "-fprofile-use;-fprofile-partial-training;-fno-tracer;${same_names}"
      SKIP_PRECOMPILE_HEADERS ON)
  endforeach()

  add_executable(${trainer} ${arg_TRAINING} ${included_copies} $<TARGET_OBJECTS:${arg_OBJECTS}>)
  particlesim_engine_settings(${trainer} PRIVATE)
  # Compiled as the library is (-fPIC, not an executable's -fPIE, which lets
  # GCC inline other calls), or the profile would not match its functions.
  set_target_properties(${trainer} PROPERTIES POSITION_INDEPENDENT_CODE OFF)
  # Only the profiled sources are instrumented (above); the link brings libgcov.
  target_compile_options(${trainer} PRIVATE -fPIC)
  target_link_options(${trainer} PRIVATE -fprofile-generate)

  # A run adds its counts to any profile already there: start from none.
  add_custom_command(OUTPUT ${profiles}
    COMMAND ${CMAKE_COMMAND} -E rm -f ${profiles}
    COMMAND ${trainer}
    DEPENDS ${trainer}
    COMMENT "Running the training program of the profile-guided build"
    VERBATIM)
endfunction()
