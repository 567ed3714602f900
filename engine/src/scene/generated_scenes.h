#pragma once
// Procedural scenes for benchmarks: complete (geometry, light, camera), deterministic,
// of a chosen size, so a benchmark can measure how a pass scales with the scene.

#include "bounce/scene/scene.h"

#include <memory>

namespace bounce::generated {

/// A closed 8 × 4 × 8 m room with a grid of bumpy spheres totalling about `triangles`
/// triangles (at least the room's 12), a point light under the ceiling and a camera in
/// a corner looking across.
std::unique_ptr<Scene> litRoom(uint32_t triangles);

}  // namespace bounce::generated
