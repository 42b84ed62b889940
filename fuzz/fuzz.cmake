# Fuzzing (docs/fuzzing.md); included at the end of the top-level CMakeLists.txt.
# - Every build: the example plug-ins of `exactccd fuzz-against` (build/plugins/*.so).
# - With tests: the plug-in loader and fuzz-against contract, and the seed corpus' freshness.
# - EXACTCCD_BUILD_FUZZERS (clang only; the flags are set at the top): the libFuzzer targets
#   fuzz_vertex_face and fuzz_edge_edge and their CTest smoke runs (fuzz.*): one in the default
#   configuration (exponent spread limit 400) and one in the full-range configuration
#   (EXACTCCD_FUZZ_MAX_SPREAD=2200: no limit, every exponent from 2^-1074 to 2^1023).

target_link_libraries(exactccd_cli PRIVATE ${CMAKE_DL_LIBS})  # dlopen for fuzz-against

# A plug-in (include/exactccd/plugin.h): a module exporting only its marked entry points.
function(exactccd_add_plugin name source)
  add_library(${name} MODULE ${source})
  set_target_properties(${name} PROPERTIES PREFIX "" LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/plugins
                        CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  target_compile_options(${name} PRIVATE ${EXACTCCD_WARNINGS})
  target_link_libraries(${name} PRIVATE exactccd_tools)
  target_link_options(${name} PRIVATE -Wl,--exclude-libs,ALL)
endfunction()
exactccd_add_plugin(naive_plugin fuzz/plugins/naive_plugin.cpp)
exactccd_add_plugin(naive_tolerance_plugin fuzz/plugins/naive_tolerance_plugin.cpp)
exactccd_add_plugin(exact_plugin fuzz/plugins/exact_plugin.cpp)
exactccd_add_plugin(sampled_distance_plugin fuzz/plugins/sampled_distance_plugin.cpp)

if(EXACTCCD_BUILD_TESTS)
  exactccd_add_plugin(plugin_vf_only tests/cli/plugin_vf_only.cpp)
  add_test(NAME cli.fuzz_against
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:exactccd_cli> -DNAIVE=$<TARGET_FILE:naive_plugin>
            -DVF_ONLY=$<TARGET_FILE:plugin_vf_only> -DWORK=${CMAKE_CURRENT_BINARY_DIR}/fuzz-against-test
            -P ${CMAKE_CURRENT_SOURCE_DIR}/tests/cli/cli_fuzz_against.cmake)
  # The minimum separation and every kind: exactccd itself as a plug-in finds nothing, the
  # sampled-distance plug-in's mistakes are found and replay, contact-only plug-ins are refused a
  # question they do not answer, shards merge (tests/cli/cli_fuzz_against_separation.cmake).
  add_test(NAME cli.fuzz_against_separation
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:exactccd_cli> -DEXACT=$<TARGET_FILE:exact_plugin>
            -DSAMPLED=$<TARGET_FILE:sampled_distance_plugin> -DNAIVE=$<TARGET_FILE:naive_plugin>
            -DVF_ONLY=$<TARGET_FILE:plugin_vf_only> -DWORK=${CMAKE_CURRENT_BINARY_DIR}/fuzz-against-separation-test
            -P ${CMAKE_CURRENT_SOURCE_DIR}/tests/cli/cli_fuzz_against_separation.cmake)
  # Sharded runs merged (tests/cli/cli_merge.cmake), and the Slurm recipe of tools/cluster/ on a
  # one-node cluster the test starts itself (tests/cli/cluster_slurm.sh; skipped without slurm-wlm
  # and munge, or when not root).
  add_test(NAME cli.merge
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:exactccd_cli> -DPLUGIN=$<TARGET_FILE:naive_plugin>
            -DDATA=${CMAKE_CURRENT_SOURCE_DIR}/data/sim -DWORK=${CMAKE_CURRENT_BINARY_DIR}/cli-tests/merge
            -P ${CMAKE_CURRENT_SOURCE_DIR}/tests/cli/cli_merge.cmake)
  add_test(NAME cli.cluster_slurm
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/tests/cli/cluster_slurm.sh $<TARGET_FILE:exactccd_cli>
            $<TARGET_FILE:naive_plugin> ${CMAKE_CURRENT_SOURCE_DIR}/data/sim
            ${CMAKE_CURRENT_SOURCE_DIR}/tools/cluster ${CMAKE_CURRENT_BINARY_DIR}/cli-tests/cluster_slurm)
  set_tests_properties(cli.cluster_slurm PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 600)
  # The slowest CLI runs (fuzz-against with shrinking: over 3 minutes under ASan with the wide
  # families, whose plug-in loading and shrinking then do not run under the sanitizers; the
  # Slurm cluster, 35 s in Release); sharded merging likewise left to the Release pass.
  set_tests_properties(cli.cluster_slurm cli.fuzz_against cli.fuzz_against_separation cli.merge PROPERTIES LABELS sanitizer-skip)
  # The committed seed corpus holds what the generator writes now.
  add_executable(make_seed_corpus fuzz/make_seed_corpus.cpp)
  target_compile_options(make_seed_corpus PRIVATE ${EXACTCCD_WARNINGS})
  target_link_libraries(make_seed_corpus PRIVATE exactccd_generators)
  add_test(NAME fuzz.seed_corpus_fresh
    COMMAND ${CMAKE_COMMAND} -DGENERATOR=$<TARGET_FILE:make_seed_corpus>
            -DCORPUS=${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus -DWORK=${CMAKE_CURRENT_BINARY_DIR}/seed-corpus-check
            -P ${CMAKE_CURRENT_SOURCE_DIR}/tests/cli/fuzz_corpus_fresh.cmake)
endif()

if(EXACTCCD_BUILD_FUZZERS)
  # Every libFuzzer target and the reader seeds, without the command-line program and the
  # plug-ins: what the fuzz.* smoke tests run (tools/test.sh builds this target, not all: the
  # program's 18 files under clang's ASan and UBSan cost CI about 100 s on 2 cores).
  add_custom_target(exactccd_fuzzers)
  set(EXACTCCD_FUZZ_SMOKE_RUNS 2000 CACHE STRING "Inputs per fuzzer in the CTest smoke runs")
  set(EXACTCCD_FUZZ_SMOKE_FULL_RANGE_RUNS 400 CACHE STRING
      "Inputs per fuzzer in the full-range CTest smoke runs (wide inputs cost up to seconds each)")
  enable_testing()
  foreach(kind vertex_face edge_edge)
    add_executable(fuzz_${kind} fuzz/fuzz_${kind}.cpp)
    target_compile_options(fuzz_${kind} PRIVATE ${EXACTCCD_WARNINGS})
    target_link_options(fuzz_${kind} PRIVATE -fsanitize=fuzzer)
    target_link_libraries(fuzz_${kind} PRIVATE exactccd_generators)
    add_dependencies(exactccd_fuzzers fuzz_${kind})
    # New inputs go to a scratch directory (the first one), never into the committed corpus.
    set(scratch ${CMAKE_CURRENT_BINARY_DIR}/fuzz-smoke/${kind})
    add_test(NAME fuzz.${kind}.smoke
      COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${scratch}' && exec '$<TARGET_FILE:fuzz_${kind}>' -runs=${EXACTCCD_FUZZ_SMOKE_RUNS} -seed=1 -max_len=512 -timeout=60 -print_final_stats=1 '${scratch}' '${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/${kind}'")
    set_tests_properties(fuzz.${kind}.smoke PROPERTIES TIMEOUT 600
      ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1;UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
    # The full-range configuration: no exponent-spread limit, so the wide seeds (famwide-*,
    # wide-*, grid-axis-scales) and whatever wide inputs the mutations make are checked too.
    set(scratch_full ${CMAKE_CURRENT_BINARY_DIR}/fuzz-smoke-full-range/${kind})
    add_test(NAME fuzz.${kind}.smoke_full_range
      COMMAND sh -c "rm -rf '${scratch_full}' && mkdir -p '${scratch_full}' && exec '$<TARGET_FILE:fuzz_${kind}>' -runs=${EXACTCCD_FUZZ_SMOKE_FULL_RANGE_RUNS} -seed=1 -max_len=512 -timeout=120 -print_final_stats=1 '${scratch_full}' '${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/${kind}'")
    set_tests_properties(fuzz.${kind}.smoke_full_range PROPERTIES TIMEOUT 900
      ENVIRONMENT "EXACTCCD_FUZZ_MAX_SPREAD=2200;ASAN_OPTIONS=detect_leaks=1;UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  endforeach()
endif()

# The reader fuzz targets (docs/fuzzing.md, section 5): every reader a user feeds a file to, on
# arbitrary bytes, with the checks of fuzz/readers/reader_oracle.hpp (errors name the file and
# line or byte offset, memory within a multiple of the input's size, round trips, counts, no
# trailing garbage). Seeds: the committed fuzz/corpus/read_<target>/ and those cut from the
# bundled data at build time (fuzz/readers/make_reader_seeds.cpp, into the build tree).
if(EXACTCCD_BUILD_FUZZERS)
  set(EXACTCCD_READER_FUZZ_SMOKE_SECONDS 4 CACHE STRING "Seconds per reader fuzz target in the CTest smoke runs")
  add_library(exactccd_reader_fuzz_support STATIC fuzz/readers/reader_oracle.cpp fuzz/readers/mesh_oracle.cpp
                                                  fuzz/readers/mesh_writers.cpp)
  target_compile_options(exactccd_reader_fuzz_support PRIVATE ${EXACTCCD_WARNINGS})
  target_include_directories(exactccd_reader_fuzz_support PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(exactccd_reader_fuzz_support PUBLIC exactccd_tools)
  add_executable(make_reader_seeds fuzz/readers/make_reader_seeds.cpp)
  target_compile_options(make_reader_seeds PRIVATE ${EXACTCCD_WARNINGS})
  target_link_libraries(make_reader_seeds PRIVATE exactccd_reader_fuzz_support)
  set(reader_seeds ${CMAKE_CURRENT_BINARY_DIR}/fuzz-reader-seeds)
  file(GLOB_RECURSE reader_seed_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/data/*.csv
       ${CMAKE_CURRENT_SOURCE_DIR}/data/*.obj ${CMAKE_CURRENT_SOURCE_DIR}/tests/data/*)
  add_custom_command(OUTPUT ${reader_seeds}/stamp
    COMMAND make_reader_seeds ${CMAKE_CURRENT_SOURCE_DIR} ${reader_seeds}
    COMMAND ${CMAKE_COMMAND} -E touch ${reader_seeds}/stamp
    DEPENDS make_reader_seeds ${reader_seed_sources}
    COMMENT "Cutting the reader fuzz seeds from the bundled data")
  add_custom_target(reader_fuzz_seeds ALL DEPENDS ${reader_seeds}/stamp)
  foreach(reader obj ply off stl benchmark_csv rigid_csv truth_json answers partial)
    set(target fuzz_read_${reader})
    add_executable(${target} fuzz/readers/${target}.cpp)
    target_compile_options(${target} PRIVATE ${EXACTCCD_WARNINGS})
    target_link_options(${target} PRIVATE -fsanitize=fuzzer)
    target_link_libraries(${target} PRIVATE exactccd_reader_fuzz_support)
    add_dependencies(${target} reader_fuzz_seeds)
    add_dependencies(exactccd_fuzzers ${target})
    set(scratch ${CMAKE_CURRENT_BINARY_DIR}/fuzz-smoke/read_${reader})
    set(seed_dirs "'${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus/read_${reader}'")
    if(NOT reader STREQUAL "partial")  # its seeds are the committed ones only
      string(APPEND seed_dirs " '${reader_seeds}/read_${reader}'")
    endif()
    add_test(NAME fuzz.read_${reader}.smoke
      COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${scratch}' && exec '$<TARGET_FILE:${target}>' -max_total_time=${EXACTCCD_READER_FUZZ_SMOKE_SECONDS} -seed=1 -max_len=8192 -timeout=10 -malloc_limit_mb=512 -rss_limit_mb=2048 -print_final_stats=1 '${scratch}' ${seed_dirs}")
    set_tests_properties(fuzz.read_${reader}.smoke PROPERTIES TIMEOUT 120
      ENVIRONMENT "ASAN_OPTIONS=detect_leaks=1;UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  endforeach()
endif()
