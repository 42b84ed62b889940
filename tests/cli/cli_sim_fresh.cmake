# The bundled data/sim CSVs are what `exactccd generate sim` writes now, with the command lines
# of data/sim/README.md (no stale data). Run with -DEXE=<exactccd> -DSOURCE_DIR=<repository>
# -DWORK_DIR=<scratch>. The scenes use the C library's sin and cos, so the files are
# reproduced bit for bit where they were made (glibc, x86-64); CMakeLists.txt registers this
# test only on Linux x86-64.
file(REMOVE_RECURSE ${WORK_DIR})
# scene resolution, as in data/sim/README.md
set(scenes "cloth 16" "strip 16" "fold 8" "pile 4")
foreach(entry IN LISTS scenes)
  separate_arguments(entry)
  list(GET entry 0 scene)
  list(GET entry 1 resolution)
  execute_process(COMMAND ${EXE} generate sim --scene ${scene} --resolution ${resolution} --seed 1
                          --max-queries 400 --truth exact --out ${WORK_DIR}
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generate sim --scene ${scene}: exit ${rc}: ${err}")
  endif()
  foreach(kind vertex-face edge-edge)
    file(READ ${WORK_DIR}/sim-${scene}-${kind}.csv fresh)
    file(READ ${SOURCE_DIR}/data/sim/sim-${scene}-${kind}.csv committed)
    if(NOT fresh STREQUAL committed)
      message(FATAL_ERROR "data/sim/sim-${scene}-${kind}.csv is stale: regenerate it with the "
                          "commands of data/sim/README.md")
    endif()
  endforeach()
endforeach()
