#pragma once
// The frame's render graph: passes declare what they create, read and write; compiling
// orders them, culls every pass whose results nobody needs (or whose condition says the
// scene does not call for it), derives barriers and layout transitions, and computes
// resource lifetimes. The engine builds a new graph every frame by calling its own
// setup code and the plugins' pass hooks in extension-point order.
//
//   graph.addPass("MyGI.DiffuseTracing", Queue::Compute, [&](PassBuilder& b) {
//     auto normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
//     auto out = b.write(b.createTexture("MyGI.Diffuse", TextureDesc::viewSized(fmt)),
//                        Access::StorageWrite);
//     bb.setTexture(channels::IndirectDiffuse, out);
//     b.condition([&] { return anyFlagged ? PassDecision::run("3 materials voxelized")
//                                         : PassDecision::skip("no material is flagged"); });
//     return [=](PassContext& ctx) { /* record commands */ };
//   });

#include "bounce/graph/extension_point.h"
#include "bounce/graph/pass_decision.h"
#include "bounce/graph/persistent_resource.h"
#include "bounce/graph/resource.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

namespace bounce {

class PassContext;  // record-time interface, implemented by the Vulkan executor
using RecordFn = std::function<void(PassContext&)>;
class CompiledGraph;
class RenderGraph;

/// A typed value on the blackboard: per-frame state one hook hands to a later one (a
/// plugin's update hook to its gather hook), gone with the frame's graph, so no
/// member variable carries it over to a frame where the first hook did not run.
///
///   inline constexpr BlackboardKey<UpdatePlan> kUpdatePlan{"MyGi.UpdatePlan"};
///   graph.blackboard().set(kUpdatePlan, plan);                        // AfterGBuffer
///   if (const UpdatePlan* p = graph.blackboard().get(kUpdatePlan)) ...  // IndirectDiffuse
template <class T>
class BlackboardKey {
 public:
  explicit constexpr BlackboardKey(std::string_view name) : name_(name) {}
  constexpr std::string_view name() const { return name_; }

 private:
  std::string_view name_;
};

/// Named handles shared between the engine and plugins within one frame (see channels.h),
/// and typed values (BlackboardKey).
class Blackboard {
 public:
  /// Stores `value` under `key` (replacing what was there) and returns it.
  template <class T>
  T& set(const BlackboardKey<T>& key, T value) {
    auto held = std::make_shared<T>(std::move(value));
    T& ref = *held;
    values_[std::string(key.name())] = {std::move(held), &typeid(T)};
    return ref;
  }
  /// The value under `key`, or null when none was set this frame. Throws
  /// std::logic_error when the name holds a value of another type (two keys, one name).
  template <class T>
  T* get(const BlackboardKey<T>& key) const {
    auto it = values_.find(key.name());
    if (it == values_.end()) return nullptr;
    if (*it->second.type != typeid(T)) throw std::logic_error(typeMismatch(key.name()));
    return static_cast<T*>(it->second.value.get());
  }

  void setTexture(std::string_view name, TextureHandle handle);
  void setBuffer(std::string_view name, BufferHandle handle);
  /// Invalid handle when absent.
  TextureHandle texture(std::string_view name) const;
  BufferHandle buffer(std::string_view name) const;
  bool has(std::string_view name) const;
  std::vector<std::string> names() const;

 private:
  std::map<std::string, TextureHandle, std::less<>> textures_;
  std::map<std::string, BufferHandle, std::less<>> buffers_;
  struct Value {
    std::shared_ptr<void> value;
    const std::type_info* type;
  };
  std::map<std::string, Value, std::less<>> values_;
  static std::string typeMismatch(std::string_view name);
};

/// Declares one pass's resources during setup.
class PassBuilder {
 public:
  TextureHandle createTexture(std::string name, const TextureDesc& desc);
  BufferHandle createBuffer(std::string name, const BufferDesc& desc);

  /// A required read: the pass depends on the producer of that version, and is culled
  /// when that producer is culled (unless the resource is persistent).
  TextureHandle read(TextureHandle handle, Access access);
  BufferHandle read(BufferHandle handle, Access access);
  /// An optional read: ignored when the handle is invalid or its producer is culled;
  /// PassContext::available() then says false at record time.
  TextureHandle readOptional(TextureHandle handle, Access access);
  BufferHandle readOptional(BufferHandle handle, Access access);
  /// A write produces a new version and returns it. The pass depends on the previous
  /// version's producer (its contents are kept), if there is one.
  TextureHandle write(TextureHandle handle, Access access);
  BufferHandle write(BufferHandle handle, Access access);

  /// A condition evaluated when the graph compiles; a pass runs only if all hold.
  void condition(std::function<PassDecision()> decide);
  /// The pass has effects outside the graph (read-back, present): never culled for
  /// lack of readers.
  void sideEffect(std::string why);
  /// What the report says when the pass is culled because nobody reads its results
  /// (default: "nothing reads its results (names)"), e.g. "no pass traces rays".
  void whenUnread(std::string why);
  /// A graphics pass whose geometry shaders read or write its resources: its barriers
  /// also wait for (and make writes visible to) that stage. Other graphics passes sync
  /// only their vertex and fragment shaders.
  void useGeometryShaders();

 private:
  friend class RenderGraph;
  PassBuilder(RenderGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
  RenderGraph& graph_;
  uint32_t pass_;
};

class RenderGraph {
 public:
  RenderGraph() = default;
  RenderGraph(const RenderGraph&) = delete;
  RenderGraph& operator=(const RenderGraph&) = delete;

  /// Adds a pass; `setup` declares its resources and returns its record callback.
  void addPass(std::string name, Queue queue, const std::function<RecordFn(PassBuilder&)>& setup);

  /// Imports persistent state owned by a plugin or the engine for this frame.
  TextureHandle importTexture(PersistentTexture& texture);
  BufferHandle importBuffer(PersistentBuffer& buffer);

  /// Marks a version as a result of the frame (the displayed image, a requested AOV):
  /// culling keeps exactly what these need.
  void markOutput(TextureHandle handle, std::string why);
  void markOutput(BufferHandle handle, std::string why);

  Blackboard& blackboard() { return blackboard_; }
  const Blackboard& blackboard() const { return blackboard_; }

  /// Passes added from now on are attributed to this extension point and origin
  /// ("engine" or a plugin name) in the report.
  void setOrigin(std::optional<ExtensionPoint> point, std::string origin);
  /// The view size that view-relative textures resolve against.
  void setViewExtent(uint32_t width, uint32_t height);

  CompiledGraph compile() const;

  // --- introspection (executor, tests) ------------------------------------------------
  struct Use {
    uint32_t resource;
    uint32_t version;  ///< the version read, or the version produced by a write
    Access access;
    bool write;
    bool optional;
  };
  struct Pass {
    std::string name;
    Queue queue;
    std::optional<ExtensionPoint> point;
    std::string origin;
    std::vector<Use> uses;
    std::vector<std::function<PassDecision()>> conditions;
    std::string sideEffect;        ///< non-empty: never culled for lack of readers
    std::string unreadReason;      ///< report text when culled for lack of readers (empty: default)
    bool geometryShaders = false;  ///< PassBuilder::useGeometryShaders
    RecordFn record;
    std::vector<std::string> errors;  ///< misuse found during setup; the pass is culled
  };
  struct Resource {
    std::string name;
    bool image = true;
    TextureDesc texture;
    BufferDesc buffer;
    PersistentTexture* importedTexture = nullptr;
    PersistentBuffer* importedBuffer = nullptr;
    std::vector<int32_t> producers;  ///< per version: producing pass, or -1 (created/imported)
    bool imported() const { return importedTexture || importedBuffer; }
  };
  const std::vector<Pass>& passes() const { return passes_; }
  const std::vector<Resource>& resources() const { return resources_; }
  uint32_t viewWidth() const { return viewWidth_; }
  uint32_t viewHeight() const { return viewHeight_; }

 private:
  friend class PassBuilder;
  template <class Tag>
  ResourceHandle<Tag> use(uint32_t pass, ResourceHandle<Tag> handle, Access access, bool write,
                          bool optional);
  uint32_t addResource(Resource resource);

  std::vector<Pass> passes_;
  std::vector<Resource> resources_;
  std::vector<std::pair<uint32_t, uint32_t>> outputs_;  // resource, version
  std::vector<std::string> outputReasons_;
  Blackboard blackboard_;
  std::optional<ExtensionPoint> point_;
  std::string origin_ = "engine";
  uint32_t viewWidth_ = 1, viewHeight_ = 1;
  friend class GraphCompiler;
};

}  // namespace bounce
