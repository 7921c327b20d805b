# History lives in CHANGELOG.md and the commit messages: no file of the tree
# speaks of sessions, issue numbers or findings (tests name the behaviour they
# check, not when it was found).
# Inputs: SOURCE_DIR.
file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/src/*" "${SOURCE_DIR}/include/*"
     "${SOURCE_DIR}/apps/*" "${SOURCE_DIR}/tests/*" "${SOURCE_DIR}/bench/*" "${SOURCE_DIR}/docs/*.md"
     "${SOURCE_DIR}/scripts/*" "${SOURCE_DIR}/cmake/*" "${SOURCE_DIR}/examples/*" "${SOURCE_DIR}/fuzz/*.cpp" "${SOURCE_DIR}/profile/*"
     "${SOURCE_DIR}/README.md" "${SOURCE_DIR}/CMakeLists.txt")
list(FILTER files EXCLUDE REGEX "\\.(png|svg)$|^tests/present_tense\\.cmake$")
set(found "")
foreach(file IN LISTS files)
  file(STRINGS "${SOURCE_DIR}/${file}" lines REGEX "[Ss]ession|[Ii]ssue [0-9]|[Ff]inding [0-9]")
  foreach(line IN LISTS lines)
    string(APPEND found "\n  ${file}: ${line}")
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "history outside CHANGELOG.md (say what is true now; history goes to CHANGELOG.md):${found}")
endif()
list(LENGTH files count)
message(STATUS "${count} files speak in the present")
