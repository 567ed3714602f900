# Helpers shared by the engine, its plugins and the tests.

set(BOUNCE_WARNINGS -Wall -Wextra -Wpedantic -Wno-missing-field-initializers)

# bounce_add_plugin: the same function out-of-tree plugins get from find_package(Bounce).
include(${CMAKE_CURRENT_LIST_DIR}/BouncePlugin.cmake)

# bounce_add_test(<target> SOURCES ... [LIBRARIES ...])
#
# A GoogleTest executable registered with ctest. Tests run from the build folder and
# find the repository through BOUNCE_SOURCE_DIR.
function(bounce_add_test target)
  # SERIAL: tests that start their own X server or window run one at a time.
  cmake_parse_arguments(ARG "SERIAL" "" "SOURCES;LIBRARIES" ${ARGN})
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE bounce_engine GTest::gtest GTest::gmock GTest::gtest_main ${ARG_LIBRARIES})
  target_compile_options(${target} PRIVATE ${BOUNCE_WARNINGS})
  target_compile_definitions(${target} PRIVATE
    BOUNCE_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    BOUNCE_BINARY_DIR="${PROJECT_BINARY_DIR}")
  set(serial FALSE)
  if(ARG_SERIAL)
    set(serial TRUE)
  endif()
  # TIMEOUT: a hang fails its own test within minutes instead of eating CI's 90 (the
  # slowest GPU test takes about a minute on two cores under load).
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60
    PROPERTIES ENVIRONMENT "BOUNCE_ROOT=${PROJECT_SOURCE_DIR}" RUN_SERIAL ${serial} TIMEOUT 300)
endfunction()
