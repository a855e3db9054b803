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

# hecal_add_module(<name> [DEPENDS <public targets>...] [PRIVATE_DEPENDS <targets>...]
#                  [TEST_DEPENDS <targets>...] [ONLY <stems>...])
# Builds library hecal_<name> (alias hecal::<name>) from src/<name>/*.cc (an INTERFACE library
# when the module has headers only) and one GoogleTest
# executable per src/<name>/*_test.cc, registered with CTest under the label "unit".
# A test file named *_slow_test.cc gets the label "slow" instead (kept out of the default run).
# A test file named *_opencv_test.cc uses OpenCV as a peer and is built only with
# HECAL_BUILD_VISION (the core libraries themselves never link OpenCV).
# ONLY keeps the sources <stem>.cc and <stem>_test.cc of the stems listed (a module whose other
# sources need a layer that is not built).
function(hecal_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS;PRIVATE_DEPENDS;TEST_DEPENDS;ONLY" ${ARGN})
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
    foreach(test_source ${test_sources})
      get_filename_component(stem ${test_source} NAME_WE)
      if(stem MATCHES "_opencv_test$" AND NOT HECAL_BUILD_VISION)
        continue()
      endif()
      hecal_add_test(${name}_${stem} ${test_source} DEPENDS ${target} ${ARG_TEST_DEPENDS})
    endforeach()
  endif()
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
                        hecal_compile_options)
  target_compile_definitions(hecal_test_pch PRIVATE HECAL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  hecal_test_optimisation(hecal_test_pch)
  target_precompile_headers(hecal_test_pch PRIVATE <gtest/gtest.h> <gmock/gmock.h> <Eigen/Dense>
                            <Eigen/Geometry> <algorithm> <cmath> <functional> <map> <memory>
                            <random> <sstream> <string> <vector>)
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

# hecal_add_test(<name> <sources>... DEPENDS <targets>...)
# One GoogleTest executable, run from the source tree so tests find data/ by relative path
# through HECAL_SOURCE_DIR. Label "slow" for *_slow_test names; "unit" and "robustness" for
# *_robustness_test names and the fuzz corpora (*_fuzz_*), which also join the target
# robustness_checks; else "unit".
function(hecal_add_test name)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  add_executable(test_${name} ${ARG_UNPARSED_ARGUMENTS})
  target_link_libraries(test_${name} PRIVATE ${ARG_DEPENDS} hecal_testing GTest::gtest
    GTest::gmock GTest::gtest_main hecal_compile_options)
  target_compile_definitions(test_${name} PRIVATE HECAL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  hecal_test_optimisation(test_${name})
  if(TARGET hecal_test_pch)
    target_precompile_headers(test_${name} REUSE_FROM hecal_test_pch)
  endif()
  add_test(NAME ${name} COMMAND test_${name})
  if(name MATCHES "_slow_test$")
    # Built on demand (cmake --build build --target slow_checks), not by the default build that
    # CI runs: the ~30 slow test files take about 4 CPU-minutes to compile.
    set_target_properties(test_${name} PROPERTIES EXCLUDE_FROM_ALL ON)
    add_dependencies(slow_checks test_${name})
    set_tests_properties(${name} PROPERTIES LABELS slow)
  elseif(name MATCHES "_robustness_test$" OR name MATCHES "_fuzz_")
    # The bad-input corpus (tests/data/robustness) and the fuzzers' kept inputs: their own label,
    # and part of every unit run.
    set_tests_properties(${name} PROPERTIES LABELS "unit;robustness")
    add_dependencies(robustness_checks test_${name})
  else()
    set_tests_properties(${name} PROPERTIES LABELS unit)
  endif()
endfunction()
