# The VPL plugin built against an installed SDK, rendered by the install's bounce-render
# (Cornell box, 32x32, Vulkan validation on: a validation error exits 3). The light paths
# and the gather must run, and the indirect light must reach the image: r.VPL.Intensity 0
# and 1 give different images. (The accuracy tests, against the path tracer, run in the
# tree: vpl_tests.)
# cmake -DRENDER=<bounce-render> -DPLUGIN_DIR=<dir> -DWORK=<dir> -P render_with_app.cmake
file(MAKE_DIRECTORY ${WORK})
set(ENV{BOUNCE_VALIDATION} 1)
set(ENV{BOUNCE_USER_INI} "")
function(render out)
  execute_process(COMMAND ${RENDER} --plugin-dir ${PLUGIN_DIR} --scene content/cornell_box.gltf --gi VPL
                          --width 32 --height 32 --set r.VPL.LightPaths=256 ${ARGN} --out ${WORK}/${out}
                  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  string(JOIN " " arguments ${ARGN})
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${RENDER} ${arguments} exited with ${status}:\n${output}")
  endif()
  foreach(pass VPL.Trace VPL.Merge VPL.Gather)
    if(NOT output MATCHES "${pass} +[0-9]")
      message(FATAL_ERROR "${pass} did not run (${arguments}):\n${output}")
    endif()
  endforeach()
  file(SHA256 ${WORK}/${out} hash)
  set(${out}_hash ${hash} PARENT_SCOPE)
endfunction()
render(off.png --set r.VPL.Intensity=0)
render(on.png --set r.VPL.Intensity=1)
if(off.png_hash STREQUAL on.png_hash)
  message(FATAL_ERROR "the VPLs' indirect light does not reach the image")
endif()
