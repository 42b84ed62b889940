# The bundled data/families CSVs are what `exactccd generate families` writes now, with the
# command line of data/families/README.md (no stale data; generate itself checks every truth
# the construction knows against Method::exact and exits 1 on a disagreement). Run with
# -DEXE=<exactccd> -DSOURCE_DIR=<repository> -DWORK_DIR=<scratch>. The placements draw from
# std::uniform_int_distribution and std::shuffle, whose algorithms the C++ standard leaves to
# the library: the files are reproduced with libstdc++ (where they were made); CMakeLists.txt
# registers this test on Linux only.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${EXE} generate families --out ${WORK_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "generate families: exit ${rc}: ${err}")
endif()
if(NOT out MATCHES "by construction, checked against Method::exact")
  message(FATAL_ERROR "generate families does not report where its truth comes from:\n${out}")
endif()
foreach(kind vertex-face edge-edge)
  file(READ ${WORK_DIR}/families-${kind}.csv fresh)
  file(READ ${SOURCE_DIR}/data/families/families-${kind}.csv committed)
  if(NOT fresh STREQUAL committed)
    message(FATAL_ERROR "data/families/families-${kind}.csv is stale: regenerate it with the "
                        "command of data/families/README.md")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
