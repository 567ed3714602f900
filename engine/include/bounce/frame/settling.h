#pragma once
// Settling: a technique whose results build up over frames by design (probes that blend
// each update into what they hold, a history that fills in) says so in every frame whose
// results it would still change for a still view. Offline renders (`bounce-render` without
// `--frames`, `bounce-bench`) render until a frame carries no note, as Unreal's Movie Render
// Queue renders warm-up frames; the viewer shows the notes and keeps rendering a still view
// while there are any.
//
//   noteSettling(graph, "MyGi: history 3 of 16 frames");   // in a pass hook, every such frame
//
// A note is a promise that the frames after it move towards the settled result: a technique
// that changes every frame for ever (noise with no accumulation) notes nothing.

#include "bounce/graph/render_graph.h"

#include <string>
#include <vector>

namespace bounce {

/// This frame's notes, one line each ("origin: why").
struct SettlingNotes {
  std::vector<std::string> notes;
};
inline constexpr BlackboardKey<SettlingNotes> kSettlingNotes{"frame.settling"};

/// Adds a note to this frame's graph.
inline void noteSettling(RenderGraph& graph, std::string why) {
  SettlingNotes* notes = graph.blackboard().get(kSettlingNotes);
  if (!notes) notes = &graph.blackboard().set(kSettlingNotes, {});
  notes->notes.push_back(std::move(why));
}

/// The notes hooks left in `graph` (empty: the frame's results are settled).
inline std::vector<std::string> settlingNotes(const RenderGraph& graph) {
  const SettlingNotes* notes = graph.blackboard().get(kSettlingNotes);
  return notes ? notes->notes : std::vector<std::string>{};
}

}  // namespace bounce
