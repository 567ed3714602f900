# @NAME@'s test: renders the Cornell box through bounce-render with this plugin, Vulkan
# validation on (a validation error exits 3), and checks that its setting and its debug
# view change the image: the pass runs and its output reaches the frame.
# cmake -DRENDER=<bounce-render> -DPLUGIN_DIR=<dir> -DNAME=@NAME@ -DWORK=<dir> -P render_test.cmake
file(MAKE_DIRECTORY ${WORK})
set(ENV{BOUNCE_VALIDATION} 1)
set(ENV{BOUNCE_USER_INI} "")
function(render out)
  execute_process(COMMAND ${RENDER} --plugin-dir ${PLUGIN_DIR} --scene content/cornell_box.gltf --gi ${NAME}
                          --width 32 --height 32 ${ARGN} --out ${WORK}/${out}
                  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    string(JOIN " " arguments ${ARGN})
    message(FATAL_ERROR "${RENDER} ${arguments} exited with ${status}:\n${output}")
  endif()
  if(NOT output MATCHES "${NAME}\\.Irradiance +[0-9]")
    message(FATAL_ERROR "the ${NAME}.Irradiance pass did not run:\n${output}")
  endif()
  file(SHA256 ${WORK}/${out} hash)
  set(${out}_hash ${hash} PARENT_SCOPE)
endfunction()
render(dim.png --set r.${NAME}.Intensity=0.1)
render(bright.png --set r.${NAME}.Intensity=2)
render(debug.png --set r.${NAME}.Intensity=2 --set r.${NAME}.DebugMode=1)
if(dim.png_hash STREQUAL bright.png_hash)
  message(FATAL_ERROR "r.${NAME}.Intensity does not change the image")
endif()
if(bright.png_hash STREQUAL debug.png_hash)
  message(FATAL_ERROR "r.${NAME}.DebugMode 1 does not change the image")
endif()
