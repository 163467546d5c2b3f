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

# Suites after FIRST run alone and start first (COST); the others go in batches of
# BATCH_SIZE suites, in listing order, one process per batch named after its suites
# (`ctest -R Suite` still finds a suite's batch).
set(BATCH_SIZE 6)
set(script "")
function(add_suites_test suites cost)
  list(JOIN suites "+" name)
  list(TRANSFORM suites APPEND ".*")
  list(JOIN suites ":" filter)
  string(APPEND script
         "add_test([=[${name}]=] [==[${TEST_EXECUTABLE}]==] [=[--gtest_filter=${filter}]=])\n"
         "set_tests_properties([=[${name}]=] PROPERTIES COST ${cost}"
         " ENVIRONMENT [==[${ENVIRONMENT}]==])\n")
  set(script "${script}" PARENT_SCOPE)
endfunction()

string(REPLACE "\n" ";" lines "${listing}")
set(batch "")
foreach(line IN LISTS lines)
  # Suite lines start in the first column and end with '.' (typed suites add "  # TypeParam").
  if(NOT line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    continue()
  endif()
  set(suite "${CMAKE_MATCH_1}")
  if(suite IN_LIST FIRST)
    add_suites_test("${suite}" 1000)
    continue()
  endif()
  list(APPEND batch "${suite}")
  list(LENGTH batch batch_length)
  if(batch_length EQUAL BATCH_SIZE)
    add_suites_test("${batch}" 1)
    set(batch "")
  endif()
endforeach()
if(batch)
  add_suites_test("${batch}" 1)
endif()
file(WRITE ${SUITES_FILE} "${script}")
