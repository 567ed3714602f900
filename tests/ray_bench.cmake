# bounce-ray-bench as a correctness check, not a timing: on small ray sets, the device's
# hits must agree with Embree's on the same rays (the benchmark exits 4 when more than 1
# ray in 10,000 disagrees on hit or miss) with the validation layer on (exit 3 on any
# message). Covers the benchmark's own paths: camera and probe rays, any-hit against
# rtcOccluded1, shading with shadow rays and with shadow maps.
if(TARGET bounce-ray-bench)
  set(cases
      "cornell_camera|--kind camera"
      "cornell_probe_shadow_rays|--kind probe --shade rays"
      "cornell_probe_shadow_maps|--kind probe --shade maps --lights spot"
      "generated_any_hit|--generate 20000 --kind probe --any-hit")
  foreach(case ${cases})
    string(REPLACE "|" ";" parts "${case}")
    list(GET parts 0 name)
    list(GET parts 1 arguments)
    separate_arguments(arguments UNIX_COMMAND "${arguments}")
    add_test(NAME ray_bench.${name}
             COMMAND bounce-ray-bench --scene ${PROJECT_SOURCE_DIR}/content/cornell_box.gltf ${arguments}
                     --rays 16384 --runs 1 --validation)
    set_tests_properties(ray_bench.${name} PROPERTIES
      ENVIRONMENT "BOUNCE_ROOT=${PROJECT_SOURCE_DIR};BOUNCE_SHADER_CACHE=${PROJECT_BINARY_DIR}/shader-cache"
      LABELS ray-bench TIMEOUT 300)
  endforeach()
endif()
