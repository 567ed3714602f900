#version 460
// The pixels specular tracing traces: below the roughness threshold, with a specular
// factor or metal. They are listed for an indirect dispatch of specular.comp over just
// them, and every other pixel's output is cleared here. lavapipe runs a workgroup's lanes
// in step, so a traced pixel among untraced neighbours cost its whole vector every cone
// step: tracing the list, a Cornell box's specular pixels took about half the time.
// Pixels are taken in Morton order within each 8×8 tile (mortonPixel), so that specular.comp's
// SIMD groups, 8 consecutive slots, trace compact 4×2 tiles, whose mirror cones stay closer
// together than a row's: SpecularTracing 4% faster at 512² (this pass 0.25 ms slower), within
// the noise at 128² (vxgi README, stop 33).
#define VXGI_NO_TRACING
#include "tracing_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 23, rgba16f) uniform writeonly image2D outTraced;
// x: workgroups of VXGI_SPECULAR_GROUP pixels for vkCmdDispatchIndirect (y, z: 1, set
// before this pass); w: pixels listed.
layout(std430, binding = 24) buffer VxgiSpecularPixels {
  uvec4 arguments;
  uint pixels[];  // x | y << 16
};

const uint VXGI_SPECULAR_GROUP = 64u;  // specular.comp's local size

void main() {
  ivec2 pixel = mortonPixel();
  if (any(greaterThanEqual(pixel, pc.sizes.xy))) return;
  // The G-buffer's depth, normal and roughness, and material (surfaceAt; 16 B).
  countWork(WORK_IMAGE_BYTES, 16u);
  vec3 P, N;
  float roughness;
  vec4 material = texelFetch(gMaterial, pixel, 0);
  bool specular = material.g > 0.0 || material.r > 0.0;  // specular factor or metallic
  if (!surfaceAt(pixel, P, N, roughness) || roughness >= pc.extra.y || !specular) {
    imageStore(outTraced, pixel, vec4(0.0));
    countWork(WORK_IMAGE_BYTES, 8u);
    return;
  }
  uint slot = atomicAdd(arguments.w, 1u);
  pixels[slot] = uint(pixel.x) | (uint(pixel.y) << 16);
  countWork(WORK_BUFFER_BYTES, 8u);
  // One more workgroup for every VXGI_SPECULAR_GROUP pixels listed.
  if (slot % VXGI_SPECULAR_GROUP == 0u) atomicAdd(arguments.x, 1u);
}
