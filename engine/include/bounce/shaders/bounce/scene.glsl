// The scene on the GPU (bounce::gpu::GpuScene): instance and material buffers, the
// vertex layout, and the push constants PassContext::drawScene sets per draw.
//
//   #include "bounce/scene.glsl"
//   SCENE_INSTANCES(0)                 // binds `SceneInstances { Instance instances[]; }`
//   SCENE_MATERIALS(1)                 // binds `SceneMaterials { Material materials[]; }`
//   SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection;)   // per-draw {instance, material} + extras
#ifndef BOUNCE_SCENE_GLSL
#define BOUNCE_SCENE_GLSL

struct Instance {
  mat4 world;
  mat4 normalMatrix;  // inverse-transpose of world's upper 3×3
};

struct Material {
  vec4 baseColor;    // linear RGBA
  vec4 emission;     // rgb: emitted radiance W/(m²·sr)
  vec4 specular;     // rgb: specular colour, a: specular factor (KHR_materials_specular)
  float metallic;
  float roughness;   // perceptual; GGX alpha = roughness²
  float normalScale;
  float alphaCutoff; // < 0: opaque
  ivec4 textures0;   // baseColor, metallicRoughness, normal, emissive (-1: none)
  ivec4 textures1;   // occlusion, specular, specularColor, flags (1: double-sided)
};

#define SCENE_INSTANCES(b) layout(std430, binding = b) readonly buffer SceneInstances { Instance instances[]; };
#define SCENE_MATERIALS(b) layout(std430, binding = b) readonly buffer SceneMaterials { Material materials[]; };
#define SCENE_DRAW_PUSH_CONSTANTS(extra) \
  layout(push_constant) uniform ScenePush { uint instance; uint material; uint pad0; uint pad1; extra } draw;

// Vertex attributes of VertexInput::Scene.
#define SCENE_VERTEX_INPUTS                       \
  layout(location = 0) in vec3 inPosition;        \
  layout(location = 1) in vec3 inNormal;          \
  layout(location = 2) in vec2 inUv;              \
  layout(location = 3) in vec4 inTangent;

#endif
