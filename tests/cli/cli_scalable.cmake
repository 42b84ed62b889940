# CLI tests on the Scalable CCD dataset's cloth-funnel sample (CMakeLists.txt, one CTest test
# per case; skipped, with the reason, when the sample is absent):
#   cmake -DEXE=<exactccd> -DSAMPLE=<scalable-ccd-sample> -DWORK=<scratch dir> -DCASE=<case>
#         -P cli_scalable.cmake
# scalable_scene: `exactccd scene` on the two binary PLY frames reports the dataset's 27
#   vertex-face and 107 edge-edge colliding pairs (the pairs themselves: test_scalable_sample).
# scalable_check: `exactccd check` on the 6-column query files, truth found by name and by
#   --truth, gives 0 FP and 0 FN with the filtered and the exact method; without a truth file
#   it is an error unless --answers.
cmake_minimum_required(VERSION 3.21)
foreach(var EXE SAMPLE WORK CASE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "cli_scalable.cmake: -D${var}=... is required")
  endif()
endforeach()
set(scene ${SAMPLE}/cloth-funnel)
if(NOT IS_DIRECTORY ${scene})
  message("SKIPPED: the Scalable CCD sample is absent: ${scene} (set EXACTCCD_SCALABLE_SAMPLE_DIR)")
  return()
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

macro(run)
  execute_process(COMMAND ${EXE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endmacro()

if(CASE STREQUAL "scalable_scene")
  run(scene ${scene}/frames/227.ply ${scene}/frames/228.ply)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "vertices +9450\n" OR NOT out MATCHES "triangles +18484\n"
     OR NOT out MATCHES "colliding vf pairs +27\n" OR NOT out MATCHES "colliding ee pairs +107\n")
    message(FATAL_ERROR "scene 227.ply 228.ply: exit ${rc}\n${out}\n${err}")
  endif()
elseif(CASE STREQUAL "scalable_check")
  set(vf ${scene}/queries/227vf.csv)
  set(ee ${scene}/queries/227ee.csv)
  foreach(method filtered exact)
    run(check --method ${method} ${vf} ${ee})
    # file, kind, queries, positives, FP, FN
    if(NOT rc EQUAL 0 OR NOT out MATCHES "227vf.csv +vf +92 +27 +0 +0 " OR NOT out MATCHES "227ee.csv +ee +263 +107 +0 +0 "
       OR NOT out MATCHES "total +355 +134 +0 +0 ")
      message(FATAL_ERROR "check --method ${method} on the sample: exit ${rc}\n${out}\n${err}")
    endif()
  endforeach()
  # Elsewhere, without the truth beside them: --truth, --answers, or an error.
  file(COPY_FILE ${vf} ${WORK}/227vf.csv)
  run(check ${WORK}/227vf.csv)
  if(NOT rc EQUAL 2 OR NOT out STREQUAL "" OR NOT err MATCHES "227vf.csv has no truth column .*--truth FILE.json")
    message(FATAL_ERROR "check without truth file: exit ${rc}\n${out}\n${err}")
  endif()
  run(check --json --truth ${scene}/mma_bool/227vf_mma_bool.json ${WORK}/227vf.csv)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\"kind\": \"vf\".*\"queries\": 92, \"positives\": 27, \"fp\": 0, \"fn\": 0")
    message(FATAL_ERROR "check --truth: exit ${rc}\n${out}\n${err}")
  endif()
  run(check --answers ${WORK}/227vf.csv)
  string(REGEX MATCHALL "1\n" ones "${out}")
  list(LENGTH ones positives)
  if(NOT rc EQUAL 0 OR NOT positives EQUAL 27)
    message(FATAL_ERROR "check --answers without truth: exit ${rc}, ${positives} positives\n${out}\n${err}")
  endif()
  # A truth file of the wrong length, or not booleans: errors naming it.
  file(WRITE ${WORK}/short.json "[true,\n false]\n")
  run(check --truth ${WORK}/short.json ${WORK}/227vf.csv)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "short.json: 2 truth values but .*227vf.csv has 92 queries")
    message(FATAL_ERROR "short truth: exit ${rc}\n${out}\n${err}")
  endif()
  file(WRITE ${WORK}/bad.json "[true,\n 1]\n")
  run(check --truth ${WORK}/bad.json ${WORK}/227vf.csv)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "bad.json:2: value 2 is not true or false")
    message(FATAL_ERROR "bad truth: exit ${rc}\n${out}\n${err}")
  endif()
  # --truth for a file with a truth column, and with several files.
  run(check --truth ${scene}/mma_bool/227vf_mma_bool.json ${vf} ${ee})
  if(NOT rc EQUAL 2 OR NOT err MATCHES "--truth FILE.json goes with one FILE.csv")
    message(FATAL_ERROR "--truth with two files: exit ${rc}\n${out}\n${err}")
  endif()
else()
  message(FATAL_ERROR "cli_scalable.cmake: unknown CASE '${CASE}'")
endif()
file(REMOVE_RECURSE ${WORK})
