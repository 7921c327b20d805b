# docs/architecture.md names every file of src/, and names no file that is
# not there: each path is written out in full (`src/folder/file.hpp`).
# Inputs: SOURCE_DIR.
file(READ "${SOURCE_DIR}/docs/architecture.md" doc)
string(REGEX MATCHALL "src/[a-z0-9_/]+\\.(hpp|cpp)" named "${doc}")
list(REMOVE_DUPLICATES named)
list(SORT named)
file(GLOB_RECURSE present RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/src/*.hpp" "${SOURCE_DIR}/src/*.cpp")
list(SORT present)
set(missing ${present})
list(REMOVE_ITEM missing ${named})
set(stale ${named})
list(REMOVE_ITEM stale ${present})
if(missing OR stale)
  message(FATAL_ERROR "docs/architecture.md and src/ disagree.\n"
                      "In src/ but not in the file table: ${missing}\nIn the file table but not in src/: ${stale}")
endif()
list(LENGTH present count)
message(STATUS "docs/architecture.md names all ${count} files of src/")
