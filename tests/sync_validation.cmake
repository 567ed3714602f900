# GPU tests run again with the validation layer's synchronization checks
# (BOUNCE_VALIDATION=sync: VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT,
# engine/src/gpu/device.cpp). A missing or wrong barrier is a SYNC-HAZARD-* validation
# error, and every GPU test fails on validation errors, so each of these passes only with
# 0 hazards. The subset covers each place barriers come from: the render graph executor
# (the compiler's barriers, persistent and aliased resources), the deferred pipeline
# (shadows, G-buffer, lighting, bloom's hand-written barriers, read-backs; with the Ambient
# plugin in GoldenImage), VXGI's voxelization, mip and cone passes, the path tracer's
# passes, and one viewer session (swapchain and overlay). The soak test covers frames that
# move objects and lights; run it with BOUNCE_VALIDATION=sync by hand (README "Soak").
# Run these alone with `ctest -L sync-validation`; they cost about 20 s in all.
function(bounce_add_sync_validation_test name target filter)
  if(TARGET ${target})
    add_test(NAME sync.${name} COMMAND ${target} --gtest_filter=${filter})
    set_tests_properties(sync.${name} PROPERTIES
      ENVIRONMENT "BOUNCE_VALIDATION=sync;BOUNCE_ROOT=${PROJECT_SOURCE_DIR}"
      LABELS sync-validation ${ARGN})
  endif()
endfunction()

bounce_add_sync_validation_test(device bounce_render_tests "DeviceTest.*:DeviceSynchronizationValidation.*")
bounce_add_sync_validation_test(executor bounce_render_tests "Executor.*")
bounce_add_sync_validation_test(deferred bounce_render_tests "AnalyticLighting.*:GoldenImage.*:RenderOutputs.*")
bounce_add_sync_validation_test(vxgi vxgi_tests "VxgiRender.WhiteFurnace*:VxgiRender.CornellBoxBleeds*:VxgiRender.StaticScene*")
bounce_add_sync_validation_test(reference reference_tests "ReferencePlugin.*")
bounce_add_sync_validation_test(viewer bounce_viewer_tests "ViewerWindowTest.OpensTheWindow*:ViewerWindowTest.TheImGuiLayerDraws" RUN_SERIAL TRUE)
