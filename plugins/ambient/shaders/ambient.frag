#version 460
// The constant ambient irradiance, on surfaces whose material receives it.
#include "bounce/scene.glsl"

SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection; vec4 irradiance;)

layout(location = 0) out vec4 outIrradiance;

void main() { outIrradiance = vec4(draw.irradiance.rgb, 1.0); }
