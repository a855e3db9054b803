cmake_minimum_required(VERSION 3.25)
# CTest driver (cmake/HecalHelpers.cmake, hecal_test_executable): every test suite that an
# executable lists (--gtest_list_tests) is selected by the --gtest_filter of one CTest test, and
# every test file's filter selects at least one suite of the executable as built, so that no test
# is left out of every filter and no file's CTest test runs nothing.
# Arguments: -DEXECUTABLE=<test executable> -DSUITES=<a>|<b>,<c>,... (the suites of each file,
# files separated by commas).
string(REPLACE "," ";" files "${SUITES}")
set(expected)
foreach(file ${files})
  string(REPLACE "|" ";" suites "${file}")
  list(APPEND expected ${suites})
endforeach()
execute_process(COMMAND ${EXECUTABLE} --gtest_list_tests RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${rc}): ${err}")
endif()
string(REPLACE "\n" ";" lines "${out}")
set(listed)
foreach(line ${lines})
  # A suite line: "Suite.", "Prefix/Suite.", "Suite/0." or "Prefix/Suite/0.", maybe followed by
  # "  # TypeParam = …"; test lines are indented.
  if(line MATCHES "^([A-Za-z0-9_/]+)\\.")
    string(REPLACE "/" ";" parts "${CMAKE_MATCH_1}")
    set(found OFF)
    foreach(part ${parts})
      if(part IN_LIST expected)
        list(APPEND listed ${part})
        set(found ON)
      endif()
    endforeach()
    if(NOT found)
      message(FATAL_ERROR "${EXECUTABLE}: suite ${CMAKE_MATCH_1} is run by no CTest test (fix: "
                          "begin the TEST line with the macro and the suite name)")
    endif()
  endif()
endforeach()
foreach(file ${files})
  string(REPLACE "|" ";" suites "${file}")
  set(found OFF)
  foreach(suite ${suites})
    if(suite IN_LIST listed)
      set(found ON)
    endif()
  endforeach()
  if(NOT found)
    message(FATAL_ERROR "${EXECUTABLE}: none of the suites ${suites} is in the executable, so "
                        "their CTest test would run nothing")
  endif()
endforeach()
list(LENGTH files count)
message(STATUS "${EXECUTABLE}: the suites of ${count} test files, each run by its CTest test")
