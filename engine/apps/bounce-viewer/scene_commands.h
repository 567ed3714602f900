#pragma once
// Console commands that edit the scene's materials and lights as the outliner does, so
// scripts and tests can toggle a plugin flag (e.g. "used with voxelization") exactly as
// a person ticking its checkbox.

#include "bounce/engine.h"

namespace bounce::viewer {

/// Registers `material` and `light`: `list`, or `NAME|INDEX PARAMETER VALUE`.
void registerSceneCommands(Engine& engine);

}  // namespace bounce::viewer
