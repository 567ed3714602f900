# Helpers shared by the engine, its plugins and the tests.

set(BOUNCE_WARNINGS -Wall -Wextra -Wpedantic -Wno-missing-field-initializers)

# bounce_add_plugin(<target> FOLDER <name> DESCRIPTOR <file> SOURCES ...)
#
# Builds one plugin as a shared library and places it, with its JSON descriptor, in
# build/plugins/<name>/ where the engine's plugin discovery finds it. A plugin links
# bounce_engine and may include only the public headers under engine/include.
function(bounce_add_plugin target)
  cmake_parse_arguments(ARG "" "FOLDER;DESCRIPTOR" "SOURCES;LIBRARIES" ${ARGN})
  add_library(${target} SHARED ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE bounce_engine ${ARG_LIBRARIES})
  target_compile_options(${target} PRIVATE ${BOUNCE_WARNINGS})
  set(out ${BOUNCE_PLUGIN_OUTPUT_DIR}/${ARG_FOLDER})
  set_target_properties(${target} PROPERTIES
    LIBRARY_OUTPUT_DIRECTORY ${out}
    PREFIX "lib"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  get_filename_component(desc_name ${ARG_DESCRIPTOR} NAME)
  configure_file(${ARG_DESCRIPTOR} ${out}/${desc_name} COPYONLY)
endfunction()

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
