#version 460
// Writes the G-buffer (see bounce/gbuffer.glsl for the layout).
#include "bounce/common.glsl"
#include "bounce/gbuffer.glsl"
#include "bounce/scene.glsl"

SCENE_INSTANCES(0)
SCENE_MATERIALS(1)
SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection; float textureLodBias;)
layout(binding = 2) uniform sampler2D baseColorTexture;
layout(binding = 3) uniform sampler2D metallicRoughnessTexture;
layout(binding = 4) uniform sampler2D normalTexture;
layout(binding = 5) uniform sampler2D emissiveTexture;

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;

layout(location = 0) out vec4 outBaseColor;
layout(location = 1) out vec4 outNormalRoughness;
layout(location = 2) out vec4 outMaterial;
layout(location = 3) out vec4 outEmissive;

void main() {
  Material m = materials[draw.material];
  vec4 base = m.baseColor * texture(baseColorTexture, inUv, draw.textureLodBias);
  if (m.alphaCutoff >= 0.0 && base.a < m.alphaCutoff) discard;
  vec2 mr = texture(metallicRoughnessTexture, inUv, draw.textureLodBias).bg;  // glTF: B = metallic, G = roughness
  float metallic = saturate(m.metallic * mr.x);
  float roughness = saturate(m.roughness * mr.y);

  // The face's own normal, facing the camera: the geometric normal the lighting pass
  // offsets shadow rays along, and the fallback for degenerate vertex normals. Framebuffer
  // x runs right and y down while the view looks into the screen, so cross(dP/dx, dP/dy)
  // points away from the camera on every visible surface; negated, it faces it. The
  // vertex normal is flipped for a back face (a double-sided material seen from behind).
  vec3 faceNormal = safeNormalize(-cross(dFdx(inWorldPosition), dFdy(inWorldPosition)), vec3(0.0, 1.0, 0.0));
  vec3 N = safeNormalize(gl_FrontFacing ? inNormal : -inNormal, faceNormal);
  if (m.textures0.z >= 0) {
    vec3 T = inTangent.xyz - N * dot(N, inTangent.xyz);
    if (dot(T, T) > 1e-12 && inTangent.w != 0.0) {
      T = normalize(T);
      vec3 B = cross(N, T) * sign(inTangent.w);
      vec3 tn = texture(normalTexture, inUv, draw.textureLodBias).xyz * 2.0 - 1.0;
      tn.xy *= m.normalScale;
      N = safeNormalize(mat3(T, B, N) * tn, N);
    }
  }
  vec3 emission = m.emission.rgb * texture(emissiveTexture, inUv, draw.textureLodBias).rgb;

  outBaseColor = vec4(saturate(base.rgb), 1.0);
  outNormalRoughness = vec4(N, roughness);
  outMaterial = vec4(metallic, saturate(m.specular.a), encodeOctahedral(faceNormal));
  outEmissive = vec4(sanitize(emission, HALF_MAX), 1.0);
}
