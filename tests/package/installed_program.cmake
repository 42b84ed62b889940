# CTest script (test package.installed_program): the installed program needs no checkout.
# `cmake --install` into a temporary prefix outside the source and build trees, then the prefix
# moved (relocated: no path of the install step is valid any more), then:
#  1. no installed file holds the source tree's, the build tree's, the shared sample's or the
#     install step's path (the program with its debug information stripped, when OBJCOPY is given).
#     Not enough for the program: GCC may store a string literal in pieces (a compiled-in
#     "<source>/data" was not found whole in it), hence 2;
#  2. the installed program copied alone into an empty folder, with the checkout in reach, must
#     fail to find its data, naming where it looked, --data-dir and EXACTCCD_DATA_DIR (a program
#     that falls back to the checkout, or prefers it, finds it there and fails this test: both
#     checked); the option and the environment variables are taken, in that precedence;
#  3. with the source tree, the build tree and the shared sample hidden (tmpfs mounts in a private
#     mount namespace: `unshare --mount --map-root-user`, else `unshare --mount` as root; where
#     neither is allowed, e.g. in a container without the capability, the trees stay visible,
#     the output says so, and 1 and 2 are what keep the checkout out of the run): `exactccd bench`
#     and `exactccd bench --motion rigid` without files (their bundled data, found beside the
#     program), `exactccd check` on the installed data files, and the find_package(exactccd)
#     consumer (tests/package/consumer) built against the prefix and run.
# Variables: BUILD_DIR, SOURCE_DIR (the project's), CONSUMER_DIR, SAMPLE_DIR (the CMake cache
# variable EXACTCCD_SAMPLE_QUERIES_DIR), OBJCOPY (optional). The script runs itself again:
# STAGE=checks for the steps (so that the temporary folder is removed whatever they find), and
# STAGE=hidden for step 3, from its copy in the temporary folder.
cmake_minimum_required(VERSION 3.20)
unset(ENV{EXACTCCD_DATA_DIR})
unset(ENV{EXACTCCD_SAMPLE_QUERIES_DIR})

# Runs the program with the arguments given; out, err and rc in the caller's scope.
function(run_program program)
  execute_process(COMMAND ${program} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
  set(rc "${code}" PARENT_SCOPE)
  set(out "${stdout}" PARENT_SCOPE)
  set(err "${stderr}" PARENT_SCOPE)
endfunction()

# Fails unless the last run exited 0 and its stdout matches every regular expression given.
function(expect_ran what)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: exit ${rc}\n${out}\n${err}")
  endif()
  foreach(pattern IN LISTS ARGN)
    if(NOT out MATCHES "${pattern}")
      message(FATAL_ERROR "${what}: no match for '${pattern}' in:\n${out}\n${err}")
    endif()
  endforeach()
endfunction()

# Fails unless the last run exited 2 and its stderr holds every text given (not patterns).
function(expect_usage_error what)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "${what}: exit ${rc}, expected 2 (the bundled data not found)\n${out}\n${err}")
  endif()
  foreach(text IN LISTS ARGN)
    string(FIND "${err}" "${text}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${what}: stderr does not say '${text}':\n${err}")
    endif()
  endforeach()
endfunction()

# Step 3, run inside the namespace (or not, see above): the trees must be hidden when MODE says so.
function(run_hidden_checks)
  if(MODE STREQUAL "hidden")
    string(REPLACE "|" ";" hidden "${HIDDEN}")
    foreach(dir IN LISTS hidden)
      file(GLOB visible ${dir}/*)
      if(visible)
        message(FATAL_ERROR "${dir} is not hidden")
      endif()
    endforeach()
  endif()
  set(exe ${PREFIX}/bin/exactccd)
  set(data ${PREFIX}/share/exactccd/data)
  run_program(${exe} bench --repetitions 1 --methods filtered)
  set(sim_rows)
  foreach(scene IN ITEMS cloth fold pile strip)
    list(APPEND sim_rows "\nsim-${scene}-vertex-face +vf filtered" "\nsim-${scene}-edge-edge +ee filtered")
  endforeach()
  expect_ran("exactccd bench (its bundled data)" ${sim_rows})
  if(out MATCHES "unit-tests")
    message(FATAL_ERROR "the installed exactccd bench read the shared sample, which is not installed:\n${out}")
  endif()
  run_program(${exe} bench --motion rigid --repetitions 1 --methods filtered)
  expect_ran("exactccd bench --motion rigid (its bundled data)" "\nrigid-families-vertex-face +vf "
             "\nrigid-sim-rings-edge-edge +ee ")
  file(GLOB linear_files ${data}/sim/*.csv ${data}/catalogue/*.csv ${data}/families/*.csv ${data}/kinds/*.csv)
  run_program(${exe} check ${linear_files})
  expect_ran("exactccd check on the installed data files" "\ntotal +5728 +[0-9]+ +0 +0 ")
  file(GLOB rigid_files ${data}/rigid/*-vertex-face.csv)
  run_program(${exe} check --motion rigid --kind vf ${rigid_files})
  expect_ran("exactccd check --motion rigid on the installed data files" "\ntotal +[0-9]+ +[0-9]+ +0 +0 ")
  message(STATUS "the installed exactccd: bench and bench --motion rigid on their bundled data, check on the "
                 "installed files: ran")
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK}/consumer -B ${WORK}/consumer-build
                          -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect_ran("configuring the find_package(exactccd) consumer against the prefix")
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/consumer-build RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  expect_ran("building the consumer")
  run_program(${WORK}/consumer-build/consumer)
  expect_ran("the consumer")
  message(STATUS "the find_package(exactccd) consumer: built against the prefix and ran")
endfunction()

# Step 1: no installed file names a tree of this machine or the install step's prefix.
function(check_no_machine_paths)
  set(scan ${WORK}/scan)
  file(MAKE_DIRECTORY ${scan})
  file(GLOB_RECURSE files ${PREFIX}/*)
  list(REMOVE_ITEM files ${PREFIX}/bin/exactccd)
  if(OBJCOPY)  # the debug information (a RelWithDebInfo build's) names the trees; the program does not read it
    execute_process(COMMAND ${OBJCOPY} --strip-debug ${PREFIX}/bin/exactccd ${scan}/exactccd RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${OBJCOPY} --strip-debug failed (${rc})")
    endif()
    list(APPEND files ${scan}/exactccd)
  else()
    list(APPEND files ${PREFIX}/bin/exactccd)
  endif()
  set(paths ${TREES} ${SOURCE_DIR} ${BUILD_DIR} ${SAMPLE_DIR} ${WORK}/installed-here)
  list(REMOVE_DUPLICATES paths)
  set(patterns)
  foreach(path IN LISTS paths)
    list(APPEND patterns -e ${path})
  endforeach()
  execute_process(COMMAND grep -c -F ${patterns} ${files} RESULT_VARIABLE rc OUTPUT_VARIABLE counts)
  if(rc EQUAL 0)
    string(REGEX REPLACE "[^\n]*:0\n" "" counts "${counts}")
    message(FATAL_ERROR "installed files name a path of this machine (${SOURCE_DIR}, ${BUILD_DIR}, ${SAMPLE_DIR} or "
                        "the install step's prefix):\n${counts}")
  elseif(NOT rc EQUAL 1)
    message(FATAL_ERROR "grep failed (${rc})")
  endif()
  list(LENGTH files n)
  message(STATUS "no path of this machine in the ${n} installed files")
endfunction()

# Writes DIR/NAME holding the first query (8 rows) of the installed sim-cloth-vertex-face.csv.
function(write_one_query dir name)
  file(STRINGS ${PREFIX}/share/exactccd/data/sim/sim-cloth-vertex-face.csv rows LIMIT_COUNT 8)
  list(JOIN rows "\n" text)
  file(WRITE ${dir}/${name} "${text}\n")
endfunction()

# Step 2: the installed program alone, the checkout in reach: its data not found, then named.
function(check_lonely_program)
  set(lonely ${WORK}/lonely/bin/exactccd)
  file(COPY ${PREFIX}/bin/exactccd DESTINATION ${WORK}/lonely/bin)
  foreach(motion IN ITEMS linear rigid)
    run_program(${lonely} bench --motion ${motion} --repetitions 1 --methods filtered)
    expect_usage_error("the installed exactccd alone: bench --motion ${motion}" "the bundled data was not found"
                       "${WORK}/lonely/share/exactccd/data" "--data-dir DIR" "EXACTCCD_DATA_DIR")
  endforeach()
  write_one_query(${WORK}/option-data/sim option-vertex-face.csv)
  write_one_query(${WORK}/variable-data/sim variable-vertex-face.csv)
  write_one_query(${WORK}/sample/unit-tests/vertex-face data_0_0.csv)
  set(bench bench --repetitions 1 --methods filtered)
  run_program(${CMAKE_COMMAND} -E env EXACTCCD_DATA_DIR=${WORK}/variable-data ${lonely} ${bench})
  expect_ran("EXACTCCD_DATA_DIR" "\nvariable-vertex-face +vf ")
  run_program(${CMAKE_COMMAND} -E env EXACTCCD_DATA_DIR=${WORK}/variable-data ${lonely} ${bench}
              --data-dir ${WORK}/option-data)
  expect_ran("--data-dir over EXACTCCD_DATA_DIR" "\noption-vertex-face +vf ")
  if(out MATCHES "variable-vertex-face")
    message(FATAL_ERROR "--data-dir and EXACTCCD_DATA_DIR: both read\n${out}")
  endif()
  run_program(${CMAKE_COMMAND} -E env EXACTCCD_DATA_DIR=${WORK}/absent ${lonely} ${bench})
  expect_usage_error("EXACTCCD_DATA_DIR naming no folder" "EXACTCCD_DATA_DIR '${WORK}/absent' is not a folder")
  run_program(${CMAKE_COMMAND} -E env EXACTCCD_SAMPLE_QUERIES_DIR=${WORK}/sample ${lonely} ${bench}
              --data-dir ${WORK}/option-data)
  expect_ran("EXACTCCD_SAMPLE_QUERIES_DIR" "\nunit-tests/vertex-face/data_0_0 +vf .*\noption-vertex-face +vf ")
  message(STATUS "the installed program alone: its data not found, though the checkout is in reach; "
                 "--data-dir, EXACTCCD_DATA_DIR and EXACTCCD_SAMPLE_QUERIES_DIR taken, in that precedence")
endfunction()

# Step 3: this script again (STAGE=hidden) in a private mount namespace with the trees hidden,
# where unshare is allowed; else without, saying so.
function(run_with_trees_hidden)
  configure_file(${CMAKE_CURRENT_LIST_FILE} ${WORK}/installed_program.cmake COPYONLY)
  file(COPY ${CONSUMER_DIR}/ DESTINATION ${WORK}/consumer)
  set(hidden ${TREES})
  list(SORT hidden ORDER DESCENDING)  # a folder inside another is mounted over first
  list(LENGTH hidden n)
  string(REPLACE ";" "|" hidden_list "${hidden}")  # one argument of the command lines below
  set(stage -DSTAGE=hidden -DPREFIX=${PREFIX} -DWORK=${WORK} -DHIDDEN=${hidden_list} -P ${WORK}/installed_program.cmake)
  # sh -c SCRIPT sh CMAKE N DIR... ARGS: mounts an empty tmpfs over each DIR, then runs CMAKE ARGS.
  set(hide [=[cmake=$1; n=$2; shift 2; while [ "$n" -gt 0 ]; do mount -t tmpfs exactccd-hidden "$1" || exit 97; shift; n=$((n - 1)); done; exec "$cmake" "$@"]=])
  file(MAKE_DIRECTORY ${WORK}/probe)
  foreach(flags IN ITEMS "--mount;--map-root-user" "--mount")
    execute_process(COMMAND unshare ${flags} sh -c "mount -t tmpfs exactccd-probe \"$0\"" ${WORK}/probe
                    RESULT_VARIABLE rc OUTPUT_VARIABLE probe ERROR_VARIABLE probe)
    if(rc EQUAL 0)
      string(REPLACE ";" " " shown "${flags}")
      list(JOIN hidden ", " shown_hidden)
      message(STATUS "hiding ${shown_hidden} (tmpfs mounts in a private mount namespace: unshare ${shown})")
      execute_process(COMMAND unshare ${flags} sh -c "${hide}" sh ${CMAKE_COMMAND} ${n} ${hidden} -DMODE=hidden ${stage}
                      RESULT_VARIABLE rc)
      if(NOT rc EQUAL 0)
        message(FATAL_ERROR "the installed program with the trees hidden: failed (${rc})")
      endif()
      return()
    endif()
  endforeach()
  string(STRIP "${probe}" probe)
  if(NOT probe)
    set(probe "${rc}")
  endif()
  message(STATUS "unshare is not allowed here (${probe}): the trees stay visible; the relocated prefix, the path "
                 "check and the program alone (above) are what keep the checkout out of this run")
  execute_process(COMMAND ${CMAKE_COMMAND} -DMODE=visible ${stage} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the installed program: failed (${rc})")
  endif()
endfunction()

if(STAGE STREQUAL "hidden")
  run_hidden_checks()
  return()
endif()
if(STAGE STREQUAL "checks")
  execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK}/installed-here
                  RESULT_VARIABLE rc OUTPUT_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install failed (${rc})")
  endif()
  set(PREFIX ${WORK}/prefix)
  file(RENAME ${WORK}/installed-here ${PREFIX})
  message(STATUS "installed into ${WORK}/installed-here, then moved to ${PREFIX}")
  foreach(file IN ITEMS bin/exactccd share/exactccd/data/sim/README.md share/exactccd/data/rigid/README.md)
    if(NOT EXISTS ${PREFIX}/${file})
      message(FATAL_ERROR "cmake --install did not install ${file}")
    endif()
  endforeach()
  check_no_machine_paths()
  check_lonely_program()
  run_with_trees_hidden()
  return()
endif()

# --- the temporary prefix, outside both trees ------------------------------------------------
if(DEFINED ENV{TMPDIR} AND IS_DIRECTORY "$ENV{TMPDIR}")
  set(tmp "$ENV{TMPDIR}")
else()
  set(tmp /tmp)
endif()
string(RANDOM LENGTH 10 suffix)
file(REAL_PATH ${tmp}/exactccd-installed-${suffix} work)
file(REAL_PATH ${SOURCE_DIR} source_real)
file(REAL_PATH ${BUILD_DIR} build_real)
set(trees ${source_real} ${build_real})
if(EXISTS ${SAMPLE_DIR})
  file(REAL_PATH ${SAMPLE_DIR} sample_real)
  list(APPEND trees ${sample_real})
endif()
foreach(tree IN LISTS trees)
  string(FIND "${work}/" "${tree}/" at)
  if(at EQUAL 0)
    message(FATAL_ERROR "the temporary folder ${work} is inside ${tree}: set TMPDIR to a folder outside it")
  endif()
endforeach()
file(MAKE_DIRECTORY ${work})

# Everything else in a script of its own, so that the temporary folder is removed whatever it finds.
execute_process(COMMAND ${CMAKE_COMMAND} -DSTAGE=checks -DWORK=${work} -DBUILD_DIR=${BUILD_DIR}
                        -DSOURCE_DIR=${SOURCE_DIR} -DCONSUMER_DIR=${CONSUMER_DIR} -DSAMPLE_DIR=${SAMPLE_DIR}
                        "-DTREES=${trees}" -DOBJCOPY=${OBJCOPY} -P ${CMAKE_CURRENT_LIST_FILE}
                RESULT_VARIABLE rc)
file(REMOVE_RECURSE ${work})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "package.installed_program failed (${rc}): see above")
endif()
