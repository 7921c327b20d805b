# pkg-config files (particlesim, particlesim-check, particlesim-mpi) for
# build systems other than CMake, installed beside the CMake package. Their
# prefix is found from where the file lies (${pcfiledir}), so that
# `cmake --install --prefix` anywhere, or moving the installed tree, keeps
# them right.
set(pc_dir "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  # Fixed places: named as they are.
  set(PC_RELATIVE_PREFIX ".")
  set(PC_LIBDIR "${CMAKE_INSTALL_FULL_LIBDIR}")
  set(PC_INCLUDEDIR "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
else()
  file(RELATIVE_PATH PC_RELATIVE_PREFIX "/prefix/${pc_dir}" "/prefix")
  string(REGEX REPLACE "/$" "" PC_RELATIVE_PREFIX "${PC_RELATIVE_PREFIX}")
  set(PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
  set(PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
# The public headers include Eigen's.
get_target_property(eigen_includes Eigen3::Eigen INTERFACE_INCLUDE_DIRECTORIES)
set(PC_EIGEN_CFLAGS "")
foreach(directory IN LISTS eigen_includes)
  string(APPEND PC_EIGEN_CFLAGS " -I${directory}")
endforeach()
string(STRIP "${PC_EIGEN_CFLAGS}" PC_EIGEN_CFLAGS)
# A static library leaves OpenMP's runtime to the program's link; a shared
# one links it itself.
get_target_property(library_type particlesim TYPE)
if(library_type STREQUAL "STATIC_LIBRARY")
  set(PC_LIBS "-L\${libdir} -lparticlesim ${OpenMP_CXX_FLAGS} -pthread")
else()
  set(PC_LIBS "-L\${libdir} -lparticlesim\nLibs.private: ${OpenMP_CXX_FLAGS} -pthread")
endif()
set(pc_names particlesim particlesim-check)
if(PARTICLESIM_MPI)
  list(APPEND pc_names particlesim-mpi)
endif()
foreach(name IN LISTS pc_names)
  configure_file("${CMAKE_CURRENT_LIST_DIR}/${name}.pc.in" "${CMAKE_CURRENT_BINARY_DIR}/${name}.pc" @ONLY)
  install(FILES "${CMAKE_CURRENT_BINARY_DIR}/${name}.pc" DESTINATION "${pc_dir}")
endforeach()
