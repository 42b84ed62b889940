# CLI contract tests of the exactccd program, one CTest test per case (CMakeLists.txt):
#   cmake -DEXE=<exactccd> -DDATA=<tests/data> -DWORK=<scratch dir> -DCASE=<case> -P cli_check.cmake
# Scratch files go to WORK (in the build tree), never to the source tree.
foreach(var EXE DATA WORK CASE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "cli_check.cmake: -D${var}=... is required")
  endif()
endforeach()
set(small ${DATA}/small-vertex-face.csv)
set(data_root ${DATA}/../../data)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# Runs the program; sets rc, out and err in the caller.
macro(run)
  execute_process(COMMAND ${EXE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endmacro()

# Fails unless the last run exited with `code` and printed nothing on stdout.
macro(expect_error code what)
  if(NOT rc EQUAL ${code})
    message(FATAL_ERROR "${what}: exit code ${rc}, expected ${code}\nstderr: ${err}")
  endif()
  if(NOT out STREQUAL "")
    message(FATAL_ERROR "${what}: stdout must be empty, got '${out}'")
  endif()
endmacro()

if(CASE STREQUAL "check_answers")
  # --answers prints exactly one line per query, 0 or 1, nothing else, and the right answers;
  # several files give their lines one after the other.
  run(check --answers ${small})
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n0\n")
    message(FATAL_ERROR "check --answers: exit ${rc}, printed '${out}', expected '1\\n0\\n'\n${err}")
  endif()
  run(check --answers ${small} ${small})
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n0\n1\n0\n")
    message(FATAL_ERROR "check --answers on two files: exit ${rc}, printed '${out}'")
  endif()

elseif(CASE STREQUAL "check_table")
  # The default output: a header, one row per file (queries, positives, FP, FN, us/query), a total.
  run(check ${small} ${small})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "check: exit ${rc}\n${err}")
  endif()
  string(REGEX MATCHALL "small-vertex-face.csv +vf +2 +1 +0 +0 +[0-9.]+\n" rows "${out}")
  list(LENGTH rows n)
  if(NOT n EQUAL 2 OR NOT out MATCHES "^file +kind +queries +positives +FP +FN +us/query\n"
     OR NOT out MATCHES "\ntotal +4 +2 +0 +0 +[0-9.]+\n$")
    message(FATAL_ERROR "check: unexpected table\n${out}")
  endif()
  # Another question (here d = 100, within which both queries come): the counts against the truth
  # column (contact) are named for what they count; the query that comes within d without
  # touching is a right answer, counted in yes_truth_0, not a false positive.
  run(check --min-distance 100 ${small})
  if(NOT rc EQUAL 0 OR NOT out MATCHES "^file +kind +queries +truth_1 +yes_truth_0 +no_truth_1 +us/query\n"
     OR NOT out MATCHES "small-vertex-face.csv +vf +2 +1 +1 +0 +[0-9.]+\ntotal +2 +1 +1 +0 +[0-9.]+\n$")
    message(FATAL_ERROR "check --min-distance: unexpected table\n${out}")
  endif()

elseif(CASE STREQUAL "check_malformed")
  # A malformed line: file and line on stderr, exit code 2, nothing on stdout, even when a good
  # file comes first.
  run(check --answers ${small} ${DATA}/malformed-vertex-face.csv)
  expect_error(2 "malformed input")
  if(NOT err MATCHES "malformed-vertex-face.csv:5: ")
    message(FATAL_ERROR "malformed input: stderr '${err}' does not name file and line 5")
  endif()
  # A row count that is not a multiple of 8 names the last row.
  file(STRINGS ${small} lines)
  list(SUBLIST lines 0 9 nine)
  list(JOIN nine "\n" text)
  file(WRITE ${WORK}/short-vertex-face.csv "${text}\n")
  run(check ${WORK}/short-vertex-face.csv)
  expect_error(2 "9 rows")
  if(NOT err MATCHES "short-vertex-face.csv:9: incomplete query")
    message(FATAL_ERROR "9 rows: stderr '${err}'")
  endif()

elseif(CASE STREQUAL "check_usage_errors")
  # Exit code 2 and a message for every usage error.
  run(check ${DATA}/../cli_check.cmake)  # the kind cannot be inferred from this path
  expect_error(2 "uninferable kind")
  if(NOT err MATCHES "--kind")
    message(FATAL_ERROR "uninferable kind: stderr '${err}' does not mention --kind")
  endif()
  run(check ${WORK}/no-such-vertex-face.csv)
  expect_error(2 "missing file")
  run(check --no-such-option ${small})
  expect_error(2 "unknown option")
  run(check --method no-such-method ${small})
  expect_error(2 "unknown method")
  run(check --kind xx ${small})
  expect_error(2 "unknown kind")
  run(check)
  expect_error(2 "no input file")
  run(no-such-subcommand)
  expect_error(2 "unknown subcommand")
  run(check --shard 2/2 ${small})
  expect_error(2 "--shard 2/2")

elseif(CASE STREQUAL "check_kind")
  # --kind overrides the path. Read as edge-edge, the same rows give other answers: edge
  # (p, a) never reaches edge (b, c) in query 0 and meets it at t = 1/2 in query 1.
  file(COPY ${small} DESTINATION ${WORK})
  file(RENAME ${WORK}/small-vertex-face.csv ${WORK}/small.csv)
  run(check --kind vf --answers ${WORK}/small.csv)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n0\n")
    message(FATAL_ERROR "--kind vf: exit ${rc}, output '${out}'\n${err}")
  endif()
  run(check --kind ee --answers ${WORK}/small.csv)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "0\n1\n")
    message(FATAL_ERROR "--kind ee: exit ${rc}, output '${out}', expected '0\\n1\\n'\n${err}")
  endif()
  # The occurrence nearest the file name wins.
  file(MAKE_DIRECTORY ${WORK}/edge-edge)
  file(COPY ${small} DESTINATION ${WORK}/edge-edge)
  run(check ${WORK}/edge-edge/small-vertex-face.csv)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "small-vertex-face.csv +vf ")
    message(FATAL_ERROR "kind from the file name: exit ${rc}\n${out}${err}")
  endif()

elseif(CASE STREQUAL "check_methods")
  # Every method answers the same on this small exact data; naive too here.
  foreach(method filtered exact naive)
    run(check --method ${method} --answers ${small})
    if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n0\n")
      message(FATAL_ERROR "--method ${method}: exit ${rc}, output '${out}'\n${err}")
    endif()
  endforeach()

elseif(CASE STREQUAL "check_batch")
  # --threads gives the same answers; --shard I/N splits the queries into contiguous blocks.
  run(check --threads 3 --answers ${small})
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n0\n")
    message(FATAL_ERROR "--threads 3: exit ${rc}, output '${out}'")
  endif()
  run(check --shard 0/2 --answers ${small})
  set(s0 "${out}")
  run(check --shard 1/2 --answers ${small})
  if(NOT s0 STREQUAL "1\n" OR NOT out STREQUAL "0\n")
    message(FATAL_ERROR "--shard: got '${s0}' and '${out}'")
  endif()

elseif(CASE STREQUAL "check_json")
  # check --json: one object per file with the documented keys.
  run(check --json ${small})
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\"queries\": 2, \"positives\": 1, \"fp\": 0, \"fn\": 0")
    message(FATAL_ERROR "check --json: exit ${rc}\n${out}")
  endif()
  run(check --json --answers ${small})
  expect_error(2 "--json with --answers")

elseif(CASE STREQUAL "check_catalogue")
  # The bundled catalogue: the exact answers match its hand-derived truth column.
  run(check ${data_root}/catalogue/catalogue-vertex-face.csv
            ${data_root}/catalogue/catalogue-edge-edge.csv)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "total +297 +187 +0 +0 ")
    message(FATAL_ERROR "check on the catalogue: exit ${rc}\n${out}")
  endif()

elseif(CASE STREQUAL "catalogue_fresh")
  # The committed catalogue CSVs are what `generate catalogue` writes now (no stale data).
  run(generate catalogue --out ${WORK})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generate catalogue: exit ${rc}\n${err}")
  endif()
  foreach(kind vertex-face edge-edge)
    file(READ ${WORK}/catalogue-${kind}.csv fresh)
    file(READ ${data_root}/catalogue/catalogue-${kind}.csv committed)
    if(NOT fresh STREQUAL committed)
      message(FATAL_ERROR "data/catalogue/catalogue-${kind}.csv is stale: run exactccd generate catalogue --out data/catalogue")
    endif()
  endforeach()

elseif(CASE STREQUAL "bench_json")
  # bench --json writes one object per (dataset, method) with the documented keys.
  run(bench --repetitions 1 --json - ${small})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "bench --json: exit ${rc}\n${err}")
  endif()
  foreach(key dataset kind method queries mean_ns median_ns fp fn fp_fn_against truth_disagrees_with_exact
          exact_fallbacks)
    string(REGEX MATCHALL "\"${key}\":" found "${out}")
    list(LENGTH found count)
    if(NOT count EQUAL 3)
      message(FATAL_ERROR "bench --json: key ${key} appears ${count} times, expected 3:\n${out}")
    endif()
  endforeach()

elseif(CASE STREQUAL "bench_truth")
  # bench counts FP and FN against the file's truth column, for the exact methods too, and
  # reports how often that column disagrees with Method::exact. wrong-truth-vertex-face.csv is
  # small-vertex-face.csv with the second query's truth flipped to 1 (p passes beside the
  # triangle at (2, 2, 0): no collision, by hand).
  run(bench --repetitions 1 --methods filtered,exact --json - ${DATA}/wrong-truth-vertex-face.csv)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "bench on a wrong truth column: exit ${rc}\n${err}")
  endif()
  string(REGEX MATCHALL "\"fp\": 0, \"fn\": 1, \"fp_fn_against\": \"file truth column\", \"truth_disagrees_with_exact\": 1"
         rows "${out}")
  list(LENGTH rows n)
  if(NOT n EQUAL 2 OR NOT err MATCHES "disagrees with Method::exact on 1 of 2 queries")
    message(FATAL_ERROR "bench on a wrong truth column: expected FN 1 and truth_disagrees_with_exact 1 for "
                        "filtered and exact, and a note on stderr:\n${out}\n${err}")
  endif()
  run(bench --repetitions 1 --methods filtered,exact --json - ${small})
  string(REGEX MATCHALL "\"fp\": 0, \"fn\": 0, \"fp_fn_against\": \"file truth column\", \"truth_disagrees_with_exact\": 0"
         rows "${out}")
  list(LENGTH rows n)
  if(NOT rc EQUAL 0 OR NOT n EQUAL 2 OR err MATCHES "exactccd bench: ")
    message(FATAL_ERROR "bench on a correct truth column: exit ${rc}\n${out}\n${err}")
  endif()

elseif(CASE STREQUAL "stability")
  # stability writes the documented CSV; the exact methods have no error.
  run(stability --families vf_vertex_through_edge,ee_parallel --k-min 40 --k-max 44
                --instances 4 --methods naive,filtered,exact)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "^family,kind,method,k,queries,fp,fn,fp_rate,fn_rate\n")
    message(FATAL_ERROR "stability: exit ${rc}\n${out}")
  endif()
  string(REGEX MATCHALL "\n[a-z_]+,(vf|ee),(filtered|exact),-?[0-9]+,4,[0-9]+,[0-9]+" exact_rows "${out}")
  list(LENGTH exact_rows n)
  if(NOT n EQUAL 24)
    message(FATAL_ERROR "stability: expected 24 filtered/exact rows, found ${n}\n${out}")
  endif()
  foreach(row IN LISTS exact_rows)
    if(NOT row MATCHES ",4,0,0$")
      message(FATAL_ERROR "stability: an exact method erred: ${row}")
    endif()
  endforeach()

elseif(CASE STREQUAL "compare")
  # compare counts FP and FN against the exact answers, with indices and categories.
  file(WRITE ${WORK}/theirs.txt "0\n1\n")
  run(compare --answers ${WORK}/theirs.txt ${small})
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "queries 2, false positives 1, false negatives 1\n0 FN generic\n1 FP generic\n")
    message(FATAL_ERROR "compare: exit ${rc}, output:\n${out}")
  endif()
  file(WRITE ${WORK}/theirs.txt "1\n")
  run(compare --answers ${WORK}/theirs.txt ${small})
  expect_error(2 "compare with too few answers")

elseif(CASE STREQUAL "exact_stdout_clean")
  # A vertex-face query (found while profiling the fuzz corpus) whose exact decision runs a
  # polynomial gcd for which CGAL's modular gcd printed "UNLUCKY PRIME !!" to stdout; stdout
  # must hold only the answer lines, and compare only its report.
  set(unlucky ${DATA}/cgal-unlucky-prime-vertex-face.csv)
  run(check --method exact --answers ${unlucky})
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n")
    message(FATAL_ERROR "check --method exact --answers: exit ${rc}, printed '${out}', expected '1\\n'")
  endif()
  file(WRITE ${WORK}/theirs.txt "0\n")
  run(compare --answers ${WORK}/theirs.txt ${unlucky})
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "queries 1, false positives 0, false negatives 1\n0 FN coplanar_for_all_t\n")
    message(FATAL_ERROR "compare: exit ${rc}, output:\n${out}")
  endif()

elseif(CASE STREQUAL "help")
  # The program and every subcommand answer --help with exit code 0; no arguments is a usage
  # error that prints the help.
  run(--help)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: exactccd <subcommand>" OR NOT out MATCHES "exit codes")
    message(FATAL_ERROR "--help: exit ${rc}\n${out}")
  endif()
  foreach(sub check bench compare generate stability)
    run(${sub} --help)
    if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: exactccd ${sub}")
      message(FATAL_ERROR "${sub} --help: exit ${rc}\n${out}")
    endif()
  endforeach()
  run()
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "no arguments: exit ${rc}, expected 2")
  endif()

elseif(CASE STREQUAL "check_small_stack")
  # Queries whose roots are ~2^-2073 apart (tests/exact/test_bounded_stack.cpp derives answer 1 and
  # TOI [0, 2^-1074]): answered by both exact methods with the process stack limited to 256 KB (a quarter of the
  # 1 MB thread stack the contract is stated for; either recursion on the caller's stack crashes here).
  foreach(kind vertex-face edge-edge)
    foreach(method filtered exact)
      execute_process(COMMAND sh -c "ulimit -s 256 && exec \"$0\" check --method ${method} --answers \"$1\""
                              ${EXE} ${DATA}/wide-close-roots-${kind}.csv
                      RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
      if(NOT rc EQUAL 0 OR NOT out STREQUAL "1\n")
        message(FATAL_ERROR "${kind} --method ${method} under a 256 KB stack: exit ${rc}, output '${out}'\n${err}")
      endif()
    endforeach()
  endforeach()

elseif(CASE STREQUAL "families_wide")
  # Through the CLI: every degenerate family in every wide-exponent style (generate checks each
  # constructed answer and TOI against Method::exact), then both exact methods on the files:
  # 0 false positives and 0 false negatives against the constructed truth.
  run(generate families --wide --k-step 12 --seed 7 --out ${WORK}/wide)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generate families --wide: exit ${rc}\n${err}")
  endif()
  foreach(method filtered exact)
    run(check --method ${method} --json --threads 2 ${WORK}/wide/families-wide-vertex-face.csv
        ${WORK}/wide/families-wide-edge-edge.csv)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "check --method ${method} on the wide families: exit ${rc}\n${err}")
    endif()
    string(REGEX MATCHALL "\"(fp|fn)\": [0-9]+" counts "${out}")
    list(LENGTH counts n)
    if(NOT n EQUAL 4)
      message(FATAL_ERROR "check --method ${method} --json: expected fp and fn for two files, got '${counts}'\n${out}")
    endif()
    foreach(c IN LISTS counts)
      if(NOT c MATCHES ": 0$")
        message(FATAL_ERROR "check --method ${method} on the wide families: ${c}\n${out}")
      endif()
    endforeach()
  endforeach()

elseif(CASE STREQUAL "check_separation")
  # Hand-derived (tests/data/separation-*.csv): point-point, p still at the origin, q moving
  # along x: (2 -> 0): |pq| = 2 - 2t <= 1/2 from t = 3/4; (3 -> 0): 3 - 3t <= 1/2 from t = 5/6
  # (between the doubles 0.83333333333333326 and 0.83333333333333337); q still at distance 3:
  # never. With --tmax 1/2 nothing collides; at d = 0 the moving q reaches p at t = 1.
  set(pp ${DATA}/separation-point-point.csv)
  run(check --kind pp --min-distance 0.5 --toi --answers ${pp})
  set(expected "1 0.75 0.75\n0\n1 0.83333333333333326 0.83333333333333337\n")
  if(NOT rc EQUAL 0 OR NOT out STREQUAL expected)
    message(FATAL_ERROR "check --kind pp --min-distance 0.5 --toi --answers: exit ${rc}, printed '${out}'\n${err}")
  endif()
  run(check --kind pp --min-distance 0.5 --tmax 0.5 --toi --answers ${pp})
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "0\n0\n0\n")
    message(FATAL_ERROR "check --tmax 0.5: exit ${rc}, printed '${out}'\n${err}")
  endif()
  run(check --kind pp --toi --answers --method exact ${pp})
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "1 1 1\n0\n1 1 1\n")
    message(FATAL_ERROR "check --kind pp at d = 0: exit ${rc}, printed '${out}'\n${err}")
  endif()
  # The truth column is the d = 1/2 question's: the table finds no FP and no FN.
  run(check --kind pp --min-distance 0.5 --json ${pp})
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\"queries\": 3, \"positives\": 2, \"fp\": 0, \"fn\": 0")
    message(FATAL_ERROR "check --json at d = 0.5: exit ${rc}, printed '${out}'\n${err}")
  endif()
  # 2D point-edge (kind inferred from the name): p falls from (0, 1) to (0, -1) through the
  # still edge [(-1, 0), (1, 0)]: distance 1 - 2t <= 1/4 from t = 3/8.
  run(check --min-distance 0.25 --toi --answers ${DATA}/separation-point-edge-2d.csv)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "1 0.375 0.375\n")
    message(FATAL_ERROR "check point-edge-2d: exit ${rc}, printed '${out}'\n${err}")
  endif()
  # The baselines answer only vf and ee at d = 0; bad numbers are usage errors.
  run(check --kind pp --method naive ${pp})
  expect_error(2 "check --kind pp --method naive")
  run(check --min-distance 0.001 --method naive ${small})
  expect_error(2 "check --min-distance with a baseline")
  foreach(bad "--min-distance;-1" "--min-distance;nan" "--tmax;0" "--tmax;1.5" "--tmax;x")
    run(check --kind pp ${bad} ${pp})
    expect_error(2 "check ${bad}")
  endforeach()
  # stability asks every degenerate family the separation question: the filtered method must
  # agree with Method::exact on every instance (columns fp and fn of its rows are 0).
  run(stability --min-distance 0.01 --tmax 0.75 --instances 2 --k-max 12 --methods filtered)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "vf_coplanar_sliding,vf,filtered,12,2,0,0")
    message(FATAL_ERROR "stability --min-distance: exit ${rc}\n${out}\n${err}")
  endif()
  string(REGEX MATCHALL ",filtered,-?[0-9]+,[0-9]+,[0-9]+,[0-9]+" rows "${out}")
  list(LENGTH rows n)
  if(n LESS 100)
    message(FATAL_ERROR "stability --min-distance: only ${n} rows\n${out}")
  endif()
  foreach(row IN LISTS rows)
    if(NOT row MATCHES ",0,0$")
      message(FATAL_ERROR "stability --min-distance: filtered disagrees with exact: ${row}")
    endif()
  endforeach()
  run(stability --min-distance 0.01 --methods naive)
  expect_error(2 "stability --min-distance --methods naive")
  # compare --toi (hand-derived, the same point-point file at d = 1/2: exact TOIs 3/4, none,
  # 5/6): T = 0.7 is safe by 0.05, T = 0.9 is after 5/6: unsafe; query 1 collides for them only.
  file(WRITE ${WORK}/theirs.txt "1 0.7\n1 0.5\n1 0.9\n")
  run(compare --kind pp --min-distance 0.5 --toi ${WORK}/theirs.txt ${pp})
  if(NOT rc EQUAL 0 OR NOT out MATCHES "false positives 1, false negatives 0\n1 FP -\ntoi: shared collisions 2, safe 1, unsafe 1\n"
     OR NOT out MATCHES "gap lo - T of the safe TOIs \\(min q25 median q75 max\\): 0.05 0.05 0.05 0.05 0.05\n"
     OR NOT out MATCHES "\n2 unsafe T 0.90000000000000002 exact \\[0.83333333333333326, 0.83333333333333337\\]\n$")
    message(FATAL_ERROR "compare --toi: exit ${rc}, printed '${out}'\n${err}")
  endif()
  file(WRITE ${WORK}/bad.txt "1\n0\n0\n")  # a collision without its time: file:line
  run(compare --kind pp --toi ${WORK}/bad.txt ${pp})
  expect_error(2 "compare --toi without a time")
  if(NOT err MATCHES "bad.txt:1: expected 0, or 1 and a time of impact")
    message(FATAL_ERROR "compare --toi without a time: stderr '${err}'")
  endif()
  # A 2D file read as 3D has the wrong number of columns: file:line.
  run(check --kind pe ${DATA}/separation-point-edge-2d.csv)
  expect_error(2 "2D file as pe")
  if(NOT err MATCHES "separation-point-edge-2d.csv:1: expected 7 comma-separated integers")
    message(FATAL_ERROR "2D file as pe: stderr '${err}'")
  endif()

else()
  message(FATAL_ERROR "cli_check.cmake: unknown CASE '${CASE}'")
endif()
file(REMOVE_RECURSE ${WORK})

