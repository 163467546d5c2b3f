cmake_minimum_required(VERSION 3.25)
# Run after each build of a GoogleTest binary (see GTestSuites.cmake): writes SUITES_FILE, the
# CTest script that adds one test per suite of TEST_EXECUTABLE.
# Inputs: TEST_EXECUTABLE, SUITES_FILE, FIRST (suites to start first), ENVIRONMENT (var=value),
# the lists with '|' between items.
string(REPLACE "|" ";" FIRST "${FIRST}")
string(REPLACE "|" ";" ENVIRONMENT "${ENVIRONMENT}")
execute_process(COMMAND ${TEST_EXECUTABLE} --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE result TIMEOUT 60)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${result}):\n${listing}")
endif()

string(REPLACE "\n" ";" lines "${listing}")
set(script "")
foreach(line IN LISTS lines)
  # Suite lines start in the first column and end with '.' (typed suites add "  # TypeParam").
  if(NOT line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    continue()
  endif()
  set(suite "${CMAKE_MATCH_1}")
  set(cost 1)
  if(suite IN_LIST FIRST)
    set(cost 1000)
  endif()
  string(APPEND script
         "add_test([=[${suite}]=] [==[${TEST_EXECUTABLE}]==] [=[--gtest_filter=${suite}.*]=])\n"
         "set_tests_properties([=[${suite}]=] PROPERTIES COST ${cost}"
         " ENVIRONMENT [==[${ENVIRONMENT}]==])\n")
endforeach()
file(WRITE ${SUITES_FILE} "${script}")
