// A voxelized fragment's voxel column, shared by the voxelizer (voxelize.frag) and the
// multi-bounce passes it hands its gathers to (vxgi/bounce_requests.glsl): the voxels along the
// projection axis that the fragment's piece of surface passes through, and the sums it adds
// to each of them in the scratch volume. Needs clip_map.glsl; for the sums (VXGI_COLUMN_SUMS)
// scratch.glsl and the `scratch` image, and with VXGI_COLUMN_WEIGHTS 1 (the voxelizer) the
// VxgiBrickOccupancy buffer.
#ifndef VXGI_VOXEL_COLUMN_GLSL
#define VXGI_VOXEL_COLUMN_GLSL

// 0: only the structs (a pass that reads or writes requests but adds no sums).
#ifndef VXGI_COLUMN_SUMS
#define VXGI_COLUMN_SUMS 1
#endif
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

#if VXGI_COLUMN_SUMS
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

#endif  // VXGI_COLUMN_SUMS

#endif
