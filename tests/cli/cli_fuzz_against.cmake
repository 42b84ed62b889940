# CLI contract tests for `exactccd fuzz-against`, run by CTest:
#   cmake -DEXE=<exactccd> -DNAIVE=<naive_plugin.so> -DVF_ONLY=<plugin_vf_only.so> -DWORK=<dir>
#         -P cli_fuzz_against.cmake
file(REMOVE_RECURSE ${WORK})
# 1. A plug-in without the kind's symbol: exit 2, an error naming the symbol, nothing on stdout.
execute_process(COMMAND ${EXE} fuzz-against ${VF_ONLY} --kind ee --queries 10 --out ${WORK}/ee-only
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "does not export the symbol exactccd_plugin_ee" OR NOT out STREQUAL "")
  message(FATAL_ERROR "missing symbol: exit ${rc} (expected 2), stderr '${err}', stdout '${out}'")
endif()
# ... while the symbol it has is accepted.
execute_process(COMMAND ${EXE} fuzz-against ${VF_ONLY} --kind vf --queries 40 --out ${WORK}/vf-only
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\ntotal +40 ")
  message(FATAL_ERROR "vf-only plug-in, --kind vf: exit ${rc}\n${out}\n${err}")
endif()
# 2. A file that is not a plug-in, and bad usage: exit 2.
execute_process(COMMAND ${EXE} fuzz-against ${WORK}/no-such-plugin.so --kind vf --out ${WORK}/x
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "cannot load plug-in")
  message(FATAL_ERROR "missing plug-in file: exit ${rc}, stderr '${err}'")
endif()
execute_process(COMMAND ${EXE} fuzz-against ${NAIVE} --out ${WORK}/x RESULT_VARIABLE rc ERROR_QUIET)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "no --kind: exit ${rc}, expected 2")
endif()
execute_process(COMMAND ${EXE} fuzz-against --help RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: exactccd fuzz-against")
  message(FATAL_ERROR "fuzz-against --help: exit ${rc}")
endif()
# 3. The naive method as a plug-in: disagreements are found and written as CSVs that replay:
#    `check` finds their truth column exact (0 FP, 0 FN) and `check --method naive` errs on
#    every one of them, as the plug-in did.
foreach(kind vf ee)
  if(kind STREQUAL "vf")
    set(long vertex-face)
  else()
    set(long edge-edge)
  endif()
  set(dir ${WORK}/naive)
  execute_process(COMMAND ${EXE} fuzz-against ${NAIVE} --kind ${kind} --queries 300 --seed 7 --threads 2
                          --out ${dir}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fuzz-against naive --kind ${kind}: exit ${rc}\n${out}\n${err}")
  endif()
  if(NOT out MATCHES "\ntotal +300 +[0-9]+ +([0-9]+) +([0-9]+) +0 ")
    message(FATAL_ERROR "fuzz-against naive --kind ${kind}: no total line\n${out}")
  endif()
  math(EXPR found "${CMAKE_MATCH_1} + ${CMAKE_MATCH_2}")
  if(found EQUAL 0)
    message(FATAL_ERROR "fuzz-against found no disagreement in the naive method (${kind})\n${out}")
  endif()
  file(GLOB singles ${dir}/[0-9][0-9][0-9][0-9][0-9][0-9]-*-${long}.csv)
  list(LENGTH singles n)
  if(NOT n EQUAL found)
    message(FATAL_ERROR "${kind}: ${found} disagreements but ${n} files")
  endif()
  execute_process(COMMAND ${EXE} check --kind ${kind} ${dir}/disagreements-${long}.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\ntotal +${found} +[0-9]+ +0 +0 ")
    message(FATAL_ERROR "${kind}: the truth column is not the exact answer:\n${out}")
  endif()
  execute_process(COMMAND ${EXE} check --kind ${kind} --method naive ${dir}/disagreements-${long}.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\ntotal +${found} +[0-9]+ +([0-9]+) +([0-9]+) ")
    message(FATAL_ERROR "${kind}: check --method naive failed:\n${out}")
  endif()
  math(EXPR replayed "${CMAKE_MATCH_1} + ${CMAKE_MATCH_2}")
  if(NOT replayed EQUAL found)
    message(FATAL_ERROR "${kind}: naive errs on ${replayed} of the ${found} written disagreements")
  endif()
  # The example plug-in reports times of impact (plugin.h's optional entry point): the unsafe
  # ones are written and replay: each collides exactly, and `compare --toi` with the plug-in's
  # times (from the .txt) finds every one unsafe.
  execute_process(COMMAND ${EXE} fuzz-against ${NAIVE} --kind ${kind} --queries 300 --seed 7 --threads 2
                          --out ${dir}-toi RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "collisions both find, ([0-9]+) safe \\(T <= exact\\), ([0-9]+) unsafe")
    message(FATAL_ERROR "fuzz-against ${kind}: no times-of-impact line\n${out}\n${err}")
  endif()
  set(unsafe ${CMAKE_MATCH_2})
  if(unsafe GREATER 0)
    file(STRINGS ${dir}-toi/unsafe-toi-${long}.txt lines REGEX "  T ")
    set(theirs "")
    foreach(line IN LISTS lines)
      string(REGEX MATCH "  T ([^ ]+)  exact" m "${line}")
      string(APPEND theirs "1 ${CMAKE_MATCH_1}\n")
    endforeach()
    file(WRITE ${dir}-toi/theirs.txt "${theirs}")
    execute_process(COMMAND ${EXE} compare --kind ${kind} --toi ${dir}-toi/theirs.txt ${dir}-toi/unsafe-toi-${long}.csv
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0 OR NOT out MATCHES "false positives 0, false negatives 0\ntoi: shared collisions ${unsafe}, safe 0, unsafe ${unsafe}\n")
      message(FATAL_ERROR "${kind}: the unsafe TOIs do not replay with compare --toi:\n${out}\n${err}")
    endif()
  endif()
  # Each single file replays on its own: one query, FP or FN as its name says.
  list(GET singles 0 first)
  string(REGEX MATCH "-(FP|FN)-" type ${first})
  execute_process(COMMAND ${EXE} check --method naive ${first} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(type STREQUAL "-FP-")
    set(expect "\ntotal +1 +0 +1 +0 ")
  else()
    set(expect "\ntotal +1 +1 +0 +1 ")
  endif()
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${expect}")
    message(FATAL_ERROR "${first} does not replay as ${type}:\n${out}")
  endif()
endforeach()
# 4. Same seed, different thread count: identical output files.
execute_process(COMMAND ${EXE} fuzz-against ${NAIVE} --kind ee --queries 300 --seed 7 --threads 1
                        --out ${WORK}/naive-1thread RESULT_VARIABLE rc OUTPUT_QUIET)
file(READ ${WORK}/naive/disagreements-edge-edge.csv a)
file(READ ${WORK}/naive-1thread/disagreements-edge-edge.csv b)
if(NOT rc EQUAL 0 OR NOT a STREQUAL b)
  message(FATAL_ERROR "fuzz-against: --threads 1 and --threads 2 wrote different disagreements")
endif()
file(REMOVE_RECURSE ${WORK})
