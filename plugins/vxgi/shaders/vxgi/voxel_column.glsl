// A voxelized fragment's voxel column, shared by the voxelizer (voxelize.frag) and the
// multi-bounce gather it hands its cones to (bounce_gather.comp): the voxels along the
// projection axis that the fragment's piece of surface passes through, and the sums it adds
// to each of them in the scratch volume. Needs clip_map.glsl, scratch.glsl and the `scratch`
// image; with VXGI_COLUMN_WEIGHTS 1 (the voxelizer) also the VxgiBrickOccupancy buffer.
#ifndef VXGI_VOXEL_COLUMN_GLSL
#define VXGI_VOXEL_COLUMN_GLSL

// 1: the sums get the coverage too (the density's sum, which the resolve divides by) and
// the voxels are marked as having sums. 0: radiance only, added to sums a fragment has
// already weighted and marked (the multi-bounce gather's light).
#ifndef VXGI_COLUMN_WEIGHTS
#define VXGI_COLUMN_WEIGHTS 1
#endif

// A column: `first` (world voxel coordinates) and the voxels first + i·axis for every bit i
// set in `mask` (at most 9: voxelize.frag spans at most 8 beyond the first).
struct VxgiVoxelColumn {
  ivec3 first;
  int axis;
  uint mask;
};

// How a piece of surface adds to a voxel's sums, per facing direction: its projected
// coverage of a voxel face along each axis, which side faces which way, and the material's
// voxelization flags.
struct VxgiSurfacePiece {
  vec3 normal;    // unit
  vec3 coverage;  // of a voxel face along x, y, z (0..1 each)
  bool doubleSided;
  bool proportional;  // emittance in proportion to coverage (else every voxel gets the full radiance)
  bool omni;          // an isotropic voxel: as opaque and as bright every way
};

// Adds radiance `front` (the side the normal faces) and `back` to every voxel of the column,
// per facing direction, with float atomics (and the coverage: VXGI_COLUMN_WEIGHTS). Returns
// the atomics done.
uint vxgiAddColumnSums(VxgiVoxelColumn column, VxgiSurfacePiece piece, vec3 front, vec3 back,
                       ivec4 scratchLayout) {
  int perDirection = scratchLayout.y;  // 4 (rgb·w, w) or 1 (w, AO mode)
  uint total = 0u;
  for (uint bits = column.mask; bits != 0u; bits &= bits - 1u) {
    ivec3 voxel = column.first;
    voxel[column.axis] += findLSB(bits);
    ivec3 t = vxgiWrap(voxel);
    uint atomics = 0u;
    for (int axis = 0; axis < 3; ++axis) {
      for (int s = 0; s < 2; ++s) {
        float facing = s == 0 ? piece.normal[axis] : -piece.normal[axis];  // > 0: the front faces ±axis
        bool frontSide = facing > 0.0;
        float w = piece.omni ? 1.0 : (frontSide || piece.doubleSided ? piece.coverage[axis] : 0.0);
        if (w <= 0.0) continue;
        float emitWeight = piece.proportional ? w : 1.0;
        int direction = VXGI_DIRECTIONS == 6 ? axis + 3 * s : axis;
        int base = direction * perDirection;
#if VXGI_AO_MODE
        imageAtomicAdd(scratch, vxgiScratchCoord(t, base, scratchLayout.x), w);
        atomics += 1u;
#else
        vec3 radiance = frontSide || piece.omni ? front : back;  // omni: the front radiance, every way
#if VXGI_COLUMN_WEIGHTS
        imageAtomicAdd(scratch, vxgiScratchCoord(t, base + 3, scratchLayout.x), w);
        atomics += 1u;
#endif
        imageAtomicAdd(scratch, vxgiScratchCoord(t, base + 0, scratchLayout.x), radiance.r * emitWeight);
        imageAtomicAdd(scratch, vxgiScratchCoord(t, base + 1, scratchLayout.x), radiance.g * emitWeight);
        imageAtomicAdd(scratch, vxgiScratchCoord(t, base + 2, scratchLayout.x), radiance.b * emitWeight);
        atomics += 3u;
#endif
      }
    }
    // The voxel has sums: the resolve reads only such voxels' (vxgi/scratch.glsl).
#if VXGI_COLUMN_WEIGHTS
    if (atomics > 0u) atomicOr(brickOccupancy[vxgiVoxelBitWord(t)], vxgiVoxelBit(t));
#endif
    total += atomics;
  }
  return total;
}

#if !VXGI_AO_MODE
// The multi-bounce gather a fragment hands to bounce_gather.comp (VxgiBounceRequests): its
// position, normal and diffuse albedo, and its column, packed into four vec4s (64 bytes).
struct VxgiBounceRequest {
  vec4 world;     // xyz: the fragment's world position; w: the packed column and flags (bits)
  vec4 normal;    // xyz: unit normal; w: first.x (bits)
  vec4 albedo;    // rgb: diffuse albedo; w: first.y (bits)
  vec4 coverage;  // xyz: coverage; w: first.z (bits)
};

// Packed word: axis (bits 0–1), mask (2–10), double-sided (11), proportional (12), omni (13).
VxgiBounceRequest vxgiPackBounceRequest(vec3 world, vec3 albedo, VxgiVoxelColumn column, VxgiSurfacePiece piece) {
  uint packed = uint(column.axis) | (column.mask << 2) | (piece.doubleSided ? 1u << 11 : 0u) |
                (piece.proportional ? 1u << 12 : 0u) | (piece.omni ? 1u << 13 : 0u);
  VxgiBounceRequest r;
  r.world = vec4(world, uintBitsToFloat(packed));
  r.normal = vec4(piece.normal, intBitsToFloat(column.first.x));
  r.albedo = vec4(albedo, intBitsToFloat(column.first.y));
  r.coverage = vec4(piece.coverage, intBitsToFloat(column.first.z));
  return r;
}

void vxgiUnpackBounceRequest(VxgiBounceRequest r, out vec3 world, out vec3 albedo, out VxgiVoxelColumn column,
                             out VxgiSurfacePiece piece) {
  uint packed = floatBitsToUint(r.world.w);
  world = r.world.xyz;
  albedo = r.albedo.rgb;
  column.first = ivec3(floatBitsToInt(r.normal.w), floatBitsToInt(r.albedo.w), floatBitsToInt(r.coverage.w));
  column.axis = int(packed & 3u);
  column.mask = (packed >> 2) & 0x1FFu;
  piece.normal = r.normal.xyz;
  piece.coverage = r.coverage.xyz;
  piece.doubleSided = (packed & (1u << 11)) != 0u;
  piece.proportional = (packed & (1u << 12)) != 0u;
  piece.omni = (packed & (1u << 13)) != 0u;
}

// PCG3D (Jarzynski and Olano, JCGT 2020): three well-mixed words from three.
uvec3 vxgiPcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// The turn of a column's multi-bounce cone pattern about its normal (a fraction of a full
// turn). Each column turns the pattern its own way: the cones that read this emittance
// average it over many voxels, and so over many turns, where one fixed pattern would give
// every surface the same directional bias. Only a turn: cones also moved outwards within
// their rings (up to grazing) lost 2.8% of the white furnace's light per bounce, against
// 1.3% with each at its ring's middle.
float vxgiColumnTurn(VxgiVoxelColumn column) {
  return float(vxgiPcg3d(uvec3(column.first) + uvec3(uint(column.axis) << 30)).x >> 8) * (1.0 / 16777216.0);
}
#endif

#endif
