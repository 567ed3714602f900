#version 460
// VPL.Merge: one workgroup compacts the occupied merge-grid slots (or, unmerged, the raw
// VPLs with flux) into the VPL list, in slot order, so the list and every sum over it are
// the same on every run. Thread t owns a contiguous range of slots: it counts its
// occupied ones, the workgroup takes a prefix sum, then each writes its own at its offset.
// A merged VPL is the flux-weighted mean position and normal of the raw VPLs in its slot,
// with their summed flux (seed 004 keeps the cell centre; the mean keeps the light on the
// surface that reflected it).
#include "vpl/common.glsl"

layout(local_size_x = 256) in;

#if VPL_MERGE
layout(std430, binding = 0) readonly buffer VplCells { uint cells[]; };
#else
layout(std430, binding = 1) readonly buffer VplRaw { VplLight raw[]; };
#endif
layout(std430, binding = 2) writeonly buffer VplLights {
  uvec4 vplHeader;  // x: count, y: largest luminance (float bits), z: capacity
  VplLight vplLights[];
};

layout(push_constant) uniform Push {
  uvec4 counts;  // x: slots (merged) or raw VPLs, y: capacity
  vec4 grid;     // xyz: origin, w: cell size
  uvec4 dims;
  vec4 quant;    // y: flux quantum (watts per unit)
};

shared uint offsets[256];
shared float peaks[256];

bool occupied(uint slot) {
#if VPL_MERGE
  return cells[slot * VPL_SLOT_WORDS + VPL_WEIGHT] > 0u;
#else
  return raw[slot].flux.a > 0.0 || any(greaterThan(raw[slot].flux.rgb, vec3(0.0)));
#endif
}

VplLight decode(uint slot) {
#if VPL_MERGE
  uint base = slot * VPL_SLOT_WORDS;
  float q = quant.y;
  // Weight > 0 here (occupied), so the divisions are safe.
  float weight = float(cells[base + VPL_WEIGHT]);
  vec3 flux = vec3(cells[base + VPL_FLUX], cells[base + VPL_FLUX + 1u], cells[base + VPL_FLUX + 2u]) * q;
  vec3 inCell = vec3(cells[base + VPL_POSITION], cells[base + VPL_POSITION + 1u], cells[base + VPL_POSITION + 2u]) / weight;
  vec3 normalSum = vec3(int(cells[base + VPL_NORMAL]), int(cells[base + VPL_NORMAL + 1u]),
                        int(cells[base + VPL_NORMAL + 2u]));
  uint cell = slot / 6u;
  uvec3 c = uvec3(cell % dims.x, (cell / dims.x) % dims.y, cell / (dims.x * dims.y));
  VplLight l;
  l.positionSlot = vec4(grid.xyz + (vec3(c) + clamp(inCell, 0.0, 1.0)) * grid.w, uintBitsToFloat(slot));
  // Opposite normals within one bin cancel only partly (same dominant axis and sign); the
  // bin's axis stands in for a sum that cancels completely.
  l.normalCount = vec4(safeNormalize(normalSum, vplBinNormal(slot % 6u)), float(cells[base + VPL_COUNT]));
  l.flux = vec4(flux, luminance(flux));
  return l;
#else
  return raw[slot];
#endif
}

void main() {
  uint t = gl_LocalInvocationID.x;
  uint n = counts.x;
  uint chunk = (n + 255u) / 256u;
  uint begin = min(t * chunk, n), end = min(begin + chunk, n);
  uint mine = 0u;
  for (uint s = begin; s < end; ++s)
    if (occupied(s)) ++mine;
  offsets[t] = mine;
  barrier();
  if (t == 0u) {
    uint sum = 0u;
    for (uint i = 0u; i < 256u; ++i) {
      uint c = offsets[i];
      offsets[i] = sum;
      sum += c;
    }
    vplHeader = uvec4(min(sum, counts.y), 0u, counts.y, 0u);
  }
  barrier();
  uint at = offsets[t];
  float peak = 0.0;
  for (uint s = begin; s < end && at < counts.y; ++s) {
    if (!occupied(s)) continue;
    VplLight l = decode(s);
    peak = max(peak, l.flux.a);
    vplLights[at++] = l;
  }
  peaks[t] = peak;
  barrier();
  if (t == 0u) {
    float m = 0.0;
    for (uint i = 0u; i < 256u; ++i) m = max(m, peaks[i]);
    vplHeader.y = floatBitsToUint(m);
  }
}
