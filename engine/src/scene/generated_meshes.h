#pragma once
// Procedural meshes for tests and benchmarks: closed, with consistent winding (front
// faces counter-clockwise seen from outside) and unit normals.

#include "bounce/scene/mesh.h"

#include <glm/glm.hpp>

#include <string>

namespace bounce::generated {

/// A closed UV sphere with a deterministic bumpy radius, radius·(1 + bump·sin 7θ·sin 5φ):
/// 2·rings·segments triangles (those at the poles have zero area).
Mesh bumpySphere(uint32_t rings, uint32_t segments, float radius, float bump, uint32_t material);

/// An axis-aligned box of `size` centred at the origin; `inward` turns its faces in (a room).
Mesh box(glm::vec3 size, bool inward, uint32_t material, std::string name);

}  // namespace bounce::generated
