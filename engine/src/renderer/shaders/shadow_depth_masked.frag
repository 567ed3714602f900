#version 460
// Alpha-masked casters in the shadow maps: the texels gbuffer.frag discards cast no
// shadow. Coverage is read from mip 0, as the engine's ray traversal and the reference
// path tracer read it: a coarser mip averages a leaf's alpha with the gaps around it,
// and a distant shadow-map texel would then lose the leaf (or fill the gaps).
#include "bounce/scene.glsl"

SCENE_MATERIALS(1)
SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection;)
layout(binding = 2) uniform sampler2D baseColorTexture;

layout(location = 0) in vec2 inUv;

void main() {
  Material m = materials[draw.material];
  if (m.alphaCutoff >= 0.0 && m.baseColor.a * textureLod(baseColorTexture, inUv, 0.0).a < m.alphaCutoff) discard;
}
