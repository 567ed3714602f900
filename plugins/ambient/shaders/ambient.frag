#version 460
// The constant ambient irradiance, on surfaces whose material receives it.
#include "bounce/scene.glsl"

SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection; vec4 irradiance;)

layout(location = 0) out vec4 outIrradiance;

// When the frame counts work: each shaded fragment's depth read (the test it passed) and
// colour write, an example of counting what only the GPU knows.
#define WORK_COUNTERS_BINDING 8
#include "bounce/work_counters.glsl"

// A shader with buffer writes otherwise runs before the depth test (and would count the
// fragments that fail it); without writes the test is early anyway, so this changes nothing else.
layout(early_fragment_tests) in;

void main() {
  outIrradiance = vec4(draw.irradiance.rgb, 1.0);
  countWork(WORK_IMAGE_BYTES, 4u + 8u);
}
