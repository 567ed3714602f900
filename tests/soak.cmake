# The soak benchmark's short version as a test: 300 frames of the changing Cornell box
# (camera through a post-process volume, a moving object, a light switched off and on)
# with the validation layer on (any message fails it), every frame's outputs checked for
# NaN/Inf, and no growth of device memory or of the resident set over the second half.
# bounce-soak exits non-zero when any check fails (engine/apps/bounce-soak/main.cpp).
#
# Techniques: VXGI at a 32³ clip-map and Ambient (the path tracer and "none" add nothing
# the nightly 10,000-frame run does not cover, and cost more; see README "Soak").
# RSS over 150 frames is noisy (allocator pools, the validation layer's own bookkeeping),
# so the test bounds the growth over the second half (8 MiB) rather than the slope; the
# slope limit is loose (it is judged over 150 frames) and the device memory must not
# grow at all.
if(TARGET bounce-soak)
  foreach(technique VXGI Ambient)
    add_test(NAME soak.${technique}
             COMMAND bounce-soak --scene ${PROJECT_SOURCE_DIR}/content/cornell_box.gltf --gi ${technique}
                     --frames 300 --size 64 --validation --set r.VXGI.MapSize=32 --progress 0
                     --max-rss-growth 8 --max-rss-slope 1000000 --max-device-growth 0)
    set_tests_properties(soak.${technique} PROPERTIES
      ENVIRONMENT "BOUNCE_ROOT=${PROJECT_SOURCE_DIR};BOUNCE_SHADER_CACHE=${PROJECT_BINARY_DIR}/shader-cache"
      LABELS soak TIMEOUT 600)
  endforeach()
endif()
