# What `cmake --install build --prefix P` puts where. The apps find everything relative to
# their own folder (Engine::locateRoot, the default plugin folder), so a prefix can move:
#
#   P/bin/                          the apps (RPATH $ORIGIN/../lib)
#   P/lib/libbounce_engine.so       the engine
#   P/lib/bounce/plugins/<Name>/    the in-tree plugins: descriptor, library, shaders/
#   P/lib/cmake/Bounce/             BounceConfig.cmake, its version file, Bounce::engine
#   P/include/bounce/               the public headers
#   P/share/bounce/                 the engine root: config/, content/, and the shaders the
#                                   engine compiles at run time under the paths it names them
#                                   by (engine/include/bounce/shaders: the GLSL library)
include(CMakePackageConfigHelpers)

set(BOUNCE_INSTALL_ROOT share/bounce)
set(BOUNCE_INSTALL_CMAKE_DIR lib/cmake/Bounce)

install(TARGETS bounce_engine EXPORT BounceTargets
  LIBRARY DESTINATION lib
  INCLUDES DESTINATION include)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/include/bounce DESTINATION include
  PATTERN shaders EXCLUDE)

# Every app the build has (the sanitizer build leaves the benchmarks out of `all`).
set(bounce_apps bounce-render bounce-viewer bounce-bench bounce-render-bench bounce-ray-bench bounce-soak)
foreach(app ${bounce_apps})
  if(NOT TARGET ${app})
    continue()
  endif()
  get_target_property(excluded ${app} EXCLUDE_FROM_ALL)
  if(excluded)
    continue()
  endif()
  set_target_properties(${app} PROPERTIES INSTALL_RPATH "$ORIGIN/../lib")
  install(TARGETS ${app} RUNTIME DESTINATION bin)
endforeach()

# The engine root. Shaders keep the paths the engine and the apps name them by.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/config ${PROJECT_SOURCE_DIR}/content DESTINATION ${BOUNCE_INSTALL_ROOT})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/include/bounce/shaders
  DESTINATION ${BOUNCE_INSTALL_ROOT}/engine/include/bounce)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/src/renderer/shaders DESTINATION ${BOUNCE_INSTALL_ROOT}/engine/src/renderer)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/apps/bounce-render-bench/shaders
  DESTINATION ${BOUNCE_INSTALL_ROOT}/engine/apps/bounce-render-bench)
install(FILES ${PROJECT_SOURCE_DIR}/engine/apps/bounce-ray-bench/trace_rays.comp
  DESTINATION ${BOUNCE_INSTALL_ROOT}/engine/apps/bounce-ray-bench)

# The CMake package: Bounce::engine and bounce_add_plugin.
install(EXPORT BounceTargets NAMESPACE Bounce:: DESTINATION ${BOUNCE_INSTALL_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/BounceConfig.cmake.in
  ${PROJECT_BINARY_DIR}/sdk/BounceConfig.cmake
  INSTALL_DESTINATION ${BOUNCE_INSTALL_CMAKE_DIR})
# Plugins load into apps of the same minor version (0.x: the plugin API version is the
# binding check; see BOUNCE_PLUGIN_API_VERSION).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sdk/BounceConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sdk/BounceConfig.cmake ${PROJECT_BINARY_DIR}/sdk/BounceConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/BouncePlugin.cmake
  DESTINATION ${BOUNCE_INSTALL_CMAKE_DIR})

# tools/new-plugin and its template: an out-of-tree author starts a plugin from the SDK
# (P/share/bounce/tools/new-plugin NAME writes ./<name>/, built with find_package(Bounce)).
install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/new-plugin DESTINATION ${BOUNCE_INSTALL_ROOT}/tools)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tools/plugin-template DESTINATION ${BOUNCE_INSTALL_ROOT}/tools)
