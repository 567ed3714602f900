#version 460
// Same transform as the engine's G-buffer pass, `precise` like it, so depths match exactly
// and the depth test against the G-buffer passes where this surface is the visible one.
#include "bounce/scene.glsl"

SCENE_VERTEX_INPUTS
SCENE_INSTANCES(0)
SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection; vec4 irradiance;)

void main() {
  precise vec4 position = draw.viewProjection * (instances[draw.instance].world * vec4(inPosition, 1.0));
  gl_Position = position;
}
