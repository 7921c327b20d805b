# Cross-compiles for 64-bit ARM Linux with Debian's g++-aarch64-linux-gnu
# (scripts/cross-check-aarch64.sh runs the result under qemu-aarch64).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
# Eigen is header-only and architecture-independent: the host's copy serves.
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
