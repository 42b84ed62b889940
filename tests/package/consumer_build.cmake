# CTest script: cmake --install into WORK_DIR/prefix, then configure, build and run the
# consumer project in SOURCE_DIR against it. With NM (the toolchain's nm), also checks that the
# installed library defines none of the tools library's code: no symbol of the non-robust
# baselines (exactccd::baseline::) or of tools::Method's dispatch (exactccd::tools::).
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
# The headers installed besides the library's own: the version macros (generated) and the
# header-only IPC Toolkit narrow phase.
foreach(header IN ITEMS exactccd/version.h exactccd/ipc_toolkit.hpp exactccd/exactccd.h)
  if(NOT EXISTS ${WORK_DIR}/prefix/include/${header})
    message(FATAL_ERROR "cmake --install did not install include/${header}")
  endif()
endforeach()
if(NM)
  file(GLOB_RECURSE libraries ${WORK_DIR}/prefix/*/libexactccd.a ${WORK_DIR}/prefix/*/libexactccd.so)
  if(NOT libraries)
    message(FATAL_ERROR "no installed libexactccd under ${WORK_DIR}/prefix")
  endif()
  foreach(library IN LISTS libraries)
    execute_process(COMMAND ${NM} -C --defined-only ${library} RESULT_VARIABLE rc
                    OUTPUT_VARIABLE symbols ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${NM} ${library} failed (${rc}): ${err}")
    endif()
    foreach(namespace IN ITEMS "exactccd::baseline::" "exactccd::tools::")
      string(FIND "${symbols}" "${namespace}" at)
      if(NOT at EQUAL -1)
        string(SUBSTRING "${symbols}" ${at} 200 excerpt)
        message(FATAL_ERROR "the installed ${library} defines ${namespace} symbols (tools library code): ${excerpt}")
      endif()
    endforeach()
  endforeach()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer returned ${rc}")
endif()
