# segslam_add_gtest_suites(TARGET [FIRST suite...] [ENVIRONMENT var=value...])
#
# Registers CTest tests for the GoogleTest suites of TARGET, found after each build from
# `TARGET --gtest_list_tests`: each suite listed after FIRST alone (named after it, running
# `TARGET --gtest_filter=Suite.*`), the others in batches of six suites, named after them
# (`A+B+C+...`, so `ctest -R Suite` still finds a suite). Few processes rather than one per test
# or per suite: starting the test binary costs 0.3 s (0.8 s under ASan; the dynamic loader
# resolving Open3D's libraries), and a suite's shared fixture (SetUpTestSuite) is built once.
# The FIRST suites run whole sequences (or the CLI on them): CTest starts them before the
# others, so that the last minutes of a parallel run are not one of them running alone. Run a
# single test with `TARGET --gtest_filter=Suite.Test`.
set(SEGSLAM_GTEST_SUITES_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/gtest_suites_discovery.cmake)

function(segslam_add_gtest_suites target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "FIRST;ENVIRONMENT")
  set(suites_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_suites.cmake")
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_suites_include.cmake")
  # Lists travel to the script with '|' for ';', which the build's shell would split on.
  string(REPLACE ";" "|" first "${arg_FIRST}")
  string(REPLACE ";" "|" environment "${arg_ENVIRONMENT}")
  add_custom_command(
    TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} "-DTEST_EXECUTABLE=$<TARGET_FILE:${target}>"
            "-DSUITES_FILE=${suites_file}" "-DFIRST=${first}"
            "-DENVIRONMENT=${environment}" -P ${SEGSLAM_GTEST_SUITES_SCRIPT}
    BYPRODUCTS ${suites_file}
    VERBATIM)
  file(WRITE ${include_file}
       "if(EXISTS \"${suites_file}\")\n"
       "  include(\"${suites_file}\")\n"
       "else()\n"
       "  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)\n"
       "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include_file})
endfunction()
