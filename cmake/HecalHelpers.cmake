# Helpers that keep every module's CMake to a few lines (COLMAP-style).

# Compiler flags shared by every hecal target (warnings, sanitizers).
add_library(hecal_compile_options INTERFACE)
target_compile_options(hecal_compile_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
  -Wold-style-cast -Wcast-align -Wnull-dereference -Wimplicit-fallthrough>)
if(HECAL_WERROR)
  target_compile_options(hecal_compile_options INTERFACE -Werror)
endif()
if(HECAL_SANITIZE)
  target_compile_options(hecal_compile_options INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(hecal_compile_options INTERFACE -fsanitize=address,undefined)
endif()
install(TARGETS hecal_compile_options EXPORT hecalTargets)

# hecal_unity_batch(<target> <n>): <n> source files per unity batch of <target> instead of
# HECAL_UNITY_BATCH, unless that is 0 (one batch per target) or <n> is empty.
function(hecal_unity_batch target size)
  if(size AND NOT HECAL_UNITY_BATCH EQUAL 0)
    set_target_properties(${target} PROPERTIES UNITY_BUILD_BATCH_SIZE ${size})
  endif()
endfunction()

# hecal_add_module(<name> [DEPENDS <public targets>...] [PRIVATE_DEPENDS <targets>...]
#                  [TEST_DEPENDS <targets>...] [ONLY <stems>...] [UNITY_BATCH <n>]
#                  [TEST_UNITY_BATCH <n>] [ALONE <stems>...])
# Builds library hecal_<name> (alias hecal::<name>) from src/<name>/*.cc (an INTERFACE library
# when the module has headers only) and the module's test executables from src/<name>/*_test.cc
# (hecal_add_tests: label "unit"; *_slow_test.cc files get the label "slow" instead and are kept
# out of the default run). A test file named *_opencv_test.cc uses OpenCV as a peer and is built
# only with HECAL_BUILD_VISION (the core libraries themselves never link OpenCV).
# ONLY keeps the sources <stem>.cc and <stem>_test.cc of the stems listed (a module whose other
# sources need a layer that is not built).
# UNITY_BATCH and TEST_UNITY_BATCH: source files per unity batch of the library and of its test
# executables where the default (HECAL_UNITY_BATCH, HECAL_TEST_UNITY_BATCH) would make a batch
# take more than about 15 s to compile (docs/build.md#build-time); ignored when that default is 0
# (one batch per target, for builds where parsing the headers dominates, such as -O0).
# ALONE: sources compiled as translation units of their own, outside the batches (a file that
# takes about 10 s alone would make any batch it joins take over 20 s).
function(hecal_add_module name)
  cmake_parse_arguments(ARG "" "UNITY_BATCH;TEST_UNITY_BATCH"
                        "DEPENDS;PRIVATE_DEPENDS;TEST_DEPENDS;ONLY;ALONE" ${ARGN})
  set(dir ${PROJECT_SOURCE_DIR}/src/${name})
  file(GLOB all_sources CONFIGURE_DEPENDS ${dir}/*.cc)
  file(GLOB test_sources CONFIGURE_DEPENDS ${dir}/*_test.cc)
  if(ARG_ONLY)
    set(kept)
    foreach(stem ${ARG_ONLY})
      list(APPEND kept ${dir}/${stem}.cc ${dir}/${stem}_test.cc)
    endforeach()
    foreach(sources all_sources test_sources)
      set(filtered)
      foreach(source ${${sources}})
        if(source IN_LIST kept)
          list(APPEND filtered ${source})
        endif()
      endforeach()
      set(${sources} ${filtered})
    endforeach()
  endif()
  set(lib_sources ${all_sources})
  if(test_sources)
    list(REMOVE_ITEM lib_sources ${test_sources})
  endif()
  set(target hecal_${name})
  if(lib_sources)
    add_library(${target} ${lib_sources})
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    hecal_unity_batch(${target} "${ARG_UNITY_BATCH}")
    if(TARGET hecal_library_pch)
      target_precompile_headers(${target} REUSE_FROM hecal_library_pch)
    endif()
    foreach(stem ${ARG_ALONE})
      set_source_files_properties(${dir}/${stem}.cc PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endforeach()
    if(HECAL_SANITIZE AND name IN_LIST HECAL_SANITIZE_OPTIMISED_MODULES)
      target_compile_options(${target} PRIVATE -O1)  # after the build type's level: it wins
    endif()
    set(scope PUBLIC)
    target_link_libraries(${target} PRIVATE ${ARG_PRIVATE_DEPENDS} hecal_compile_options)
  else()  # a header-only module
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif()
  add_library(hecal::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} ${scope} ${ARG_DEPENDS})
  install(TARGETS ${target} EXPORT hecalTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  if(HECAL_BUILD_TESTS)
    set(kept_tests)
    foreach(test_source ${test_sources})
      get_filename_component(stem ${test_source} NAME_WE)
      if(stem MATCHES "_opencv_test$" AND NOT HECAL_BUILD_VISION)
        continue()
      endif()
      list(APPEND kept_tests ${test_source})
    endforeach()
    if(kept_tests)
      hecal_add_tests(${name} PREFIX ${name}_ SOURCES ${kept_tests}
                      DEPENDS ${target} ${ARG_TEST_DEPENDS} UNITY_BATCH ${ARG_TEST_UNITY_BATCH})
    endif()
  endif()
endfunction()

# hecal_add_library_pch(): the precompiled header the module libraries reuse (REUSE_FROM): Eigen
# and the standard headers most of their files include, compiled once with the libraries' flags
# (position-independent, the build type's optimisation) instead of parsed again by each unity
# batch (about 2 s a batch with clang). Not in sanitized builds, whose modules differ in their
# optimisation level (HECAL_SANITIZE_OPTIMISED_MODULES), which a precompiled header must match.
# HECAL_LIBRARY_PCH=OFF turns it off.
option(HECAL_LIBRARY_PCH "Compile the module libraries with a shared precompiled header" ON)
function(hecal_add_library_pch)
  if(NOT HECAL_LIBRARY_PCH OR HECAL_SANITIZE)
    return()
  endif()
  file(WRITE ${PROJECT_BINARY_DIR}/hecal_library_pch.cc
       "// The libraries' precompiled header's own translation unit.\n")
  add_library(hecal_library_pch OBJECT ${PROJECT_BINARY_DIR}/hecal_library_pch.cc)
  set_target_properties(hecal_library_pch PROPERTIES POSITION_INDEPENDENT_CODE ON
                        UNITY_BUILD OFF)
  target_link_libraries(hecal_library_pch PRIVATE Eigen3::Eigen hecal_compile_options)
  target_precompile_headers(hecal_library_pch PRIVATE <Eigen/Dense> <Eigen/Geometry> <algorithm>
                            <array> <cmath> <cstdio> <functional> <limits> <map> <memory>
                            <numbers> <optional> <random> <sstream> <stdexcept> <string>
                            <string_view> <utility> <vector>)
endfunction()

# hecal_add_test_pch(): the precompiled header every test executable reuses (REUSE_FROM):
# GoogleTest, GoogleMock, Eigen and the standard headers the tests use most, compiled once with
# the tests' own flags (hecal_test_pch). Measured (2026-11-29, -Og, user + system CPU, twice
# each): src/geometry/so3_test.cc 7.1 s without, 6.2 s with; apps/hecal/calibrate_test.cc 14.5 s
# without, 13.6 s with — about 1 s a test file, some 4 CPU-minutes over ~240 files; the header
# itself takes 11 s once. GCC uses the header only
# where the flags match (every test has the same ones) and otherwise parses the headers as usual,
# so a mismatch costs time, never correctness. HECAL_TEST_PCH=OFF turns it off.
option(HECAL_TEST_PCH "Compile the tests with a shared precompiled header" ON)
function(hecal_add_test_pch)
  if(NOT HECAL_TEST_PCH)
    return()
  endif()
  file(WRITE ${PROJECT_BINARY_DIR}/hecal_test_pch.cc "// The precompiled header's own translation unit.\n")
  add_library(hecal_test_pch OBJECT ${PROJECT_BINARY_DIR}/hecal_test_pch.cc)
  target_link_libraries(hecal_test_pch PRIVATE Eigen3::Eigen GTest::gtest GTest::gmock
                        nlohmann_json::nlohmann_json hecal_compile_options)
  target_compile_definitions(hecal_test_pch PRIVATE HECAL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  hecal_test_optimisation(hecal_test_pch)
  target_precompile_headers(hecal_test_pch PRIVATE <gtest/gtest.h> <gmock/gmock.h> <Eigen/Dense>
                            <Eigen/Geometry> <nlohmann/json.hpp> <algorithm> <array> <cmath>
                            <cstdio> <filesystem> <fstream> <functional> <limits> <map>
                            <memory> <numbers> <optional> <random> <sstream> <string>
                            <string_view> <vector>)
endfunction()

# The test files themselves at -Og in Release: the libraries under test keep -O3, and much of a
# test file's compile time at -O3 goes into optimising gtest's assertion code (the header-only
# helpers of src/testing are compiled at -Og with it). Measured on test files of geometry,
# estimation, io, vision, uncertainty and the CLI: 7.0 s CPU each at -O3, 5.6 s at -O1 (but GCC 12
# then warns falsely that Eigen copies an uninitialised vector, -Wmaybe-uninitialized, in
# first_order_test.cc), on that file 6.3 s at -O3, 6.1 s at -O2, 4.8 s at -Og; side by side on
# two more, -Og took 13% and 32% less than -O3: about 5 CPU-minutes over ~190 files. The price:
# test bodies run slower, most visibly contour_shape_tracker_sequence_test (10 → 40 s CPU); the
# unit suite took 277 s CPU (was about 240 s). The results do not change (IEEE arithmetic at every
# level, no -ffast-math). Sanitized builds choose their own level (scripts/test.sh).
function(hecal_test_optimisation target)
  if(NOT HECAL_SANITIZE)
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-Og>)
  endif()
endfunction()

# hecal_add_tests(<group> [PREFIX <prefix>] SOURCES <test files>... DEPENDS <targets>...
#                 [UNITY_BATCH <n>])
# The test files of one module (or of the CLI, or of tests/) as one GoogleTest executable per
# kind instead of one per file: bin/test_<group> (label "unit"), bin/test_<group>_robustness
# (*_robustness_test and *_fuzz_* files: labels "unit;robustness" and the target
# robustness_checks, so that a sanitized build can build just those) and bin/test_<group>_slow
# (*_slow_test files: label "slow", built on demand by the target slow_checks). Each executable
# is a unity build (HECAL_UNITY_BUILD: the files of a batch share one parse of GoogleTest, Eigen
# and hecal's headers and one instantiation of their templates) on the shared precompiled header.
# Each test file stays one CTest test, <prefix><stem>, that runs the file's own test suites
# (--gtest_filter from its TEST, TEST_F, TEST_P and TYPED_TEST lines), so a suite name belongs to
# one file of its executable: checked here, and by the CTest test <executable>_partition against
# the executable's own list of tests (docs/build.md#tests). A suite under #if counts as the file's
# as well; each file must have at least one suite in the executable as built.
function(hecal_add_tests group)
  cmake_parse_arguments(ARG "" "PREFIX;UNITY_BATCH" "SOURCES;DEPENDS" ${ARGN})
  if(NOT ARG_UNITY_BATCH OR HECAL_TEST_UNITY_BATCH EQUAL 0)
    set(ARG_UNITY_BATCH ${HECAL_TEST_UNITY_BATCH})
  endif()
  set(unit)
  set(robustness)
  set(slow)
  foreach(source ${ARG_SOURCES})
    get_filename_component(stem ${source} NAME_WE)
    if(stem MATCHES "_slow_test$")
      list(APPEND slow ${source})
    elseif(stem MATCHES "(^|_)robustness_test$" OR stem MATCHES "_fuzz_")
      list(APPEND robustness ${source})
    else()
      list(APPEND unit ${source})
    endif()
  endforeach()
  foreach(kind unit robustness slow)
    if(NOT ${kind})
      continue()
    endif()
    set(executable test_${group})
    if(NOT kind STREQUAL "unit")
      string(APPEND executable _${kind})
    endif()
    hecal_test_executable(${executable} ${kind} "${ARG_PREFIX}" ${ARG_UNITY_BATCH}
                          SOURCES ${${kind}} DEPENDS ${ARG_DEPENDS})
  endforeach()
endfunction()

# hecal_test_suites(<source> <out>): the test suites a test file defines or instantiates, from
# the lines that begin with TEST(, TEST_F(, TEST_P(, TYPED_TEST( or TYPED_TEST_P( followed by the
# suite's name, or with INSTANTIATE_TEST_SUITE_P(Prefix, or INSTANTIATE_TYPED_TEST_SUITE_P(Prefix,
# followed by it (a suite of a shared header, src/testing/lie_group_suite.h).
function(hecal_test_suites source out)
  file(STRINGS ${source} lines
       REGEX "^(TEST|TEST_F|TEST_P|TYPED_TEST|TYPED_TEST_P|INSTANTIATE_[A-Z_]*TEST_SUITE_P)\\(")
  set(suites)
  foreach(line ${lines})
    if(line MATCHES "^INSTANTIATE_[A-Z_]+\\( *[A-Za-z0-9_]+ *, *([A-Za-z_][A-Za-z0-9_]*)")
      list(APPEND suites ${CMAKE_MATCH_1})
    elseif(line MATCHES "^[A-Z_]+\\( *([A-Za-z_][A-Za-z0-9_]*) *,")
      list(APPEND suites ${CMAKE_MATCH_1})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES suites)
  set(${out} ${suites} PARENT_SCOPE)
endfunction()

# hecal_test_executable(<executable> unit|robustness|slow <prefix> <unity batch> SOURCES ...
#                       DEPENDS ...): the executable of hecal_add_tests and one CTest test per
# source file.
function(hecal_test_executable executable kind prefix batch)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${executable} ${ARG_SOURCES})
  target_link_libraries(${executable} PRIVATE ${ARG_DEPENDS} hecal_testing GTest::gtest
    GTest::gmock GTest::gtest_main hecal_compile_options)
  target_compile_definitions(${executable} PRIVATE HECAL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  hecal_test_optimisation(${executable})
  if(TARGET hecal_test_pch)
    target_precompile_headers(${executable} REUSE_FROM hecal_test_pch)
  endif()
  set_target_properties(${executable} PROPERTIES UNITY_BUILD_BATCH_SIZE ${batch})
  if(kind STREQUAL "slow")
    # Built on demand (cmake --build build --target slow_checks), not by the default build that
    # CI runs.
    set_target_properties(${executable} PROPERTIES EXCLUDE_FROM_ALL ON)
    add_dependencies(slow_checks ${executable})
    set(labels slow)
  elseif(kind STREQUAL "robustness")
    # The bad-input corpus (tests/data/robustness) and the fuzzers' kept inputs: their own label,
    # and part of every unit run.
    add_dependencies(robustness_checks ${executable})
    set(labels unit robustness)
  else()
    set(labels unit)
  endif()
  set(all_suites)
  foreach(source ${ARG_SOURCES})
    get_filename_component(stem ${source} NAME_WE)
    hecal_test_suites(${source} suites)
    if(NOT suites)
      message(FATAL_ERROR "${source}: no line begins with TEST(Suite, …) or TEST_F(Suite, …) "
                          "(fix: begin each test's first line with its macro and suite)")
    endif()
    set(filter)
    foreach(suite ${suites})
      get_property(owner GLOBAL PROPERTY HECAL_TEST_SUITE_${executable}_${suite})
      if(owner AND NOT owner STREQUAL source)
        message(FATAL_ERROR "${source}: test suite ${suite} is also defined in ${owner}, and both "
                            "are in ${executable} (fix: give each file's suites their own names)")
      endif()
      set_property(GLOBAL PROPERTY HECAL_TEST_SUITE_${executable}_${suite} ${source})
      list(APPEND filter "${suite}.*" "*/${suite}.*" "${suite}/*" "*/${suite}/*")
    endforeach()
    list(JOIN suites "|" file_suites)
    list(APPEND all_suites ${file_suites})
    list(JOIN filter ":" filter)
    add_test(NAME ${prefix}${stem} COMMAND ${executable} --gtest_filter=${filter})
    set_tests_properties(${prefix}${stem} PROPERTIES LABELS "${labels}")
  endforeach()
  list(JOIN all_suites "," all_suites)
  add_test(NAME ${executable}_partition
    COMMAND ${CMAKE_COMMAND} -DEXECUTABLE=$<TARGET_FILE:${executable}> -DSUITES=${all_suites}
            -P ${PROJECT_SOURCE_DIR}/cmake/check_test_partition.cmake)
  set_tests_properties(${executable}_partition PROPERTIES LABELS "${labels}")
endfunction()
