#include "bounce/graph/persistent_resource.h"

namespace bounce {

PersistentTexture::PersistentTexture(std::string name, TextureDesc desc)
    : name_(std::move(name)), desc_(desc) {}
PersistentTexture::~PersistentTexture() = default;

bool PersistentTexture::setDesc(const TextureDesc& desc) {
  if (desc == desc_) return false;
  desc_ = desc;
  ++generation_;
  // The old image is gone: the next user starts from undefined contents.
  storage_->image.reset();
  storage_->state = {};
  return true;
}

void PersistentTexture::setAllocation(std::unique_ptr<gpu::ImageAllocation> allocation) {
  storage_->image = std::move(allocation);
}

PersistentBuffer::PersistentBuffer(std::string name, BufferDesc desc) : name_(std::move(name)), desc_(desc) {}
PersistentBuffer::~PersistentBuffer() = default;

bool PersistentBuffer::setDesc(const BufferDesc& desc) {
  if (desc == desc_) return false;
  desc_ = desc;
  ++generation_;
  storage_->buffer.reset();
  storage_->state = {};
  return true;
}

void PersistentBuffer::setAllocation(std::unique_ptr<gpu::BufferAllocation> allocation) {
  storage_->buffer = std::move(allocation);
}

}  // namespace bounce
