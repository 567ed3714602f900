#pragma once
// GPU state that lives across frames (clip-maps, probe atlases, history buffers). A
// plugin owns one of these and imports it into each frame's graph; its update passes
// are then culled like any other when nothing reads it, and the graph carries its
// synchronization state from one frame to the next.

#include "bounce/graph/resource.h"

#include <memory>
#include <string>

namespace bounce {

namespace gpu {
/// Device memory behind a persistent resource; the Vulkan layer derives from these.
struct ImageAllocation {
  virtual ~ImageAllocation() = default;
};
struct BufferAllocation {
  virtual ~BufferAllocation() = default;
};
}  // namespace gpu

class PersistentTexture {
 public:
  PersistentTexture(std::string name, TextureDesc desc);
  ~PersistentTexture();
  PersistentTexture(const PersistentTexture&) = delete;
  PersistentTexture& operator=(const PersistentTexture&) = delete;

  const std::string& name() const { return name_; }
  const TextureDesc& desc() const { return desc_; }
  /// Changes the description; the GPU image is re-created (contents undefined) the next
  /// time a graph that imports it executes. Returns true when something changed.
  bool setDesc(const TextureDesc& desc);
  /// Increases on every setDesc() that changed something.
  uint64_t generation() const { return generation_; }

  /// Synchronization state after the last executed use (maintained by the graph).
  const ResourceState& state() const { return state_; }
  void setState(const ResourceState& state) { state_ = state; }

  /// The device's allocation, created lazily by the graph executor.
  gpu::ImageAllocation* allocation() const { return allocation_.get(); }
  void setAllocation(std::unique_ptr<gpu::ImageAllocation> allocation);

 private:
  std::string name_;
  TextureDesc desc_;
  uint64_t generation_ = 1;
  ResourceState state_;
  std::unique_ptr<gpu::ImageAllocation> allocation_;
};

class PersistentBuffer {
 public:
  PersistentBuffer(std::string name, BufferDesc desc);
  ~PersistentBuffer();
  PersistentBuffer(const PersistentBuffer&) = delete;
  PersistentBuffer& operator=(const PersistentBuffer&) = delete;

  const std::string& name() const { return name_; }
  const BufferDesc& desc() const { return desc_; }
  bool setDesc(const BufferDesc& desc);
  uint64_t generation() const { return generation_; }
  const ResourceState& state() const { return state_; }
  void setState(const ResourceState& state) { state_ = state; }
  gpu::BufferAllocation* allocation() const { return allocation_.get(); }
  void setAllocation(std::unique_ptr<gpu::BufferAllocation> allocation);

 private:
  std::string name_;
  BufferDesc desc_;
  uint64_t generation_ = 1;
  ResourceState state_;
  std::unique_ptr<gpu::BufferAllocation> allocation_;
};

}  // namespace bounce
