#pragma once
// A fingerprint of values (settings, revisions) for "has anything this depends on
// changed since last frame?": FNV-1a over each value's std::hash. Plugins keep the last
// one and redo their cached work when it differs.

#include <cstdint>
#include <functional>

namespace bounce {

class ValueHash {
 public:
  template <class T>
  ValueHash& add(const T& value) {
    key_ = (key_ ^ std::hash<T>{}(value)) * 1099511628211ull;  // FNV-1a prime
    return *this;
  }
  uint64_t value() const { return key_; }

 private:
  uint64_t key_ = 1469598103934665603ull;  // FNV-1a offset basis
};

}  // namespace bounce
