# README.md's "simcli" section is `simcli --help`, verbatim but for the word
# "usage:" and the closing exit status paragraph (the README says it in prose),
# so that the options a reader sees are the ones simcli takes.
# Inputs: README, SIMCLI.
execute_process(COMMAND "${SIMCLI}" --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "simcli --help exited with ${status}")
endif()
string(REGEX REPLACE "^usage: " "" help "${help}")
string(REPLACE "\n       simcli --resume" "\nsimcli --resume" help "${help}")
string(FIND "${help}" "\n\nExit status:" at)
if(at EQUAL -1)
  message(FATAL_ERROR "simcli --help has no exit status paragraph")
endif()
string(SUBSTRING "${help}" 0 ${at} help)
file(READ "${README}" readme)
string(FIND "${readme}" "```\n${help}\n```" at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md's simcli section is not simcli --help; paste it again:\n${help}")
endif()
