#version 460
// Voxelization, step 1: world-space vertices for the geometry shader.
#include "bounce/scene.glsl"

SCENE_VERTEX_INPUTS
SCENE_INSTANCES(20)
SCENE_DRAW_PUSH_CONSTANTS(ivec4 regionMin; ivec4 regionMax; ivec4 innerMin; ivec4 innerMax;)

layout(location = 0) out vec3 vWorld;
layout(location = 1) out vec2 vUv;

void main() {
  Instance inst = instances[draw.instance];
  vWorld = (inst.world * vec4(inPosition, 1.0)).xyz;
  vUv = inUv;
  gl_Position = vec4(vWorld, 1.0);
}
