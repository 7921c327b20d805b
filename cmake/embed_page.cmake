# Builds simcli's animation page from its sources (apps/simcli/page/): the CSS
# and the script are put inline into page.html, and the result is written as
# a C++ header of two string views, the page before and after the run's data.
# Inputs: PAGE_DIR, OUTPUT.
file(READ "${PAGE_DIR}/page.html" html)
file(READ "${PAGE_DIR}/page.css" css)
file(READ "${PAGE_DIR}/page.js" js)
set(delimiter "particlesim_page")
foreach(part html css js)
  string(FIND "${${part}}" ")${delimiter}\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "page.${part} contains the raw-string delimiter )${delimiter}\"")
  endif()
endforeach()
string(REPLACE "/*@PAGE_CSS@*/" "${css}" html "${html}")
string(REPLACE "/*@PAGE_JS@*/" "${js}" html "${html}")
string(FIND "${html}" "<!--@RUN_DATA@-->" at)
if(at EQUAL -1)
  message(FATAL_ERROR "page.html has no <!--@RUN_DATA@--> placeholder")
endif()
string(SUBSTRING "${html}" 0 ${at} before)
math(EXPR after_start "${at} + 17")
string(SUBSTRING "${html}" ${after_start} -1 after)
file(WRITE "${OUTPUT}.tmp"
  "// Generated from apps/simcli/page/ by cmake/embed_page.cmake: edit those files, not this one.\n"
  "#pragma once\n#include <string_view>\nnamespace simcli::page {\n"
  "inline constexpr std::string_view before_data = R\"${delimiter}(${before})${delimiter}\";\n"
  "inline constexpr std::string_view after_data = R\"${delimiter}(${after})${delimiter}\";\n"
  "}  // namespace simcli::page\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
