# The README's examples (docs/examples/, included verbatim in README.md): each is run by a test,
# and docs.readme_snippets checks that the README shows exactly these files.
find_package(Python3 COMPONENTS Interpreter QUIET)
if(Python3_Interpreter_FOUND)
  add_test(NAME docs.readme_snippets
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/tests/readme_snippets.py ${CMAKE_CURRENT_SOURCE_DIR})
endif()

# The C++ example: compiled against the library like a user's program, run, output checked
# (the values derived by hand: z(t) = 1 - 2t meets the plane at t = 1/2 and is 0.25 above it
# at t = 3/8).
add_executable(example_first_query docs/examples/first_query.cpp)
target_compile_options(example_first_query PRIVATE ${EXACTCCD_WARNINGS})
target_link_libraries(example_first_query PRIVATE exactccd::exactccd)
add_test(NAME docs.example_cpp COMMAND example_first_query)
set_tests_properties(docs.example_cpp PROPERTIES
  PASS_REGULAR_EXPRESSION "^hit 1, toi \\[0\\.5, 0\\.5\\], within 0\\.25 from \\[0\\.375, 0\\.375\\]\n$")

# The command lines, as a user runs them from the repository root with exactccd on PATH
# (errors, including in a pipeline, fail the script).
add_test(NAME docs.example_cli
  COMMAND ${CMAKE_COMMAND} -E env "PATH=$<TARGET_FILE_DIR:exactccd_cli>:$ENV{PATH}"
          bash -euo pipefail docs/examples/cli.sh
  WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
set_tests_properties(docs.example_cli PROPERTIES
  PASS_REGULAR_EXPRESSION "total .*\ntotal [^\n]*\n1 [0-9.e-]+ [0-9.e-]+\n1 [^\n]*\n1 [^\n]*\nvertices .*candidates ")
