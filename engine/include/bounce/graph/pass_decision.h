#pragma once
#include <string>

namespace bounce {

/// Whether a pass is needed this frame, and why. Passes declare conditions evaluated
/// against the scene and variables each frame ("no material is flagged for
/// voxelization", "scene unchanged since the last voxelization"); the graph report
/// shows the reason for every pass that runs or is culled.
struct PassDecision {
  bool needed = true;
  std::string reason;

  static PassDecision run(std::string why) { return {true, std::move(why)}; }
  static PassDecision skip(std::string why) { return {false, std::move(why)}; }
};

}  // namespace bounce
