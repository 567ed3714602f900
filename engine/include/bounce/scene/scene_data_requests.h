#pragma once
// Scene data the engine prepares only when a plugin asks for it, so a scene rendered
// without that plugin (or with its feature off) pays nothing. Each request is a predicate
// evaluated every frame before the GPU scene is updated.

#include "bounce/core/owner.h"

#include <functional>
#include <vector>

namespace bounce {

class SceneDataRequests {
 public:
  /// Simplified index lists (meshoptimizer, up to three per primitive, coarsest within a
  /// world error: PassContext::drawScene's maxWorldError) are built while `wanted` says so.
  void addSimplifiedMeshes(std::function<bool()> wanted, OwnerId owner);
  /// True when any request holds this frame.
  bool simplifiedMeshesWanted() const;
  void removeOwnedBy(OwnerId owner);

 private:
  struct Request {
    std::function<bool()> wanted;
    OwnerId owner;
  };
  std::vector<Request> simplifiedMeshes_;
};

}  // namespace bounce
