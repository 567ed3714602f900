#version 460
// Specular tracing: one cone along the mirror direction for pixels below the roughness
// threshold. Its aperture follows the GGX lobe (diameter factor 2α, α = roughness²)
// but never goes below the floor the voxel resolution allows. Output: the incident
// radiance from the reflected direction (W/(m²·sr)) × intensity.
#include "tracing_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 23, rgba16f) uniform writeonly image2D outTraced;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, pc.sizes.xy))) return;
  vec3 P, N;
  float roughness;
  vec4 material = texelFetch(gMaterial, pixel, 0);
  bool specular = material.g > 0.0 || material.r > 0.0;  // specular factor or metallic
  if (!surfaceAt(pixel, P, N, roughness) || roughness >= pc.extra.y || !specular) {
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
