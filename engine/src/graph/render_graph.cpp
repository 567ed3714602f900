#include "bounce/graph/render_graph.h"

#include <fmt/format.h>

namespace bounce {

// --- Blackboard -----------------------------------------------------------------------

void Blackboard::setTexture(std::string_view name, TextureHandle handle) {
  textures_.insert_or_assign(std::string(name), handle);
}
void Blackboard::setBuffer(std::string_view name, BufferHandle handle) {
  buffers_.insert_or_assign(std::string(name), handle);
}
TextureHandle Blackboard::texture(std::string_view name) const {
  auto it = textures_.find(name);
  return it == textures_.end() ? TextureHandle{} : it->second;
}
BufferHandle Blackboard::buffer(std::string_view name) const {
  auto it = buffers_.find(name);
  return it == buffers_.end() ? BufferHandle{} : it->second;
}
bool Blackboard::has(std::string_view name) const {
  return textures_.count(name) || buffers_.count(name) || values_.count(name);
}
std::vector<std::string> Blackboard::names() const {
  std::vector<std::string> out;
  for (const auto& [n, h] : textures_) out.push_back(n);
  for (const auto& [n, h] : buffers_) out.push_back(n);
  for (const auto& [n, v] : values_) out.push_back(n);
  return out;
}
std::string Blackboard::typeMismatch(std::string_view name) {
  return fmt::format("blackboard value '{}' was set with another type than this key's", name);
}

// --- PassBuilder ----------------------------------------------------------------------

TextureHandle PassBuilder::createTexture(std::string name, const TextureDesc& desc) {
  RenderGraph::Resource r;
  r.name = std::move(name);
  r.image = true;
  r.texture = desc;
  r.producers = {-1};
  return TextureHandle{graph_.addResource(std::move(r)), 0};
}

BufferHandle PassBuilder::createBuffer(std::string name, const BufferDesc& desc) {
  RenderGraph::Resource r;
  r.name = std::move(name);
  r.image = false;
  r.buffer = desc;
  r.producers = {-1};
  return BufferHandle{graph_.addResource(std::move(r)), 0};
}

TextureHandle PassBuilder::read(TextureHandle h, Access a) { return graph_.use(pass_, h, a, false, false); }
BufferHandle PassBuilder::read(BufferHandle h, Access a) { return graph_.use(pass_, h, a, false, false); }
TextureHandle PassBuilder::readOptional(TextureHandle h, Access a) {
  return graph_.use(pass_, h, a, false, true);
}
BufferHandle PassBuilder::readOptional(BufferHandle h, Access a) {
  return graph_.use(pass_, h, a, false, true);
}
TextureHandle PassBuilder::write(TextureHandle h, Access a) { return graph_.use(pass_, h, a, true, false); }
BufferHandle PassBuilder::write(BufferHandle h, Access a) { return graph_.use(pass_, h, a, true, false); }

void PassBuilder::condition(std::function<PassDecision()> decide) {
  graph_.passes_[pass_].conditions.push_back(std::move(decide));
}

void PassBuilder::sideEffect(std::string why) { graph_.passes_[pass_].sideEffect = std::move(why); }

void PassBuilder::whenUnread(std::string why) { graph_.passes_[pass_].unreadReason = std::move(why); }

void PassBuilder::useGeometryShaders() { graph_.passes_[pass_].geometryShaders = true; }

// --- RenderGraph ----------------------------------------------------------------------

uint32_t RenderGraph::addResource(Resource resource) {
  resources_.push_back(std::move(resource));
  return uint32_t(resources_.size() - 1);
}

template <class Tag>
ResourceHandle<Tag> RenderGraph::use(uint32_t pass, ResourceHandle<Tag> h, Access access, bool write,
                                     bool optional) {
  Pass& p = passes_[pass];
  constexpr bool image = std::is_same_v<Tag, TextureTag>;
  if (!h.valid()) {
    if (!optional)
      p.errors.push_back(
          fmt::format("{} an invalid {} handle", write ? "writes" : "reads", image ? "texture" : "buffer"));
    return h;
  }
  if (h.resource >= resources_.size() || resources_[h.resource].image != image ||
      h.version >= resources_[h.resource].producers.size()) {
    p.errors.push_back("uses a handle that does not belong to this graph");
    return {};
  }
  Resource& r = resources_[h.resource];
  if (isWrite(access) != write) {
    p.errors.push_back(fmt::format("declares '{}' {} with the {} access '{}'", r.name,
                                   write ? "written" : "read", isWrite(access) ? "write" : "read",
                                   accessName(access)));
  }
  if (!write) {
    p.uses.push_back({h.resource, h.version, access, false, optional});
    return h;
  }
  // Versions form a chain: writing anything but the latest would fork the resource's
  // history, and readers of the newer version would see neither write reliably.
  if (h.version + 1 != r.producers.size()) {
    p.errors.push_back(fmt::format("writes version {} of '{}', but version {} already exists", h.version,
                                   r.name, r.producers.size() - 1));
    return h;
  }
  // The pass depends on the previous contents: record the version it starts from...
  p.uses.push_back({h.resource, h.version, access, false, false});
  // ...and the version it produces.
  r.producers.push_back(int32_t(pass));
  uint32_t produced = uint32_t(r.producers.size() - 1);
  p.uses.push_back({h.resource, produced, access, true, false});
  return ResourceHandle<Tag>{h.resource, produced};
}

template TextureHandle RenderGraph::use(uint32_t, TextureHandle, Access, bool, bool);
template BufferHandle RenderGraph::use(uint32_t, BufferHandle, Access, bool, bool);

void RenderGraph::addPass(std::string name, Queue queue, const std::function<RecordFn(PassBuilder&)>& setup) {
  Pass p;
  p.name = std::move(name);
  p.queue = queue;
  p.point = point_;
  p.origin = origin_;
  passes_.push_back(std::move(p));
  uint32_t index = uint32_t(passes_.size() - 1);
  PassBuilder builder(*this, index);
  RecordFn record = setup(builder);
  passes_[index].record = std::move(record);
}

TextureHandle RenderGraph::importTexture(PersistentTexture& texture) {
  for (uint32_t i = 0; i < resources_.size(); ++i)
    if (resources_[i].importedTexture == &texture)
      return TextureHandle{i, uint32_t(resources_[i].producers.size() - 1)};
  Resource r;
  r.name = texture.name();
  r.image = true;
  r.texture = texture.desc();
  r.importedTexture = &texture;
  r.producers = {-1};
  return TextureHandle{addResource(std::move(r)), 0};
}

BufferHandle RenderGraph::importBuffer(PersistentBuffer& buffer) {
  for (uint32_t i = 0; i < resources_.size(); ++i)
    if (resources_[i].importedBuffer == &buffer)
      return BufferHandle{i, uint32_t(resources_[i].producers.size() - 1)};
  Resource r;
  r.name = buffer.name();
  r.image = false;
  r.buffer = buffer.desc();
  r.importedBuffer = &buffer;
  r.producers = {-1};
  return BufferHandle{addResource(std::move(r)), 0};
}

void RenderGraph::markOutput(TextureHandle h, std::string why) {
  if (!h.valid()) return;
  outputs_.emplace_back(h.resource, h.version);
  outputReasons_.push_back(std::move(why));
}

void RenderGraph::markOutput(BufferHandle h, std::string why) {
  if (!h.valid()) return;
  outputs_.emplace_back(h.resource, h.version);
  outputReasons_.push_back(std::move(why));
}

void RenderGraph::setOrigin(std::optional<ExtensionPoint> point, std::string origin) {
  point_ = point;
  origin_ = std::move(origin);
}

void RenderGraph::setViewExtent(uint32_t width, uint32_t height) {
  viewWidth_ = std::max(1u, width);
  viewHeight_ = std::max(1u, height);
}

}  // namespace bounce
