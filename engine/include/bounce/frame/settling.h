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

#include <memory>
#include <string>
#include <vector>

namespace bounce {

/// This frame's notes, one line each ("origin: why").
struct SettlingNotes {
  std::vector<std::string> notes;
};
inline constexpr BlackboardKey<SettlingNotes> kSettlingNotes{"frame.settling"};
/// Those read-backs add (lateSettlingNotes).
inline constexpr BlackboardKey<std::shared_ptr<SettlingNotes>> kLateSettlingNotes{"frame.settling.late"};

/// Adds a note to this frame's graph.
inline void noteSettling(RenderGraph& graph, std::string why) {
  SettlingNotes* notes = graph.blackboard().get(kSettlingNotes);
  if (!notes) notes = &graph.blackboard().set(kSettlingNotes, {});
  notes->notes.push_back(std::move(why));
}

/// Notes that only the frame's GPU results can tell: a pass reads something back and finds
/// this frame's results incomplete (a list that overflowed, to be redone next frame with
/// room). Take the list while building the graph and add to it from the ReadbackFn, which
/// runs once the frame's GPU work has completed; the frame's notes include them.
///
///   auto late = lateSettlingNotes(graph);                       // in the pass's setup
///   ctx.readback(h, [late](auto bytes) { if (...) late->notes.push_back("MyGi: ..."); });
inline std::shared_ptr<SettlingNotes> lateSettlingNotes(RenderGraph& graph) {
  std::shared_ptr<SettlingNotes>* late = graph.blackboard().get(kLateSettlingNotes);
  if (!late) late = &graph.blackboard().set(kLateSettlingNotes, std::make_shared<SettlingNotes>());
  return *late;
}

/// The notes hooks left in `graph` (empty: the frame's results are settled), and once the
/// frame has run, those its read-backs added (lateSettlingNotes).
inline std::vector<std::string> settlingNotes(const RenderGraph& graph) {
  const SettlingNotes* notes = graph.blackboard().get(kSettlingNotes);
  std::vector<std::string> all = notes ? notes->notes : std::vector<std::string>{};
  if (const std::shared_ptr<SettlingNotes>* late = graph.blackboard().get(kLateSettlingNotes); late && *late)
    all.insert(all.end(), (*late)->notes.begin(), (*late)->notes.end());
  return all;
}

}  // namespace bounce
