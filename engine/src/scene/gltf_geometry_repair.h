#pragma once
// Makes a freshly read triangle list keep MeshPrimitive's promises (finite positions,
// no degenerate triangles, unit normals) by dropping or recomputing what is broken.
// Pure geometry: reporting what was repaired is the caller's job.

#include "bounce/scene/mesh.h"

#include <cstddef>

namespace bounce::gltf {

struct GeometryRepairs {
  size_t nanTriangles = 0;       ///< dropped: a vertex position has a NaN
  size_t infTriangles = 0;       ///< dropped: a vertex position is infinite (and none NaN)
  size_t zeroAreaTriangles = 0;  ///< dropped: no area (coincident or collinear corners)
  size_t repairedNormals = 0;    ///< NaN, infinite or zero-length normals recomputed
  bool normalsComputed = false;  ///< the primitive had no normals; all were computed
};

/// Repairs `primitive` in place. Indices must already be in range. Positions that are
/// not finite are removed from the vertex arrays (which renumbers the indices).
/// Normals that are missing or broken are replaced with area-weighted smooth normals
/// (the average of the adjacent faces' normals, weighted by face area); normals that
/// are merely not unit length are normalized without being counted.
GeometryRepairs repairGeometry(MeshPrimitive& primitive);

}  // namespace bounce::gltf
