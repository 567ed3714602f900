# bounce_add_plugin: builds a Bounce plugin, in this repository or in a project of its own
# (find_package(Bounce) includes this file; see docs/architecture.md, "The SDK").
#
#   bounce_add_plugin(<target>
#     SOURCES <file>...          C++ sources of the shared library
#     [SHADERS <dir>]            GLSL; found at run time as PluginContext::shaderPath("x.comp")
#     [CONTENT <dir>]            data files the plugin reads (PluginDescriptor::folder()/content)
#     [DESCRIPTOR <file>]        default: the one *.bplugin in the calling folder
#     [FOLDER <name>]            default: the descriptor's "Name"
#     [LIBRARIES <lib>...])      linked privately, besides Bounce::engine
#
# The output folder <BOUNCE_PLUGIN_OUTPUT_DIR>/<FOLDER>/ (default: <build>/plugins) holds
# everything the engine loads: the descriptor, lib<target>.so, shaders/ and content/ (links
# to the source folders, so edited shaders hot-reload without a rebuild). Point the apps at
# <BOUNCE_PLUGIN_OUTPUT_DIR> with --plugin-dir or BOUNCE_PLUGIN_PATH. `cmake --install`
# copies the folder to <prefix>/lib/bounce/plugins/<FOLDER>/.

set(BOUNCE_PLUGIN_INSTALL_DIR lib/bounce/plugins)

# Stops configuring with one line naming the plugin target (the arguments after it are
# joined, so no semicolons). The leading space makes CMake print the text as it is instead
# of wrapping it.
function(bounce_plugin_configure_error target)
  string(JOIN "" text ${ARGN})
  message(FATAL_ERROR " bounce_add_plugin(${target}): ${text}")
endfunction()

function(bounce_add_plugin target)
  cmake_parse_arguments(ARG "" "FOLDER;DESCRIPTOR;SHADERS;CONTENT" "SOURCES;LIBRARIES" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    bounce_plugin_configure_error(${target} "unexpected arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_SOURCES)
    bounce_plugin_configure_error(${target} "no SOURCES")
  endif()

  # The descriptor names the library the engine opens and, by default, the folder.
  if(NOT ARG_DESCRIPTOR)
    file(GLOB found ${CMAKE_CURRENT_SOURCE_DIR}/*.bplugin)
    list(LENGTH found count)
    if(NOT count EQUAL 1)
      bounce_plugin_configure_error(${target} "expected one *.bplugin in ${CMAKE_CURRENT_SOURCE_DIR}, "
                                  "found ${count} (name one with DESCRIPTOR)")
    endif()
    set(ARG_DESCRIPTOR ${found})
  endif()
  get_filename_component(descriptor ${ARG_DESCRIPTOR} ABSOLUTE)
  if(NOT EXISTS ${descriptor})
    bounce_plugin_configure_error(${target} "descriptor ${descriptor} does not exist")
  endif()
  file(READ ${descriptor} json)
  string(JSON library ERROR_VARIABLE json_error GET "${json}" Library)
  if(json_error)
    bounce_plugin_configure_error(${target} "${descriptor}: no \"Library\": ${json_error}")
  endif()
  if(NOT library STREQUAL target)
    bounce_plugin_configure_error(${target} "${descriptor} names the library \"${library}\", so "
                                  "the engine would not find lib${target}.so")
  endif()
  string(JSON api ERROR_VARIABLE json_error GET "${json}" EngineApiVersion)
  if(NOT json_error AND DEFINED BOUNCE_PLUGIN_API_VERSION AND NOT api EQUAL BOUNCE_PLUGIN_API_VERSION)
    bounce_plugin_configure_error(${target} "${descriptor} targets plugin API ${api}, "
                                  "this SDK provides ${BOUNCE_PLUGIN_API_VERSION}")
  endif()
  if(NOT ARG_FOLDER)
    string(JSON ARG_FOLDER ERROR_VARIABLE json_error GET "${json}" Name)
    if(json_error)
      bounce_plugin_configure_error(${target} "${descriptor}: no \"Name\": ${json_error}")
    endif()
  endif()

  if(NOT BOUNCE_PLUGIN_OUTPUT_DIR)
    set(BOUNCE_PLUGIN_OUTPUT_DIR ${CMAKE_BINARY_DIR}/plugins)
  endif()
  set(out ${BOUNCE_PLUGIN_OUTPUT_DIR}/${ARG_FOLDER})
  set(install_dir ${BOUNCE_PLUGIN_INSTALL_DIR}/${ARG_FOLDER})

  add_library(${target} SHARED ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE Bounce::engine ${ARG_LIBRARIES})
  if(DEFINED BOUNCE_WARNINGS)
    target_compile_options(${target} PRIVATE ${BOUNCE_WARNINGS})
  endif()
  set_target_properties(${target} PROPERTIES
    LIBRARY_OUTPUT_DIRECTORY ${out}
    PREFIX "lib"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    # Installed in lib/bounce/plugins/<FOLDER>: the engine's library is three levels up.
    INSTALL_RPATH "$ORIGIN/../../..")
  get_filename_component(descriptor_name ${descriptor} NAME)
  configure_file(${descriptor} ${out}/${descriptor_name} COPYONLY)
  install(TARGETS ${target} LIBRARY DESTINATION ${install_dir})
  install(FILES ${descriptor} DESTINATION ${install_dir})

  foreach(kind SHADERS CONTENT)
    if(NOT ARG_${kind})
      continue()
    endif()
    string(TOLOWER ${kind} name)
    get_filename_component(dir ${ARG_${kind}} ABSOLUTE)
    if(NOT IS_DIRECTORY ${dir})
      bounce_plugin_configure_error(${target} "${kind} ${dir} is not a folder")
    endif()
    file(CREATE_LINK ${dir} ${out}/${name} SYMBOLIC)
    install(DIRECTORY ${dir}/ DESTINATION ${install_dir}/${name})
  endforeach()
endfunction()
