# CLI contract tests of unreadable input, bounded resources and command-line numbers (docs/formats.md,
# "Input files"), one CTest test per case (CMakeLists.txt):
#   cmake -DEXE=<exactccd> -DDATA=<tests/data> -DPLUGIN=<naive_plugin.so> -DWORK=<scratch dir>
#         -DCASE=<case> -P cli_input.cmake
# Bad input is never answered: exit code 2, a message naming the file (and line), nothing on
# stdout, no file written half-way. Scratch files go to WORK (in the build tree).
cmake_minimum_required(VERSION 3.21)  # file(COPY_FILE); empty list elements kept (CMP0007)
foreach(var EXE DATA PLUGIN WORK CASE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "cli_input.cmake: -D${var}=... is required")
  endif()
endforeach()
set(small ${DATA}/small-vertex-face.csv)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# Runs the program; sets rc, out and err in the caller.
macro(run)
  execute_process(COMMAND ${EXE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endmacro()

# Fails unless the last run exited with 2, printed nothing on stdout and `pattern` on stderr.
macro(expect_input_error what pattern)
  if(NOT rc EQUAL 2 OR NOT out STREQUAL "" OR NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: exit ${rc}, stdout '${out}', stderr '${err}' (expected exit 2 and '${pattern}')")
  endif()
endmacro()

# Fails unless the last run exited with 0 and printed `expected` on stdout.
macro(expect_output what expected)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: exit ${rc}, stdout '${out}' (expected '${expected}'), stderr '${err}'")
  endif()
endmacro()

# Whether the tests run as root, who may write anywhere (permission cases are then skipped).
execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE id_rc)
if(id_rc EQUAL 0 AND uid STREQUAL "0")
  set(as_root TRUE)
else()
  set(as_root FALSE)
endif()

if(CASE STREQUAL "option_values")
  # Every malformed or out-of-range number, for every subcommand that takes it: a usage error
  # naming the option and the value (exit 2), never an internal error, a wrapped value or an
  # accepted prefix.
  # Each case: subcommand|option|values (comma-separated)|other arguments ('^'-separated).
  set(plugin_args "${PLUGIN}^--kind^vf^--out^${WORK}/fuzz")
  set(cases
    "check|--threads|abc,-1,2x,1e9,100000,1025,4294967297|${small}"
    "check|--shard|3/2,2/2,-1/2,1/2x,1,abc,0/0|${small}"
    "bench|--repetitions|abc,-1,0,2x,1e9,100001|${small}"
    "stability|--threads|abc,-1,2x,1e9,100000|--instances^1"
    "stability|--shard|3/2,0/0,x/2|--instances^1"
    "stability|--instances|-3,0,abc,1e9,2x|"
    "stability|--k-min|-1,abc,1.5,1075|"
    "stability|--k-max|-1,abc,2x|"
    "stability|--seed|-1,abc,1e9,18446744073709551616|"
    "scene|--threads|abc,-1,2x,1e9,100000|a.obj^b.obj"
    "generate|--resolution|abc,1,-24,1e9,24x,1001|catalogue^--out^${WORK}/gen"
    "generate|--seed|-1,abc,1e9|catalogue^--out^${WORK}/gen"
    "generate|--max-queries|-1,abc,1e9,10x|catalogue^--out^${WORK}/gen"
    "generate|--instances|-3,0,abc|families^--out^${WORK}/gen"
    "generate|--k-step|0,-4,61,abc|families^--out^${WORK}/gen"
    "fuzz-against|--queries|-1,0,abc,2x,1e9,10000001|${plugin_args}"
    "fuzz-against|--seed|-1,abc,1e9|${plugin_args}"
    "fuzz-against|--threads|-1,2x,1e9,100000|${plugin_args}")
  foreach(c IN LISTS cases)
    string(REPLACE "|" ";" parts "${c}")
    list(GET parts 0 sub)
    list(GET parts 1 option)
    list(GET parts 2 values)
    list(GET parts 3 rest)
    string(REPLACE "," ";" values "${values}")
    string(REPLACE "^" ";" rest "${rest}")
    foreach(value IN LISTS values)
      run(${sub} ${option} ${value} ${rest})
      string(REPLACE "+" "[+]" option_pattern "${option}")
      expect_input_error("${sub} ${option} ${value}" "exactccd: ${sub}: ${option_pattern} needs [^\n]*, not '${value}'\n")
    endforeach()
  endforeach()
  # The same values in the options that take a kind, a method or a list: usage errors too.
  run(check --method exact2 ${small})
  expect_input_error("check --method exact2" "--method needs one of")
  run(bench --methods naive,,exact ${small})
  expect_input_error("bench --methods naive,,exact" "--methods needs a comma-separated list")
  run(compare --kind xx --answers ${WORK}/a.txt ${small})
  expect_input_error("compare --kind xx" "--kind needs one of vf, ee")
  run(generate sim --truth naive --out ${WORK}/gen --scene cloth)
  expect_input_error("generate --truth naive" "--truth needs one of exact, filtered")
  run(check --threads)
  expect_input_error("check --threads without a value" "option --threads needs a value")
  # Values at the ends of the documented ranges are accepted.
  run(check --threads 1024 --answers ${small})
  expect_output("check --threads 1024" "1\n0\n")
  # 0: every hardware thread, as in the library, the C API and the Python module.
  run(check --threads 0 --answers ${small})
  expect_output("check --threads 0" "1\n0\n")
  run(check --shard 1/2 --answers ${small})
  expect_output("check --shard 1/2" "0\n")
  run(stability --families ee_parallel --k-min 1074 --k-max 1074 --instances 1 --methods filtered
                --seed 18446744073709551615)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\nee_parallel,ee,filtered,1074,1,0,0,")
    message(FATAL_ERROR "stability at k = 1074: exit ${rc}\n${out}\n${err}")
  endif()
  # The help states the ranges the parser applies (both come from one table).
  run(check --help)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "--threads N[^\n]*\n?[^\n]*\\(N in 0..1024; default 1\\)")
    message(FATAL_ERROR "check --help does not state the --threads range:\n${out}")
  endif()
  foreach(sub scene fuzz-against)
    run(${sub} --help)
    if(NOT rc EQUAL 0 OR NOT out MATCHES "--threads N[^\n]*\n?[^\n]*\\(N in 0..1024")
      message(FATAL_ERROR "${sub} --help does not state the --threads range:\n${out}")
    endif()
  endforeach()

elseif(CASE STREQUAL "check_threads")
  # --threads beyond the documented 0..1024 is a usage error; 1024 is allowed, and when the
  # system refuses threads the run degrades to fewer threads with the same answers instead of
  # aborting.
  run(check --threads 100000 --answers ${small})
  expect_input_error("--threads 100000" "--threads needs an integer in 0..1024, not '100000'")
  file(READ ${small} one)
  string(REPEAT "${one}" 600 many)
  file(WRITE ${WORK}/many-vertex-face.csv "${many}")
  string(REPEAT "1\n0\n" 600 answers)
  run(check --threads 1024 --answers ${WORK}/many-vertex-face.csv)
  expect_output("--threads 1024" "${answers}")
  # The system refusing threads: a limit on the user's processes (threads count as processes)
  # that leaves room for the program's main thread and no other (oneTBB cannot recover from a
  # worker it fails to start: the command line must not ask for one). It applies to the user's
  # processes: as root (who ignores it) the run switches to the user nobody, limited to 1;
  # otherwise the limit is the user's processes counted now, ps included (ps is gone when the
  # program starts: its place is the program's). CTest runs this test alone (RUN_SERIAL): a
  # test running beside it would take the user's processes.
  find_program(PRLIMIT prlimit)
  find_program(SETPRIV setpriv)
  find_program(PS ps)
  set(limited_run "")
  if(PRLIMIT AND as_root AND SETPRIV)
    set(limited_run ${SETPRIV} --reuid=65534 --regid=65534 --clear-groups ${PRLIMIT} --nproc=1)
  elseif(PRLIMIT AND NOT as_root AND PS)
    execute_process(COMMAND ${PS} -L -u ${uid} --no-headers OUTPUT_VARIABLE mine)
    string(REGEX MATCHALL "\n" lines "\n${mine}")
    list(LENGTH lines count)
    set(limited_run ${PRLIMIT} --nproc=${count})
  endif()
  # Under AddressSanitizer, LeakSanitizer checks at exit from a thread of its own, which the
  # limit refuses ("LeakSanitizer has encountered a fatal error"): these runs go without the
  # leak check (the same commands without the limit keep it).
  if(limited_run)
    set(limited_run ${CMAKE_COMMAND} -E env "ASAN_OPTIONS=$ENV{ASAN_OPTIONS}:detect_leaks=0" ${limited_run})
  endif()
  if(NOT limited_run)
    message(STATUS "check_threads: skipped the runs with a process limit: needs prlimit (util-linux), and "
                   "setpriv as root or ps otherwise")
  else()
    file(CHMOD ${WORK} DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
                                             WORLD_READ WORLD_EXECUTE)  # nobody reads the input
    execute_process(COMMAND ${limited_run} ${EXE} check --threads 1024 --answers ${WORK}/many-vertex-face.csv
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    expect_output("check --threads 1024 with no thread to spare" "${answers}")
    # (k <= 60: wider instances may need exact root isolation on a helper thread with a larger
    # stack, which the limit would refuse too.)
    set(sweep --families ee_parallel,vf_vertex_through_edge --k-min 0 --k-max 60 --instances 1 --methods naive)
    execute_process(COMMAND ${limited_run} ${EXE} stability --threads 1024 ${sweep}
                    RESULT_VARIABLE limited_rc OUTPUT_VARIABLE limited ERROR_VARIABLE err)
    run(stability --threads 1 ${sweep})
    if(NOT limited_rc EQUAL 0 OR NOT rc EQUAL 0 OR NOT limited STREQUAL out)
      message(FATAL_ERROR "stability --threads 1024 with no thread to spare: exit ${limited_rc} "
                          "(unlimited, one thread: ${rc}), same output: no\n${err}")
    endif()
    # The scene's narrow phase (lib/scene/parallel.hpp): the bundled cloth step, thousands of
    # candidate pairs in chunks for many threads.
    set(cloth ${DATA}/../../data/scenes/cloth)
    run(scene --threads 1 --json ${cloth}/T0.obj ${cloth}/T1.obj)
    set(one_thread "${out}")
    execute_process(COMMAND ${limited_run} ${EXE} scene --threads 1024 --json ${cloth}/T0.obj ${cloth}/T1.obj
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0 OR NOT out STREQUAL one_thread OR NOT one_thread MATCHES "\"candidates\": [1-9]")
      message(FATAL_ERROR "scene --threads 1024 with no thread to spare: exit ${rc}\n${out}\n${err}")
    endif()
  endif()

elseif(CASE STREQUAL "check_input_files")
  # Empty files, directories and missing files are errors naming the file; never an empty answer.
  file(WRITE ${WORK}/empty-vertex-face.csv "")
  run(check ${WORK}/empty-vertex-face.csv)
  expect_input_error("empty CSV" "empty-vertex-face.csv: no queries")
  file(WRITE ${WORK}/blank-vertex-face.csv "\n\r\n  \n")
  run(check --answers ${small} ${WORK}/blank-vertex-face.csv)
  expect_input_error("blank CSV after a good one" "blank-vertex-face.csv: no queries")
  file(MAKE_DIRECTORY ${WORK}/dir-vertex-face.csv)
  run(check ${WORK}/dir-vertex-face.csv)
  expect_input_error("directory" "dir-vertex-face.csv: is a directory")
  run(check ${WORK}/no-such-vertex-face.csv)
  expect_input_error("missing file" "no-such-vertex-face.csv: no such file")
  run(compare --answers ${WORK}/no-such.txt ${small})
  expect_input_error("missing answers file" "no-such.txt: no such file")
  # A rigid query file given without --motion rigid: the error names the file, the line and the command.
  file(WRITE ${WORK}/rigid-vertex-face.csv "# rigid\n0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,1,1,0,0,0,1,0,0,0,1,0\n")
  run(check ${WORK}/rigid-vertex-face.csv)
  expect_input_error("rigid file without --motion rigid" "rigid-vertex-face.csv:1: a '#' comment line[^\n]*--motion rigid")
  if(as_root)
    message(STATUS "check_input_files: skipped the unreadable-file case: running as root, who reads every file")
  else()
    file(COPY_FILE ${small} ${WORK}/locked-vertex-face.csv)
    file(CHMOD ${WORK}/locked-vertex-face.csv PERMISSIONS OWNER_WRITE)
    run(check ${WORK}/locked-vertex-face.csv)
    expect_input_error("unreadable file" "locked-vertex-face.csv: cannot open: Permission denied")
  endif()
  # A numerator of 10^5 digits (it ran for more than 15 minutes): refused at once, with the line.
  # Rows of small-vertex-face.csv's first query, its third row replaced.
  file(STRINGS ${small} rows)
  list(SUBLIST rows 0 8 rows)
  string(REPEAT "9" 100000 huge)
  foreach(variant "num|${huge},1,0,1,0,1,1" "den|1,000${huge},0,1,0,1,1")
    string(REPLACE "|" ";" v "${variant}")
    list(GET v 0 name)
    list(GET v 1 row)
    set(query ${rows})
    list(REMOVE_AT query 2)
    list(INSERT query 2 "${row}")
    list(JOIN query "\n" text)
    file(WRITE ${WORK}/huge-${name}-vertex-face.csv "${text}\n")
  endforeach()
  string(TIMESTAMP start "%s")
  run(check --method exact ${WORK}/huge-num-vertex-face.csv)
  string(TIMESTAMP end "%s")
  expect_input_error("10^5-digit numerator" "huge-num-vertex-face.csv:3: field 1 has 100000 digits, more than the limit of 4096 bits")
  math(EXPR seconds "${end} - ${start}")
  if(seconds GREATER 10)
    message(FATAL_ERROR "the oversized numerator took ${seconds} s to refuse")
  endif()
  # The same in a denominator, whose leading zeros do not count.
  run(check ${WORK}/huge-den-vertex-face.csv)
  expect_input_error("10^5-digit denominator" "huge-den-vertex-face.csv:3: field 2 has 100000 digits")
  # A UTF-8 byte order mark loses no row: the same answers as without it.
  string(ASCII 239 187 191 bom)
  file(READ ${small} body)
  file(WRITE ${WORK}/bom-vertex-face.csv "${bom}${body}")
  run(check --answers ${WORK}/bom-vertex-face.csv)
  expect_output("CSV with a byte order mark" "1\n0\n")
  # A coordinate beyond the largest double (2^1024, on the third row): the exact methods answer
  # it, a double-based baseline cannot and says so with file and line (not an internal error).
  set(two_1024 "179769313486231590772930519078902473361797697894230657273430081157732675805500963132708477322407536021120113879871393357658789768814416622492847430639474124377767893424865485276302219601246094119453082952085005768838150682342462881473913110540827237163350510684586298239947245938479716304835356329624224137216")
  string(REGEX REPLACE "^([^\n]*\n[^\n]*\n)[0-9]+," "\\1${two_1024}," big "${body}")
  file(WRITE ${WORK}/big-vertex-face.csv "${big}")
  foreach(method naive naive-tolerance mpfr256)
    run(check --method ${method} ${WORK}/big-vertex-face.csv)
    expect_input_error("2^1024 under ${method}" "big-vertex-face.csv:3: a coordinate rounds beyond the largest double")
  endforeach()
  run(bench --repetitions 1 --methods filtered,naive ${WORK}/big-vertex-face.csv)
  expect_input_error("2^1024 in bench with naive" "big-vertex-face.csv:3: a coordinate rounds beyond the largest double")
  foreach(method filtered exact)
    run(check --method ${method} --answers ${WORK}/big-vertex-face.csv)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "2^1024 under ${method}: exit ${rc}\n${err}")
    endif()
  endforeach()

elseif(CASE STREQUAL "out_unwritable")
  # An output path that cannot be written is an input error naming it (exit 2), found before the
  # work; nothing is left half-written (no temporaries, an existing file untouched).
  file(WRITE ${WORK}/plain.txt "old\n")
  run(stability --families ee_parallel --k-max 1 --instances 1 --out ${WORK}/missing-dir/x.csv)
  expect_input_error("--out in a missing directory" "missing-dir/x.csv: cannot write: No such file or directory")
  run(stability --families ee_parallel --k-max 1 --instances 1 --out ${WORK})
  expect_input_error("--out a directory" "${WORK}: is a directory")
  run(bench --repetitions 1 --json ${WORK}/plain.txt/x.json ${small})
  expect_input_error("--json under a file" "plain.txt/x.json: cannot write: Not a directory")
  run(generate catalogue --out ${WORK}/plain.txt)
  expect_input_error("generate --out a file" "plain.txt: not a directory")
  run(generate catalogue --out ${WORK}/plain.txt/sub)
  expect_input_error("generate --out under a file" "plain.txt/sub: cannot create directory")
  run(generate scene --scene cloth --resolution 2 --out ${WORK}/plain.txt)
  expect_input_error("generate scene --out a file" "plain.txt: not a directory")
  run(fuzz-against ${PLUGIN} --kind vf --queries 4 --out ${WORK}/plain.txt)
  expect_input_error("fuzz-against --out a file" "plain.txt: not a directory")
  file(READ ${WORK}/plain.txt kept)
  if(NOT kept STREQUAL "old\n")
    message(FATAL_ERROR "a failed run changed plain.txt: '${kept}'")
  endif()
  # A good run writes the whole file and no temporary is left.
  run(stability --families ee_parallel --k-max 1 --instances 1 --methods filtered --out ${WORK}/s.csv)
  file(READ ${WORK}/s.csv written)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "" OR NOT written MATCHES "^family,kind,method,k,queries,fp,fn,fp_rate,fn_rate\nee_parallel,ee,filtered,-1,1,0,0,0,0\n")
    message(FATAL_ERROR "stability --out: exit ${rc}, file '${written}'")
  endif()
  file(GLOB temporaries ${WORK}/*.tmp* ${WORK}/*/*.tmp* ${WORK}/.exactccd*)
  if(temporaries)
    message(FATAL_ERROR "temporaries left behind: ${temporaries}")
  endif()
  # Standard output that cannot be written (a full device) is an error too, not a silent exit 0.
  if(EXISTS /dev/full)
    execute_process(COMMAND ${EXE} check --answers ${small} OUTPUT_FILE /dev/full RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 2 OR NOT err MATCHES "cannot write the standard output")
      message(FATAL_ERROR "stdout on /dev/full: exit ${rc}, stderr '${err}'")
    endif()
  endif()
  # A directory without write permission (root writes anyway: skipped).
  if(as_root)
    message(STATUS "out_unwritable: skipped the permission cases: running as root, who writes everywhere")
  else()
    file(MAKE_DIRECTORY ${WORK}/locked)
    file(CHMOD ${WORK}/locked DIRECTORY_PERMISSIONS OWNER_READ OWNER_EXECUTE)
    run(stability --families ee_parallel --k-max 1 --instances 1 --out ${WORK}/locked/x.csv)
    expect_input_error("--out in a read-only directory" "locked/x.csv: cannot write: Permission denied")
    run(generate catalogue --out ${WORK}/locked)
    expect_input_error("generate --out a read-only directory" "locked: cannot write: Permission denied")
    run(bench --repetitions 1 --json ${WORK}/locked/b.json ${small})
    expect_input_error("bench --json in a read-only directory" "locked/b.json: cannot write: Permission denied")
    file(CHMOD ${WORK}/locked DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
  endif()

elseif(CASE STREQUAL "scene_formats")
  # Every format is read: each bundled tetrahedron gives the OBJ tetrahedron's answer; a
  # mislabelled or unknown file is an error, never an empty mesh answered "intersection-free".
  set(meshes ${DATA}/meshes)
  set(tri "f 1 2 3\nf 4 5 6\n")
  set(t0 "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.25 0.25 1\nv 0.6 0.25 1\nv 0.25 0.6 1\n${tri}")
  file(WRITE ${WORK}/T0.obj "${t0}")
  file(WRITE ${WORK}/T1.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.25 0.25 -1\nv 0.6 0.25 -1\nv 0.25 0.6 -1\n${tri}")
  file(WRITE ${WORK}/tetra.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
  run(scene --json ${WORK}/tetra.obj ${WORK}/tetra.obj)
  set(tetra "${out}")
  if(NOT rc EQUAL 0 OR NOT tetra MATCHES "\"vertices\": 4, \"triangles\": 4")
    message(FATAL_ERROR "scene on tetra.obj: exit ${rc}\n${out}\n${err}")
  endif()
  foreach(f tetra.ply tetra-ascii.ply tetra-be.ply tetra.off tetra.stl tetra-ascii.stl)
    run(scene --json ${meshes}/${f} ${meshes}/${f})
    if(NOT rc EQUAL 0 OR NOT out STREQUAL tetra)
      message(FATAL_ERROR "scene on ${f}: exit ${rc}, output differs from tetra.obj's:\n${out}\n${tetra}\n${err}")
    endif()
  endforeach()
  # Malformed files of the other formats: errors with the line.
  file(READ ${meshes}/tetra-ascii.ply ascii_ply)
  string(REPLACE "element vertex 4" "element vertex 5" wrong_count "${ascii_ply}")
  file(WRITE ${WORK}/count.ply "${wrong_count}")
  run(scene ${WORK}/count.ply ${WORK}/count.ply)
  expect_input_error("PLY with a wrong vertex count" "count.ply:15: too many values for element 'vertex' [(]4, expected 3[)]")
  file(READ ${meshes}/tetra.off off)
  string(REPLACE "3 1 2 3" "3 1 2 4" off_range "${off}")
  file(WRITE ${WORK}/range.off "${off_range}")
  run(scene ${WORK}/range.off ${WORK}/range.off)
  expect_input_error("OFF index out of range" "range.off:10: face vertex index 4 out of range")
  # Mislabelled content: the extension and the content must agree.
  foreach(pair "tetra.ply|ply.obj|the content is PLY, but the extension says OBJ"
               "tetra-ascii.ply|ascii-ply.obj|the content is PLY, but the extension says OBJ"
               "tetra.off|off.obj|the content is OFF, but the extension says OBJ"
               "tetra.stl|stl.obj|the content is STL, but the extension says OBJ"
               "tetra-ascii.stl|ascii-stl.obj|the content is STL, but the extension says OBJ"
               "tetra.ply|ply.stl|the content is PLY, but the extension says STL"
               "tetra.stl|stl.ply|the content is STL, but the extension says PLY")
    string(REPLACE "|" ";" p "${pair}")
    list(GET p 0 from)
    list(GET p 1 to)
    list(GET p 2 pattern)
    file(COPY_FILE ${meshes}/${from} ${WORK}/${to})
    run(scene ${WORK}/${to} ${WORK}/T1.obj)
    expect_input_error("${from} as ${to}" "${to}: ${pattern}")
  endforeach()
  file(WRITE ${WORK}/obj.ply "${t0}")
  run(scene ${WORK}/obj.ply ${WORK}/T1.obj)
  expect_input_error("OBJ text as .ply" "obj.ply: the content is not PLY [(]text without the PLY header[)]")
  string(ASCII 1 2 3 127 binary)
  file(WRITE ${WORK}/binary.obj "${binary}${binary}")
  run(scene ${WORK}/binary.obj ${WORK}/T1.obj)
  expect_input_error("binary data as .obj" "binary.obj: the content is not OBJ [(]binary data[)]")
  # Unknown or missing extensions, with OBJ content.
  file(WRITE ${WORK}/T0.xyz "${t0}")
  run(scene ${WORK}/T0.xyz ${WORK}/T1.obj)
  expect_input_error("unknown extension" "T0.xyz: unknown mesh file extension '.xyz' [(]expected .ply, .stl, .off, .obj[)]")
  file(WRITE ${WORK}/T0 "${t0}")
  run(scene ${WORK}/T0 ${WORK}/T1.obj)
  expect_input_error("no extension" "T0: no file extension")
  # Empty meshes.
  file(WRITE ${WORK}/empty.obj "")
  run(scene ${WORK}/empty.obj ${WORK}/empty.obj)
  expect_input_error("empty OBJ" "empty.obj: no vertices")
  file(WRITE ${WORK}/comments.obj "# nothing here\n\n")
  run(scene ${WORK}/comments.obj ${WORK}/comments.obj)
  expect_input_error("OBJ of comments" "comments.obj: no vertices")
  file(WRITE ${WORK}/points.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\n")
  run(scene ${WORK}/points.obj ${WORK}/points.obj)
  expect_input_error("OBJ without faces" "points.obj: no faces")
  # Strict OBJ: unknown keywords and free-form geometry are errors with the line.
  file(WRITE ${WORK}/keyword.obj "v 0 0 0\nv 1 0 0\nvx 0 1 0\nf 1 2 3\n")
  run(scene ${WORK}/keyword.obj ${WORK}/keyword.obj)
  expect_input_error("unknown OBJ keyword" "keyword.obj:3: unknown OBJ keyword 'vx'")
  file(WRITE ${WORK}/curve.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\ncstype bspline\ncurv 0 1 1 2\n")
  run(scene ${WORK}/curve.obj ${WORK}/curve.obj)
  expect_input_error("free-form OBJ" "curve.obj:5: OBJ free-form geometry [(]'cstype'[)] is not supported")
  file(WRITE ${WORK}/extra.obj "v 0 0 0 1 junk\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
  run(scene ${WORK}/extra.obj ${WORK}/extra.obj)
  expect_input_error("malformed number after x y z" "extra.obj:1: vertex with 5 numbers")
  file(WRITE ${WORK}/normal.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 nan\nf 1//1 2//1 3//1\n")
  run(scene ${WORK}/normal.obj ${WORK}/normal.obj)
  expect_input_error("non-finite normal" "normal.obj:4: coordinate 'nan' is not finite")
  file(WRITE ${WORK}/ref.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n")
  run(scene ${WORK}/ref.obj ${WORK}/ref.obj)
  expect_input_error("bad face reference" "ref.obj:4: face vertex '1/x' is malformed")
  # Directories and missing files.
  file(MAKE_DIRECTORY ${WORK}/dir.obj)
  run(scene ${WORK}/dir.obj ${WORK}/T1.obj)
  expect_input_error("directory" "dir.obj: is a directory")
  run(scene ${WORK}/T0.obj ${WORK}/no-such.obj)
  expect_input_error("missing file" "no-such.obj: no such file")
  # A UTF-8 byte order mark loses no line: the same answer as without it (its first line is a
  # vertex, whose loss would shift every index).
  run(scene --json ${WORK}/T0.obj ${WORK}/T1.obj)
  set(plain "${out}")
  if(NOT rc EQUAL 0 OR NOT plain MATCHES "\"vertices\": 6")
    message(FATAL_ERROR "scene on the plain files: exit ${rc}\n${out}\n${err}")
  endif()
  string(ASCII 239 187 191 bom)
  file(WRITE ${WORK}/bom.obj "${bom}${t0}")
  run(scene --json ${WORK}/bom.obj ${WORK}/T1.obj)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL plain)
    message(FATAL_ERROR "OBJ with a byte order mark: exit ${rc}, output differs:\n${out}\n${plain}\n${err}")
  endif()
  # Upper-case extensions are the same formats.
  file(WRITE ${WORK}/UPPER.OBJ "${t0}")
  run(scene --json ${WORK}/UPPER.OBJ ${WORK}/T1.obj)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL plain)
    message(FATAL_ERROR "UPPER.OBJ: exit ${rc}\n${out}\n${err}")
  endif()

else()
  message(FATAL_ERROR "cli_input.cmake: unknown CASE '${CASE}'")
endif()
file(REMOVE_RECURSE ${WORK})
