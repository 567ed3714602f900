# The soak benchmark's short version as a test: 300 frames of the changing Cornell box
# (camera through a post-process volume, a moving object, a light switched off and on)
# with the validation layer on (any message fails it), every frame's outputs checked for
# NaN/Inf, and no growth of device memory or of the resident set over the second half.
# bounce-soak exits non-zero when any check fails (engine/apps/bounce-soak/main.cpp).
#
# Techniques: VXGI (at the soak's cheap settings, 32³ clip-maps with three levels) and
# Ambient. 300 frames cost about 75 s of CPU for VXGI and 7 s for Ambient on lavapipe
# (measured; the path tracer and "none" add little the benchmark run does not cover).
# RSS over 150 frames moves in allocator-sized steps (a 64 KiB step reads as a slope of
# 430 KiB/1000 frames), so the test bounds the growth over the second half instead: at
# most 2 MiB (seen: under 0.1 MiB), which catches a leak of 14 KiB a frame or more, such
# as one 64² RGBA16F image per frame. Device memory must not grow at all.
if(TARGET bounce-soak)
  foreach(technique VXGI Ambient)
    add_test(NAME soak.${technique}
             COMMAND bounce-soak --scene ${PROJECT_SOURCE_DIR}/content/cornell_box.gltf --gi ${technique}
                     --ini ${PROJECT_SOURCE_DIR}/config/Soak.ini
                     --frames 300 --size 64 --validation --progress 0
                     --max-rss-growth 2 --max-rss-slope -1 --max-device-growth 0)
    set_tests_properties(soak.${technique} PROPERTIES
      ENVIRONMENT "BOUNCE_ROOT=${PROJECT_SOURCE_DIR};BOUNCE_SHADER_CACHE=${PROJECT_BINARY_DIR}/shader-cache"
      LABELS soak TIMEOUT 600)
  endforeach()
endif()
