#pragma once
#include <functional>
#include <utility>

namespace bounce {

/// RAII handle for a callback registration: the callback is removed when the handle
/// is destroyed or reset. Move-only.
class Subscription {
 public:
  Subscription() = default;
  explicit Subscription(std::function<void()> cancel) : cancel_(std::move(cancel)) {}
  Subscription(Subscription&& other) noexcept : cancel_(std::exchange(other.cancel_, {})) {}
  Subscription& operator=(Subscription&& other) noexcept {
    if (this != &other) {
      reset();
      cancel_ = std::exchange(other.cancel_, {});
    }
    return *this;
  }
  Subscription(const Subscription&) = delete;
  Subscription& operator=(const Subscription&) = delete;
  ~Subscription() { reset(); }

  void reset() {
    if (cancel_) std::exchange(cancel_, {})();
  }
  /// Drops the handle without cancelling (the registration lives as long as its owner).
  void release() { cancel_ = {}; }

 private:
  std::function<void()> cancel_;
};

}  // namespace bounce
