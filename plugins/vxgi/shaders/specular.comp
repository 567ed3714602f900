#version 460
// Specular tracing: one cone along the mirror direction for each pixel specular_list.comp
// listed (below the roughness threshold, specular or metal; it cleared the others). Its
// aperture follows the GGX lobe (diameter factor 2α, α = roughness²) but never goes below
// the floor the voxel resolution allows. Output: the incident radiance from the reflected
// direction (W/(m²·sr)) × intensity.
#include "tracing_common.glsl"

layout(local_size_x = 64) in;
layout(binding = 23, rgba16f) uniform writeonly image2D outTraced;
layout(std430, binding = 24) readonly buffer VxgiSpecularPixels {
  uvec4 arguments;  // w: pixels listed
  uint pixels[];    // x | y << 16
};

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= arguments.w) return;
  ivec2 pixel = ivec2(pixels[index] & 0xffffu, pixels[index] >> 16);
  vec3 P, N;
  float roughness;
  if (!surfaceAt(pixel, P, N, roughness)) {  // listed, so a surface: kept for safety
    imageStore(outTraced, pixel, vec4(0.0));
    return;
  }
  vec3 V = safeNormalize(pc.cameraPosition.xyz - P, N);
  vec3 R = reflect(-V, N);
  if (dot(R, N) <= 0.0) R = safeNormalize(R - N * (2.0 * dot(R, N)), N);  // below the horizon: mirror back up
  float alpha = roughness * roughness;
  ConeTracingArguments args = surfaceConeArguments(P, N);
  args.direction = R;
  args.coneFactor = max(2.0 * alpha, pc.extra.z);
  ConeTracingResults cone = TraceCone(args);
  countWork(WORK_TEXTURE_SAMPLES, vxgiFetches);
  imageStore(outTraced, pixel, vec4(sanitize(cone.irradiance * INV_PI * pc.tracing.x, HALF_MAX), 1.0));
}
