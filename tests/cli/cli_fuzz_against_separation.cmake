# CLI contract tests of `exactccd fuzz-against --min-distance D --tmax T` (every kind), run by CTest:
#   cmake -DEXE=<exactccd> -DEXACT=<exact_plugin.so> -DSAMPLED=<sampled_distance_plugin.so>
#         -DVF_ONLY=<plugin_vf_only.so> -DNAIVE=<naive_plugin.so> -DWORK=<dir> -P cli_fuzz_against_separation.cmake
# vf and ee run fewer queries: their exact answers on tangencies at d cost ~30 ms each (and
# shrinking one disagreement ~60 of them).
file(REMOVE_RECURSE ${WORK})
set(question --min-distance 1e-3 --tmax 0.75)
set(long_vf vertex-face)
set(long_ee edge-edge)
set(long_pe point-edge)
set(long_pp point-point)
set(long_ee2 edge-edge-2d)
set(long_pe2 point-edge-2d)
set(long_pp2 point-point-2d)
# The total row: queries, collide, FP, FN, errors, unsafe, early.
set(total_row "\ntotal +([0-9]+) +([0-9]+) +([0-9]+) +([0-9]+) +([0-9]+) +([0-9-]+) +([0-9-]+) ")

function(run_fuzz out_var)
  execute_process(COMMAND ${EXE} fuzz-against ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${total_row}")
    message(FATAL_ERROR "fuzz-against ${ARGN}: exit ${rc}\n${out}\n${err}")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
  foreach(i RANGE 1 7)
    set(column_${i} ${CMAKE_MATCH_${i}} PARENT_SCOPE)
  endforeach()
endfunction()

# Expects `exactccd check ARGS` to print a total of `queries` queries with fp FP and fn FN.
function(expect_check queries fp fn)
  execute_process(COMMAND ${EXE} check ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\ntotal +${queries} +[0-9]+ +${fp} +${fn} ")
    message(FATAL_ERROR "check ${ARGN}: expected ${queries} queries, FP ${fp}, FN ${fn}:\n${out}\n${err}")
  endif()
endfunction()

# 1. exactccd itself (Method::filtered through the public API) as a plug-in finds nothing against
#    the reference path, for every kind at d > 0, and at d = 0 on the plane's point-edge (whose
#    families are the separation ones at d = 0).
foreach(kind vf ee pe pp ee2 pe2 pp2 pe2@0)
  string(REPLACE "@0" "" k ${kind})
  set(q ${question})
  if(kind MATCHES "@0")
    set(q "")
  endif()
  set(n 200)
  if(k STREQUAL "vf" OR k STREQUAL "ee")
    set(n 64)
  endif()
  run_fuzz(out ${EXACT} --kind ${k} ${q} --queries ${n} --threads 2 --out ${WORK}/exact)
  if(NOT column_1 EQUAL n OR NOT "${column_3} ${column_4} ${column_5} ${column_6} ${column_7}" STREQUAL "0 0 0 0 0")
    message(FATAL_ERROR "the library as a plug-in disagrees (${kind}):\n${out}")
  endif()
endforeach()

# 2. A plug-in that checks the distance at sampled times only: its false negatives (passes at d
#    between two samples) and unsafe times are found; every written counterexample replays with
#    `check` and the run's question to the exact truth (0 FP, 0 FN), not with the contact question;
#    the unsafe times replay with `compare --toi`.
foreach(kind pe ee2 pp2 vf)
  set(dir ${WORK}/sampled-${kind})
  set(long ${long_${kind}})
  set(args --queries 200)
  if(kind STREQUAL "vf")
    set(args --queries 64 --no-shrink)
  endif()
  run_fuzz(out ${SAMPLED} --kind ${kind} ${question} ${args} --threads 2 --out ${dir})
  math(EXPR found "${column_3} + ${column_4}")
  if(column_4 EQUAL 0 OR column_6 EQUAL 0)
    message(FATAL_ERROR "sampled distance (${kind}): no false negative or no unsafe time found\n${out}")
  endif()
  file(GLOB singles ${dir}/[0-9][0-9][0-9][0-9][0-9][0-9]-*-${long}.csv)
  list(LENGTH singles n)
  if(NOT n EQUAL found)
    message(FATAL_ERROR "${kind}: ${found} disagreements but ${n} files")
  endif()
  expect_check(${found} 0 0 --kind ${kind} ${question} ${dir}/disagreements-${long}.csv)
  foreach(single IN LISTS singles)
    expect_check(1 0 0 --kind ${kind} ${question} ${single})
  endforeach()
  execute_process(COMMAND ${EXE} check --kind ${kind} ${dir}/disagreements-${long}.csv OUTPUT_VARIABLE out)
  if(out MATCHES "\ntotal +${found} +[0-9]+ +0 +0 ")
    message(FATAL_ERROR "${kind}: the counterexamples' truth is the contact question's, not d = 1e-3's")
  endif()
  file(STRINGS ${dir}/unsafe-toi-${long}.txt lines REGEX "  T ")
  set(theirs "")
  foreach(line IN LISTS lines)
    string(REGEX MATCH "  T ([^ ]+)  exact" m "${line}")
    string(APPEND theirs "1 ${CMAKE_MATCH_1}\n")
  endforeach()
  file(WRITE ${dir}/theirs.txt "${theirs}")
  execute_process(COMMAND ${EXE} compare --kind ${kind} ${question} --toi ${dir}/theirs.txt ${dir}/unsafe-toi-${long}.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "toi: shared collisions ${column_6}, safe 0, unsafe ${column_6}\n")
    message(FATAL_ERROR "${kind}: the unsafe times do not replay with compare --toi:\n${out}\n${err}")
  endif()
endforeach()
# Early times (2 T < the exact time): this run has one (a sample's distance in doubles under d
# while the exact one is not: coordinates near 2^55), listed in early-toi-point-edge.txt.
run_fuzz(out ${SAMPLED} --kind pe ${question} --queries 200 --threads 2 --out ${WORK}/sampled-pe)
file(STRINGS ${WORK}/sampled-pe/early-toi-point-edge.txt early REGEX "  T ")
list(LENGTH early n)
if(column_7 EQUAL 0 OR NOT n EQUAL column_7)
  message(FATAL_ERROR "pe: ${column_7} early times in the table, ${n} in early-toi-point-edge.txt\n${out}")
endif()

# 3. Plug-ins with only the contact-only symbols run at the contact question as before (given
#    explicitly here), and any other question is an error naming the symbol it needs.
run_fuzz(out ${VF_ONLY} --kind vf --min-distance 0 --tmax 1 --queries 40 --out ${WORK}/vf-only)
if(NOT out MATCHES "\\(exactccd_plugin_vf\\)" OR NOT column_1 EQUAL 40)
  message(FATAL_ERROR "vf-only plug-in at the contact question:\n${out}")
endif()
execute_process(COMMAND ${EXE} fuzz-against ${VF_ONLY} --kind vf --tmax 0.5 --queries 10 --out ${WORK}/x
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "exactccd_plugin_vf answers only d = 0 and tmax = 1" OR NOT out STREQUAL "")
  message(FATAL_ERROR "vf-only plug-in at tmax 0.5: exit ${rc}, stderr '${err}', stdout '${out}'")
endif()
execute_process(COMMAND ${EXE} fuzz-against ${VF_ONLY} --kind vf ${question} --queries 10 --out ${WORK}/x
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "does not export the symbol exactccd_plugin_vf_query" OR NOT out STREQUAL "")
  message(FATAL_ERROR "vf-only plug-in at d > 0: exit ${rc}, stderr '${err}', stdout '${out}'")
endif()
execute_process(COMMAND ${EXE} fuzz-against ${NAIVE} --kind pe --queries 10 --out ${WORK}/x
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "does not export the symbol exactccd_plugin_pe_query" OR NOT out STREQUAL "")
  message(FATAL_ERROR "contact-only plug-in, --kind pe: exit ${rc}, stderr '${err}', stdout '${out}'")
endif()

# Questions the families cannot ask, and bad factors: usage errors.
foreach(bad "--min-distance;1e302;above 2\\^1000" "--early-factor;0.5;--early-factor needs" "--min-distance;-1;--min-distance needs")
  list(GET bad 0 option)
  list(GET bad 1 value)
  list(GET bad 2 message)
  execute_process(COMMAND ${EXE} fuzz-against ${EXACT} --kind pp ${option} ${value} --queries 10 --out ${WORK}/x
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${message}" OR NOT out STREQUAL "")
    message(FATAL_ERROR "${option} ${value}: exit ${rc}, stderr '${err}', stdout '${out}'")
  endif()
endforeach()

# 4. A sharded run at d > 0, merged: byte-identical to one run, report and files (and the one
#    run with --threads 1 identical to --threads 2).
set(one ${WORK}/one)
file(MAKE_DIRECTORY ${one})
execute_process(COMMAND ${EXE} fuzz-against ${SAMPLED} --kind pp2 ${question} --queries 120 --seed 3 --out out
                WORKING_DIRECTORY ${one} OUTPUT_VARIABLE single ERROR_QUIET)
foreach(i 0 1 2)
  execute_process(COMMAND ${EXE} fuzz-against ${SAMPLED} --kind pp2 ${question} --queries 120 --seed 3 --threads 2
                          --shard ${i}/3 --partial ${WORK}/part-${i} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "shard ${i}: ${err}")
  endif()
endforeach()
set(merged_dir ${WORK}/merged)
file(MAKE_DIRECTORY ${merged_dir})
execute_process(COMMAND ${EXE} merge --out out ${WORK}/part-2 ${WORK}/part-0 ${WORK}/part-1
                WORKING_DIRECTORY ${merged_dir} OUTPUT_VARIABLE merged RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT merged STREQUAL single OR NOT single MATCHES "--min-distance 0.001 --tmax 0.75")
  message(FATAL_ERROR "merged shards differ from one run (${rc} ${err}):\n${merged}\n---\n${single}")
endif()
file(GLOB files RELATIVE ${one}/out ${one}/out/*)
foreach(f IN LISTS files)
  file(READ ${one}/out/${f} a)
  file(READ ${merged_dir}/out/${f} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "merged ${f} differs from one run's")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
