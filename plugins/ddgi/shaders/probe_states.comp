#version 460
// DDGI.Relocation and DDGI.Classification (note §4.6, §4.7), one invocation per updated
// probe, from the fixed rays of this update. DDGI_RELOCATION 1 moves probes out of walls
// and away from nearby front faces; 0 classifies them (active or inactive).
#define DDGI_VOLUME_BINDING 0
#include "ddgi/volume.glsl"

layout(local_size_x = 32) in;

layout(std430, binding = 1) readonly buffer DdgiRays { vec4 ddgiRays[]; };
layout(binding = 2, rgba16f) uniform image2DArray probeData;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= ddgiUpdate.y) return;
  uint rays = ddgiTexels.z;
  uint fixedRays = ddgiTexels.w;
  uint probe = (ddgiUpdate.x + slot) % uint(ddgiCounts.w);
  ivec3 c = ddgiProbeCoords(probe);
  ivec3 texel = ddgiProbeDataTexel(c);
  vec4 data = imageLoad(probeData, texel);
  // A NaN from an earlier bad frame must not stick: start again from the rest position.
  if (any(isnan(data)) || any(isinf(data))) data = vec4(0.0);
  vec3 spacing = ddgiSpacing.xyz;
  float minFront = ddgiBias.z;

  uint backfaces = 0u;
  float closestBack = 1e30, closestFront = 1e30, farthestFront = 0.0;
  uint closestBackRay = 0u, closestFrontRay = 0u, farthestFrontRay = 0u;
  bool nearGeometry = false;  // classification: a front face within the probe's cell
  for (uint r = 0u; r < fixedRays; ++r) {
    float d = ddgiRays[slot * rays + r].w;
    vec3 dir = ddgiRayDirections[r].xyz;
    if (d < 0.0) {
      backfaces++;
      d = -5.0 * d;  // undo the trace's 0.2 factor
      if (d < closestBack) {
        closestBack = d;
        closestBackRay = r;
      }
      continue;
    }
    // RTXGI tests "farthest" only when the ray is not the new closest (an else-if); both
    // are tested here, so a probe with one front hit has it as both.
    if (d < closestFront) {
      closestFront = d;
      closestFrontRay = r;
    }
    if (d > farthestFront && d < DDGI_MISS_DISTANCE) {
      farthestFront = d;
      farthestFrontRay = r;
    }
    vec3 toPlanes = spacing / max(abs(dir), vec3(1e-6));  // 1e-6: an axis-parallel ray never reaches the other planes
    if (d <= min(toPlanes.x, min(toPlanes.y, toPlanes.z))) nearGeometry = true;
  }
  bool inside = backfaces > 0u && float(backfaces) / float(max(fixedRays, 1u)) > ddgiMisc.x;

#if DDGI_RELOCATION
  vec3 offset = data.xyz * spacing;
  vec3 moved = offset;
  if (inside) {
    // Through the nearest backface, and half the minimum distance beyond it.
    moved = offset + ddgiRayDirections[closestBackRay].xyz * (closestBack + 0.5 * minFront);
  } else if (closestFront < minFront) {
    // Too close to a front face: towards the farthest one, if it lies the other way
    // (RTXGI caps the step at 1 world unit; the minimum distance keeps it scale-free).
    vec3 nearDir = ddgiRayDirections[closestFrontRay].xyz;
    vec3 farDir = ddgiRayDirections[farthestFrontRay].xyz;
    if (dot(nearDir, farDir) <= 0.0) moved = offset + farDir * min(farthestFront, minFront);
  } else if (closestFront > minFront) {
    // Room to spare: drift back towards the rest position.
    float len = length(offset);
    if (len > 0.0) moved = offset - (offset / len) * min(closestFront - minFront, len);
  }
  // At most 45% of a cell (RTXGI), so a probe never crosses its neighbours.
  vec3 normalized = moved / spacing;
  if (dot(normalized, normalized) < 0.45 * 0.45) data.xyz = normalized;
#else
  data.w = (!inside && nearGeometry) ? 0.0 : 1.0;
#endif
  imageStore(probeData, texel, data);
}
