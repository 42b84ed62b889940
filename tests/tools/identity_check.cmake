# tools/identity_check.sh works and can fail (tests/CMakeLists.txt, tools.identity_check):
#   cmake -DEXE=<exactccd> -DSOURCE_DIR=<repository> -DWORK=<scratch dir> -P identity_check.cmake
# - the program against itself on 20 files of tests/data (a malformed file, rigid files with the
#   kind in the path or from --kind, linear files of three kinds; not the two wide-close-roots
#   files, 11 s of the 15 s tests/data takes): identical, exit 0, the malformed file rejected by
#   both alike;
# - against a wrapper that changes one answer line of one file at one question: exactly that
#   difference reported (file, question, line), exit 1;
# - a wrapper that fails as an internal error on one file, a program that does not exist, no
#   arguments: exit 2; an absent shared sample is said so.
foreach(var EXE SOURCE_DIR WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "identity_check.cmake: -D${var}=... is required")
  endif()
endforeach()
set(script ${SOURCE_DIR}/tools/identity_check.sh)
set(data ${SOURCE_DIR}/tests/data)
set(small ${data}/small-vertex-face.csv)
set(subset --no-default-roots --root ${data}/rigid --root ${data}/rigid-closed-form-vertex-face.csv
           --root ${data}/malformed-vertex-face.csv --root ${small} --root ${data}/separation-point-edge-2d.csv
           --root ${data}/separation-point-point.csv)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

macro(run)
  execute_process(COMMAND bash ${script} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endmacro()

# A function, not a macro: a macro's arguments are unescaped once more ("\\(" would be a group).
function(expect code pattern what)
  if(NOT rc EQUAL ${code} OR NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: exit ${rc} (expected ${code}), output not matching '${pattern}'\n"
                        "stdout:\n${out}\nstderr:\n${err}")
  endif()
endfunction()

# A wrapper of the program: the runs whose arguments match CASE_PATTERN get BODY (a shell
# snippet; "$@" are the arguments), the others are the program's own.
function(wrapper name case_pattern body)
  file(WRITE ${WORK}/${name}
       "#!/bin/sh\ncase \"$*\" in\n  ${case_pattern})\n    ${body} ;;\nesac\nexec \"${EXE}\" \"$@\"\n")
  file(CHMOD ${WORK}/${name} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endfunction()

# The program against itself: identical; only the malformed file rejected (at its 6 questions:
# a rigid file run as linear, or a hand-derived one without --kind, would be rejected too).
run(${subset} ${EXE} ${EXE})
expect(0 "identity_check: 20 files x 6 questions = 120 compared \\(6 rejected by both alike\\), 0 differences, 0 failed runs"
       "the program against itself")
expect(0 "rejected by both alike: exactccd: [^\n]*malformed-vertex-face.csv:" "the malformed file")

# One answer line changed (the second query of small-vertex-face.csv at d = 0, tmax = 1): 0
# becomes 1 0 0, 1 ... becomes 0.
wrapper(one_answer_changed "*\"--min-distance 0 --tmax 1 \"*small-vertex-face.csv"
        "out=$(\"${EXE}\" \"$@\"); rc=$?; printf '%s\\n' \"$out\" | sed '2s/^1 .*/0/;t;2s/^0$/1 0 0/'; exit $rc")
run(${subset} ${EXE} ${WORK}/one_answer_changed ${WORK}/kept)
expect(1 "DIFFERENCE tests/data/small-vertex-face.csv, d = 0, tmax = 1:\n  stdout differs\n    first difference at line 2:\n      old: [^\n]*\n      new: "
       "one answer changed")
expect(1 "= 120 compared [^\n]*, 1 differences, 0 failed runs" "one answer changed: the count")
file(GLOB kept ${WORK}/kept/new/*.out)
list(LENGTH kept kept)
if(NOT kept EQUAL 120 OR NOT EXISTS ${WORK}/kept/files.tsv)
  message(FATAL_ERROR "one answer changed: ${kept} outputs kept in OUT_DIR, not 120 and files.tsv\n${out}")
endif()

# An internal error (exit 1) on one file: a run that failed, exit 2 (the outputs kept in WORK,
# not in a temporary folder).
wrapper(internal_error "*small-vertex-face.csv" "echo 'exactccd: internal error: test' >&2; exit 1")
run(--no-default-roots --root ${small} ${EXE} ${WORK}/internal_error ${WORK}/failed)
expect(2 "FAILED TO RUN tests/data/small-vertex-face.csv, d = 0, tmax = 1: exit status old 0, new 1" "internal error")

# Usage errors: no program, a missing program, an unknown option.
run()
expect(2 "expected OLD_EXACTCCD NEW_EXACTCCD" "no arguments")
run(${EXE} ${WORK}/no-such-program)
expect(2 "no-such-program is not an executable program" "a missing program")
run(--bogus ${EXE} ${EXE})
expect(2 "unknown option '--bogus'" "an unknown option")

# An absent shared sample is said so (and listing needs no program).
run(--list --sample-dir ${WORK}/absent-sample)
expect(0 "the shared folder [^\n]*absent-sample is absent: its files are NOT compared" "absent sample")
expect(0 "\nlinear\tauto\tdata/sim/sim-cloth-vertex-face.csv\n" "the listing")
file(REMOVE_RECURSE ${WORK})
