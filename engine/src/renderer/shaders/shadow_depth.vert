#version 460
// Depth of scene geometry as seen from one shadow-map layer (and, for alpha-masked
// casters, the UV shadow_depth_masked.frag tests coverage at).
#include "bounce/scene.glsl"

SCENE_VERTEX_INPUTS
SCENE_INSTANCES(0)
SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection;)

layout(location = 0) out vec2 outUv;

void main() {
  outUv = inUv;
  gl_Position = draw.viewProjection * (instances[draw.instance].world * vec4(inPosition, 1.0));
}
