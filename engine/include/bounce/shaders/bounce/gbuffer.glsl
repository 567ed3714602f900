// Reading the engine's G-buffer (channels.h) in a compute or fragment shader.
//
//   gbuffer.baseColor        RGBA8 sRGB   rgb: albedo (linear when sampled)
//   gbuffer.normalRoughness  RGBA16F      xyz: world normal (unit), w: perceptual roughness
//   gbuffer.material         RGBA8        r: metallic, g: specular factor, ba: geometric normal
//                                         (octahedral, decodeGeometricNormal; faces the camera)
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

// A unit normal as two numbers in [0, 1] (octahedral mapping, Meyer et al. 2010): what
// gbuffer.material's blue and alpha hold. In 8 bits a normal comes back within 1.3°:
// enough to tell which side of its surface a light or a ray is on and to move a ray's
// origin off it, what the geometric normal is for.
vec2 encodeOctahedral(vec3 n) {
  n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-20);
  vec2 e = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * mix(vec2(-1.0), vec2(1.0), greaterThanEqual(n.xy, vec2(0.0)));
  return e * 0.5 + 0.5;
}
vec3 decodeOctahedral(vec2 e) {
  e = e * 2.0 - 1.0;
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * mix(vec2(-1.0), vec2(1.0), greaterThanEqual(n.xy, vec2(0.0)));
  return normalize(n);  // |n| >= 1/sqrt(3) on the octahedron: never zero
}
// The geometric normal (the triangle's plane, facing the camera) from gbuffer.material.
vec3 decodeGeometricNormal(vec4 material) { return decodeOctahedral(material.ba); }

// Depth 1 means no geometry was drawn there (the far plane is at infinity).
bool isBackground(float depth) { return depth >= 1.0; }

#endif
