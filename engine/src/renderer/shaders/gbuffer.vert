#version 460
#include "bounce/scene.glsl"

SCENE_VERTEX_INPUTS
SCENE_INSTANCES(0)
SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection; float textureLodBias;)

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;
layout(location = 3) out vec4 outTangent;


void main() {
  Instance inst = instances[draw.instance];
  vec4 world = inst.world * vec4(inPosition, 1.0);
  outWorldPosition = world.xyz;
  outNormal = mat3(inst.normalMatrix) * inNormal;
  outUv = inUv;
  outTangent = vec4(mat3(inst.world) * inTangent.xyz, inTangent.w);
  // Plugins redraw scene surfaces depth-tested against the G-buffer; `precise` (no fused
  // multiply-adds) and the same expression give them bit-identical depths.
  precise vec4 position = draw.viewProjection * (inst.world * vec4(inPosition, 1.0));
  gl_Position = position;
}
