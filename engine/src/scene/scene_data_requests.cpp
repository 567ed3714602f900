#include "bounce/scene/scene_data_requests.h"

#include <algorithm>

namespace bounce {

void SceneDataRequests::addSimplifiedMeshes(std::function<bool()> wanted, OwnerId owner) {
  if (wanted) simplifiedMeshes_.push_back({std::move(wanted), owner});
}

bool SceneDataRequests::simplifiedMeshesWanted() const {
  return std::any_of(simplifiedMeshes_.begin(), simplifiedMeshes_.end(),
                     [](const Request& r) { return r.wanted(); });
}

void SceneDataRequests::removeOwnedBy(OwnerId owner) {
  std::erase_if(simplifiedMeshes_, [owner](const Request& r) { return r.owner == owner; });
}

}  // namespace bounce
