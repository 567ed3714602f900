#pragma once
// The result of compiling a render graph: execution order, culled passes with reasons,
// barriers before each pass, resource lifetimes and memory, and a report.

#include "bounce/graph/render_graph.h"

#include <string>
#include <vector>

namespace bounce {

/// A pipeline barrier (and, for images, layout transition) the executor issues before
/// a pass. `resource` indexes CompiledGraph::resources.
struct Barrier {
  uint32_t resource = 0;
  bool image = true;
  ResourceState before;
  ResourceState after;
};

struct CompiledPass {
  uint32_t node = 0;  ///< index into RenderGraph::passes()
  std::string name;
  Queue queue = Queue::Graphics;
  std::optional<ExtensionPoint> point;
  std::string origin;
  bool executed = false;
  std::string reason;  ///< why it runs, or why it was culled
  std::vector<Barrier> barriers;
  std::vector<uint32_t> unavailableOptionalReads;  ///< resources whose optional read was dropped
};

struct CompiledResource {
  std::string name;
  bool image = true;
  bool imported = false;
  TextureDesc texture;  ///< view-relative sizes resolved
  BufferDesc buffer;
  VkImageUsageFlags imageUsage = 0;
  VkBufferUsageFlags bufferUsage = 0;
  int32_t firstPass = -1;  ///< position in CompiledGraph::passes of first/last executed use
  int32_t lastPass = -1;
  uint64_t bytes = 0;
  /// Transient resources with disjoint lifetimes share a slot (memory aliasing).
  int32_t aliasSlot = -1;
  ResourceState finalState;  ///< state after the frame (written back to persistent resources)
  bool used() const { return firstPass >= 0; }
};

class CompiledGraph {
 public:
  std::vector<CompiledPass> passes;  ///< every pass in execution order, culled ones included
  std::vector<CompiledResource> resources;
  std::vector<std::string> errors;       ///< graph misuse (also reasons of the culled passes)
  std::vector<uint64_t> aliasSlotBytes;  ///< size of each aliasing slot

  size_t executedCount() const;
  const CompiledPass* find(std::string_view passName) const;
  bool executed(std::string_view passName) const;
  /// Bytes of transient resources without and with aliasing, and of imported ones.
  uint64_t transientBytes() const;
  uint64_t aliasedTransientBytes() const;
  uint64_t persistentBytes() const;

  std::string reportText() const;
  std::string reportJson() const;  ///< {"passes": [...], "resources": [...], ...}
};

}  // namespace bounce
