// Reading the engine's G-buffer (channels.h) in a compute or fragment shader.
//
//   gbuffer.baseColor        RGBA8 sRGB   rgb: albedo (linear when sampled)
//   gbuffer.normalRoughness  RGBA16F      xyz: world normal (unit), w: perceptual roughness
//   gbuffer.material         RGBA8        r: metallic, g: specular factor, a: 1 where geometry was drawn
//   gbuffer.emissive         RGBA16F      rgb: emitted radiance
//   gbuffer.depth            D32          0 near .. 1 far (1: nothing drawn)
#ifndef BOUNCE_GBUFFER_GLSL
#define BOUNCE_GBUFFER_GLSL

// World position of a pixel from its depth and the inverse view-projection.
vec3 worldPositionFromDepth(vec2 uv, float depth, mat4 inverseViewProjection) {
  vec4 ndc = vec4(uv * 2.0 - 1.0, depth, 1.0);
  vec4 world = inverseViewProjection * ndc;
  return world.xyz / world.w;
}

// Depth 1 means no geometry was drawn there (the far plane is at infinity).
bool isBackground(float depth) { return depth >= 1.0; }

#endif
