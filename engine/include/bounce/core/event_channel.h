#pragma once
// A list of callbacks for one kind of event, each tagged with who registered it. The
// RAII Subscription removes one callback; removeOwnedBy removes all of an owner's (a
// plugin being unloaded), whichever comes first.

#include "bounce/core/owner.h"
#include "bounce/core/subscription.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace bounce {

template <class Event>
class EventChannel {
 public:
  using Callback = std::function<void(const Event&)>;

  Subscription subscribe(Callback callback, OwnerId owner = kEngineOwner) {
    const uint64_t id = state_->nextId++;
    state_->entries.push_back({id, owner, std::move(callback)});
    // Weak: a subscription may outlive the channel (a plugin object destroyed after the
    // engine's registries) and must then do nothing.
    return Subscription([weak = std::weak_ptr<State>(state_), id] {
      if (auto s = weak.lock()) std::erase_if(s->entries, [id](const Entry& e) { return e.id == id; });
    });
  }

  /// Calls every callback registered now; callbacks may subscribe or unsubscribe while
  /// it runs (they act on the next emit).
  void emit(const Event& event) const {
    const std::vector<Entry> entries = state_->entries;
    for (const Entry& e : entries) e.callback(event);
  }

  void removeOwnedBy(OwnerId owner) {
    std::erase_if(state_->entries, [owner](const Entry& e) { return e.owner == owner; });
  }
  size_t size() const { return state_->entries.size(); }

 private:
  struct Entry {
    uint64_t id;
    OwnerId owner;
    Callback callback;
  };
  struct State {
    std::vector<Entry> entries;
    uint64_t nextId = 1;
  };
  std::shared_ptr<State> state_ = std::make_shared<State>();
};

}  // namespace bounce
