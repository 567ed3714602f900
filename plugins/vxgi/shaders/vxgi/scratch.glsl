// The voxelization scratch volume (ScratchLayout in src/voxelization_passes.cpp): float
// sums, `channels` per voxel tiled `perRow` along X and the rest along Z, so no side
// exceeds 2048 texels. Needs clip_map.glsl (mapSize).
#ifndef VXGI_SCRATCH_GLSL
#define VXGI_SCRATCH_GLSL

// Scratch texel of channel `channel` of toroidal voxel t. perRow is a power of two, so
// masks and shifts stand in for % and / (a scalar division per lane on a CPU device).
ivec3 vxgiScratchCoord(ivec3 t, int channel, int perRow) {
  int n = clipMap.mapSize;
  return t + ivec3((channel & (perRow - 1)) * n, 0, (channel >> findLSB(perRow)) * n);
}

#endif
