# CLI contract tests for `exactccd check`, run by CTest:
#   cmake -DEXE=<exactccd> -DDATA=<tests/data> -P cli_check.cmake
# 1. --answers prints exactly one line per query, 0 or 1, nothing else, and the right answers.
execute_process(COMMAND ${EXE} check --answers ${DATA}/small-vertex-face.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check --answers exited with ${rc}: ${err}")
endif()
if(NOT out STREQUAL "1\n0\n")
  message(FATAL_ERROR "check --answers printed '${out}', expected '1\\n0\\n'")
endif()
# 2. A malformed line is an error naming file and line, with exit code 2 and nothing on stdout.
execute_process(COMMAND ${EXE} check --answers ${DATA}/malformed-vertex-face.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "malformed input: exit code ${rc}, expected 2")
endif()
if(NOT err MATCHES "malformed-vertex-face.csv:5:")
  message(FATAL_ERROR "malformed input: stderr '${err}' does not name file and line 5")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "malformed input: stdout not empty: '${out}'")
endif()
# 3. The kind cannot be inferred from this path without --kind.
execute_process(COMMAND ${EXE} check ${DATA}/../cli_check.cmake RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "uninferable kind: exit code ${rc}, expected 2")
endif()
# 4. Every method answers the same on this small exact data; naive too here.
foreach(method filtered exact naive)
  execute_process(COMMAND ${EXE} check --method ${method} --answers ${DATA}/small-vertex-face.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n0\n")
    message(FATAL_ERROR "--method ${method}: exit ${rc}, output '${out}'")
  endif()
endforeach()
