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
# 5. --threads gives the same answers; --shard I/N splits the queries into contiguous blocks.
execute_process(COMMAND ${EXE} check --threads 3 --answers ${DATA}/small-vertex-face.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n0\n")
  message(FATAL_ERROR "--threads 3: exit ${rc}, output '${out}'")
endif()
execute_process(COMMAND ${EXE} check --shard 0/2 --answers ${DATA}/small-vertex-face.csv OUTPUT_VARIABLE s0)
execute_process(COMMAND ${EXE} check --shard 1/2 --answers ${DATA}/small-vertex-face.csv OUTPUT_VARIABLE s1)
if(NOT s0 STREQUAL "1\n" OR NOT s1 STREQUAL "0\n")
  message(FATAL_ERROR "--shard: got '${s0}' and '${s1}'")
endif()
execute_process(COMMAND ${EXE} check --shard 2/2 ${DATA}/small-vertex-face.csv RESULT_VARIABLE rc)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "--shard 2/2 must be a usage error, exit ${rc}")
endif()
# 6. bench --json writes one object per (dataset, method) with the documented keys.
execute_process(COMMAND ${EXE} bench --repetitions 1 --json - ${DATA}/small-vertex-face.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench --json: exit ${rc}")
endif()
foreach(key dataset kind method queries mean_ns median_ns fp fn exact_fallbacks)
  string(REGEX MATCHALL "\"${key}\":" found "${out}")
  list(LENGTH found count)
  if(NOT count EQUAL 3)
    message(FATAL_ERROR "bench --json: key ${key} appears ${count} times, expected 3:\n${out}")
  endif()
endforeach()
# 7. Every subcommand answers --help with exit code 0.
foreach(sub check bench generate)
  execute_process(COMMAND ${EXE} ${sub} --help RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: exactccd ${sub}")
    message(FATAL_ERROR "${sub} --help: exit ${rc}")
  endif()
endforeach()
# 8. The committed catalogue CSVs are what `generate catalogue` writes now (no stale data).
set(gen ${DATA}/../../build-generate-check)
file(REMOVE_RECURSE ${gen})
execute_process(COMMAND ${EXE} generate catalogue --out ${gen} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "generate catalogue: exit ${rc}")
endif()
foreach(kind vertex-face edge-edge)
  file(READ ${gen}/catalogue-${kind}.csv fresh)
  file(READ ${DATA}/../../data/catalogue/catalogue-${kind}.csv committed)
  if(NOT fresh STREQUAL committed)
    message(FATAL_ERROR "data/catalogue/catalogue-${kind}.csv is stale: run exactccd generate catalogue --out data/catalogue")
  endif()
endforeach()
file(REMOVE_RECURSE ${gen})
# 9. The bundled catalogue: the exact answers match its hand-derived truth column.
execute_process(COMMAND ${EXE} check ${DATA}/../../data/catalogue/catalogue-vertex-face.csv
                        ${DATA}/../../data/catalogue/catalogue-edge-edge.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "total +297 +187 +0 +0 ")
  message(FATAL_ERROR "check on the catalogue: exit ${rc}\n${out}")
endif()
