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

/// Where a persistent resource's device memory and synchronization state live. Shared
/// so that the executor that created the allocation can free it when it (and its
/// device) goes away first, whatever order an application destroys things in.
struct PersistentStorage {
  std::unique_ptr<gpu::ImageAllocation> image;
  std::unique_ptr<gpu::BufferAllocation> buffer;
  ResourceState state;
};

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
  const ResourceState& state() const { return storage_->state; }
  void setState(const ResourceState& state) { storage_->state = state; }

  /// The device's allocation, created lazily by the graph executor.
  gpu::ImageAllocation* allocation() const { return storage_->image.get(); }
  void setAllocation(std::unique_ptr<gpu::ImageAllocation> allocation);
  std::weak_ptr<PersistentStorage> storage() const { return storage_; }

 private:
  std::string name_;
  TextureDesc desc_;
  uint64_t generation_ = 1;
  std::shared_ptr<PersistentStorage> storage_ = std::make_shared<PersistentStorage>();
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
  const ResourceState& state() const { return storage_->state; }
  void setState(const ResourceState& state) { storage_->state = state; }
  gpu::BufferAllocation* allocation() const { return storage_->buffer.get(); }
  void setAllocation(std::unique_ptr<gpu::BufferAllocation> allocation);
  std::weak_ptr<PersistentStorage> storage() const { return storage_; }

 private:
  std::string name_;
  BufferDesc desc_;
  uint64_t generation_ = 1;
  std::shared_ptr<PersistentStorage> storage_ = std::make_shared<PersistentStorage>();
};

}  // namespace bounce
