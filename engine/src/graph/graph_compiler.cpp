// Compiles a RenderGraph: culling, lifetimes, aliasing and barriers.
//
// Order: passes execute in declaration order. That order is dependency-consistent by
// construction — a handle names a version that already exists when a pass declares
// it, so every producer precedes its readers — and the engine declares passes in
// extension-point order, which gives plugins a deterministic place in the frame.

#include "bounce/graph/compiled_graph.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace bounce {

class GraphCompiler {
 public:
  explicit GraphCompiler(const RenderGraph& g) : g_(g), n_(g.passes_.size()) {}

  CompiledGraph run() {
    out_.passes.resize(n_);
    alive_.assign(n_, true);
    live_.assign(n_, false);
    dropped_.assign(n_, {});
    runReasons_.assign(n_, {});
    liveReasons_.assign(n_, {});
    for (size_t i = 0; i < n_; ++i) {
      const auto& p = g_.passes_[i];
      CompiledPass& cp = out_.passes[i];
      cp.node = uint32_t(i);
      cp.name = p.name;
      cp.queue = p.queue;
      cp.point = p.point;
      cp.origin = p.origin;
    }
    cullInvalidAndConditions();
    cullMissingInputs();
    cullUnread();
    for (size_t i = 0; i < n_; ++i) {
      CompiledPass& cp = out_.passes[i];
      cp.executed = alive_[i] && live_[i];
      if (cp.executed) {
        std::string why = runReasons_[i];
        if (!liveReasons_[i].empty()) why += (why.empty() ? "" : "; ") + liveReasons_[i];
        cp.reason = why;
      } else if (cp.reason.empty()) {
        cp.reason = unreadReason(i);
      }
    }
    resolveResources();
    assignAliasSlots();
    deriveBarriers();
    return std::move(out_);
  }

 private:
  using Use = RenderGraph::Use;

  void cull(size_t pass, std::string reason) {
    alive_[pass] = false;
    out_.passes[pass].reason = std::move(reason);
  }

  void cullInvalidAndConditions() {
    for (size_t i = 0; i < n_; ++i) {
      const auto& p = g_.passes_[i];
      if (!p.errors.empty()) {
        for (const std::string& e : p.errors) out_.errors.push_back(fmt::format("pass '{}' {}", p.name, e));
        cull(i, fmt::format("invalid: {}", fmt::join(p.errors, "; ")));
        continue;
      }
      std::vector<std::string> runs, skips;
      for (const auto& condition : p.conditions) {
        PassDecision d = condition();
        (d.needed ? runs : skips).push_back(d.reason);
      }
      if (!skips.empty())
        cull(i, fmt::format("{}", fmt::join(skips, "; ")));
      else
        runReasons_[i] = fmt::format("{}", fmt::join(runs, "; "));
    }
  }

  // A persistent resource keeps its contents when a write to it is culled, so readers of
  // that version really read the latest version an executed pass produced.
  int32_t effectiveProducer(uint32_t resource, uint32_t version) const {
    const auto& r = g_.resources_[resource];
    int32_t producer = r.producers[version];
    while (r.imported() && producer >= 0 && !alive_[size_t(producer)] && version > 0)
      producer = r.producers[--version];
    if (r.imported() && producer >= 0 && !alive_[size_t(producer)]) producer = -1;
    return producer;
  }

  void cullMissingInputs() {
    for (size_t i = 0; i < n_; ++i) {
      if (!alive_[i]) continue;
      const auto& p = g_.passes_[i];
      for (size_t u = 0; u < p.uses.size(); ++u) {
        const Use& use = p.uses[u];
        if (use.write) continue;
        const auto& r = g_.resources_[use.resource];
        const bool explicitRead = !isWrite(use.access);  // not the base of a write
        int32_t producer = r.producers[use.version];
        if (producer < 0) {
          if (!r.imported() && explicitRead) {
            if (use.optional) {
              dropped_[i].push_back(u);
              continue;
            }
            std::string e = fmt::format("reads '{}' before any pass writes it", r.name);
            out_.errors.push_back(fmt::format("pass '{}' {}", p.name, e));
            cull(i, "invalid: " + e);
            break;
          }
          continue;
        }
        if (alive_[size_t(producer)] || r.imported()) continue;
        if (use.optional) {
          dropped_[i].push_back(u);
          continue;
        }
        cull(i,
             fmt::format("needs '{}' from '{}', which is culled", r.name, g_.passes_[size_t(producer)].name));
        break;
      }
    }
  }

  bool isDropped(size_t pass, size_t use) const {
    return std::find(dropped_[pass].begin(), dropped_[pass].end(), use) != dropped_[pass].end();
  }

  void cullUnread() {
    std::vector<size_t> work;
    auto markLive = [&](size_t pass, std::string why) {
      if (!alive_[pass] || live_[pass]) return;
      live_[pass] = true;
      liveReasons_[pass] = std::move(why);
      work.push_back(pass);
    };
    for (size_t i = 0; i < n_; ++i)
      if (!g_.passes_[i].sideEffect.empty()) markLive(i, "side effect: " + g_.passes_[i].sideEffect);
    for (size_t o = 0; o < g_.outputs_.size(); ++o) {
      auto [res, ver] = g_.outputs_[o];
      const auto& r = g_.resources_[res];
      int32_t producer = effectiveProducer(res, ver);
      if (producer >= 0 && alive_[size_t(producer)]) {
        markLive(size_t(producer),
                 fmt::format("produces the output '{}' ({})", r.name, g_.outputReasons_[o]));
      } else if (!r.imported()) {
        int32_t declared = r.producers[ver];
        out_.errors.push_back(declared >= 0 ? fmt::format("output '{}' is not produced: '{}' is culled ({})",
                                                          r.name, g_.passes_[size_t(declared)].name,
                                                          out_.passes[size_t(declared)].reason)
                                            : fmt::format("output '{}' is never written", r.name));
      }
    }
    while (!work.empty()) {
      size_t p = work.back();
      work.pop_back();
      const auto& pass = g_.passes_[p];
      for (size_t u = 0; u < pass.uses.size(); ++u) {
        const Use& use = pass.uses[u];
        if (use.write || isDropped(p, u)) continue;
        int32_t producer = effectiveProducer(use.resource, use.version);
        if (producer >= 0 && size_t(producer) != p)
          markLive(size_t(producer),
                   fmt::format("'{}' is read by '{}'", g_.resources_[use.resource].name, pass.name));
      }
    }
  }

  std::string unreadReason(size_t pass) const {
    if (!g_.passes_[pass].unreadReason.empty()) return g_.passes_[pass].unreadReason;
    std::vector<std::string> written;
    for (const Use& u : g_.passes_[pass].uses)
      if (u.write) {
        const std::string& name = g_.resources_[u.resource].name;
        if (std::find(written.begin(), written.end(), name) == written.end()) written.push_back(name);
      }
    if (written.empty()) return "nothing reads its results (it writes nothing)";
    return fmt::format("nothing reads its results ({})", fmt::join(written, ", "));
  }

  void resolveResources() {
    out_.resources.resize(g_.resources_.size());
    for (size_t i = 0; i < g_.resources_.size(); ++i) {
      const auto& r = g_.resources_[i];
      CompiledResource& cr = out_.resources[i];
      cr.name = r.name;
      cr.image = r.image;
      cr.imported = r.imported();
      cr.texture = r.texture;
      cr.buffer = r.buffer;
      if (r.image && r.texture.viewScale > 0.0f) {
        cr.texture.width = std::max(1u, uint32_t(std::ceil(float(g_.viewWidth_) * r.texture.viewScale)));
        cr.texture.height = std::max(1u, uint32_t(std::ceil(float(g_.viewHeight_) * r.texture.viewScale)));
      }
      if (r.image) {
        // A mip chain ends at 1×1; a small view cannot hold all the mips a pass asked for.
        const uint32_t largest =
            std::max({cr.texture.width, cr.texture.height,
                      cr.texture.type == TextureType::Tex3D ? cr.texture.depth : 1u, 1u});
        cr.texture.mips =
            std::clamp(cr.texture.mips, 1u, uint32_t(std::floor(std::log2(double(largest)))) + 1);
      }
      cr.bytes = r.image ? textureBytes(cr.texture) : r.buffer.size;
    }
    for (size_t i = 0; i < n_; ++i) {
      if (!out_.passes[i].executed) continue;
      const auto& p = g_.passes_[i];
      for (size_t u = 0; u < p.uses.size(); ++u) {
        const Use& use = p.uses[u];
        if (isDropped(i, u)) {
          out_.passes[i].unavailableOptionalReads.push_back(use.resource);
          continue;
        }
        CompiledResource& cr = out_.resources[use.resource];
        if (cr.firstPass < 0) cr.firstPass = int32_t(i);
        cr.lastPass = int32_t(i);
        addUsage(cr, use.access);
      }
    }
  }

  static void addUsage(CompiledResource& cr, Access a) {
    if (cr.image) {
      switch (a) {
        case Access::Sampled:
          cr.imageUsage |= VK_IMAGE_USAGE_SAMPLED_BIT;
          break;
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite:
          cr.imageUsage |= VK_IMAGE_USAGE_STORAGE_BIT;
          break;
        case Access::ColorAttachment:
          cr.imageUsage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
          break;
        case Access::DepthAttachment:
        case Access::DepthRead:
          cr.imageUsage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
          break;
        case Access::TransferSrc:
          cr.imageUsage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
          break;
        case Access::TransferDst:
          cr.imageUsage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
          break;
        default:
          break;
      }
    } else {
      switch (a) {
        case Access::StorageRead:
        case Access::StorageWrite:
        case Access::StorageReadWrite:
          cr.bufferUsage |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
          break;
        case Access::Uniform:
          cr.bufferUsage |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
          break;
        case Access::Vertex:
          cr.bufferUsage |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
          break;
        case Access::Index:
          cr.bufferUsage |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
          break;
        case Access::Indirect:
          cr.bufferUsage |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
          break;
        case Access::TransferSrc:
          cr.bufferUsage |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
          break;
        case Access::TransferDst:
          cr.bufferUsage |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
          break;
        default:
          break;
      }
    }
  }

  // Greedy interval packing: transient resources whose lifetimes do not overlap share
  // memory. Images and buffers never share a slot (their memory requirements differ).
  void assignAliasSlots() {
    std::vector<size_t> order;
    for (size_t i = 0; i < out_.resources.size(); ++i)
      if (!out_.resources[i].imported && out_.resources[i].used()) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return out_.resources[a].firstPass < out_.resources[b].firstPass;
    });
    struct Slot {
      bool image;
      int32_t lastPass;
    };
    std::vector<Slot> slots;
    for (size_t i : order) {
      CompiledResource& r = out_.resources[i];
      int32_t best = -1;
      for (size_t s = 0; s < slots.size(); ++s) {
        if (slots[s].image != r.image || slots[s].lastPass >= r.firstPass) continue;
        // Prefer the smallest slot that already fits, else the one that grows least.
        auto cost = [&](size_t k) {
          uint64_t b = out_.aliasSlotBytes[k];
          return b >= r.bytes ? b - r.bytes : (r.bytes - b) * 2;
        };
        if (best < 0 || cost(s) < cost(size_t(best))) best = int32_t(s);
      }
      if (best < 0) {
        slots.push_back({r.image, -1});
        out_.aliasSlotBytes.push_back(0);
        best = int32_t(slots.size() - 1);
      }
      slots[size_t(best)].lastPass = r.lastPass;
      out_.aliasSlotBytes[size_t(best)] = std::max(out_.aliasSlotBytes[size_t(best)], r.bytes);
      r.aliasSlot = best;
    }
  }

  struct Tracked {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 writeStages = 0;
    VkAccessFlags2 writeAccess = 0;
    VkPipelineStageFlags2 readStages = 0;     // stages that read since the last write
    VkPipelineStageFlags2 visibleStages = 0;  // stages the last write was made visible to
    VkAccessFlags2 visibleAccess = 0;
    VkAccessFlags2 lastAccess = 0;
  };

  void deriveBarriers() {
    std::vector<Tracked> state(g_.resources_.size());
    for (size_t i = 0; i < g_.resources_.size(); ++i) {
      const auto& r = g_.resources_[i];
      // Persistent resources start where the previous frame left them; treat whatever it
      // did last as a write so the first use this frame waits for it.
      ResourceState s = r.importedTexture  ? r.importedTexture->state()
                        : r.importedBuffer ? r.importedBuffer->state()
                                           : ResourceState{};
      state[i].layout = s.layout;
      state[i].writeStages = s.stages;
      state[i].writeAccess = s.access & kWriteAccessMask;
    }
    // A transient resource sharing a memory slot with an earlier one must not start
    // writing before that one's last users finish: its first barrier waits for them.
    std::vector<int32_t> slotOccupant(out_.aliasSlotBytes.size(), -1);
    std::vector<bool> touched(g_.resources_.size(), false);
    for (size_t i = 0; i < n_; ++i) {
      CompiledPass& cp = out_.passes[i];
      if (!cp.executed) continue;
      const auto& p = g_.passes_[i];
      for (const Use& use : p.uses) {
        if (touched[use.resource]) continue;
        touched[use.resource] = true;
        const int32_t slot = out_.resources[use.resource].aliasSlot;
        if (slot < 0) continue;
        if (int32_t prev = slotOccupant[size_t(slot)]; prev >= 0) {
          const Tracked& before = state[size_t(prev)];
          state[use.resource].writeStages = before.writeStages | before.readStages;
          state[use.resource].writeAccess = before.writeAccess;
          state[use.resource].layout = VK_IMAGE_LAYOUT_UNDEFINED;  // contents are discarded
        }
        slotOccupant[size_t(slot)] = int32_t(use.resource);
      }
      // Combine every use of a resource within the pass into one state.
      std::vector<std::pair<uint32_t, ResourceState>> combined;
      std::vector<bool> writes;
      for (size_t u = 0; u < p.uses.size(); ++u) {
        if (isDropped(i, u)) continue;
        const Use& use = p.uses[u];
        const auto& cr = out_.resources[use.resource];
        ResourceState s = accessState(use.access, p.queue, cr.image,
                                      cr.image && isDepthFormat(cr.texture.format), p.geometryShaders);
        auto it = std::find_if(combined.begin(), combined.end(),
                               [&](const auto& c) { return c.first == use.resource; });
        if (it == combined.end()) {
          combined.emplace_back(use.resource, s);
          writes.push_back(isWrite(use.access));
        } else {
          size_t k = size_t(it - combined.begin());
          it->second.stages |= s.stages;
          it->second.access |= s.access;
          // Two different layouts in one pass (sampled and storage): GENERAL serves both.
          if (it->second.layout != s.layout) it->second.layout = VK_IMAGE_LAYOUT_GENERAL;
          writes[k] = writes[k] || isWrite(use.access);
        }
      }
      for (size_t k = 0; k < combined.size(); ++k) {
        auto [res, want] = combined[k];
        Tracked& t = state[res];
        const bool image = out_.resources[res].image;
        Barrier b{res, image, {}, want};
        bool needed = false;
        if (image && want.layout != t.layout) {
          needed = true;  // layout transition; waits for all previous uses
          b.before = {t.writeStages | t.readStages, t.writeAccess, t.layout};
        } else if (writes[k] && (t.readStages || t.writeStages)) {
          needed = true;  // write after read (execution dependency) or after write
          b.before = {t.writeStages | t.readStages, t.writeAccess, t.layout};
        } else if (!writes[k] && t.writeStages &&
                   ((want.stages & ~t.visibleStages) || (want.access & ~t.visibleAccess))) {
          needed = true;  // read after write, not yet visible to this stage/access
          b.before = {t.writeStages, t.writeAccess, t.layout};
        }
        if (needed) {
          if (!image) b.before.layout = b.after.layout = VK_IMAGE_LAYOUT_UNDEFINED;
          cp.barriers.push_back(b);
        }
        if (writes[k]) {
          t.writeStages = want.stages;
          t.writeAccess = want.access & kWriteAccessMask;
          t.readStages = 0;
          t.visibleStages = 0;
          t.visibleAccess = 0;
        } else {
          t.readStages |= want.stages;
          if (needed) {
            t.visibleStages |= want.stages;
            t.visibleAccess |= want.access;
          }
        }
        t.layout = want.layout;
        t.lastAccess = want.access;
        CompiledResource& cr = out_.resources[res];
        cr.finalState = {writes[k] ? want.stages : (t.readStages | t.writeStages),
                         writes[k] ? want.access : t.lastAccess, t.layout};
      }
    }
  }

  static constexpr VkAccessFlags2 kWriteAccessMask =
      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT |
      VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;

  const RenderGraph& g_;
  size_t n_;
  CompiledGraph out_;
  std::vector<bool> alive_;  // not culled by errors, conditions or missing inputs
  std::vector<bool> live_;   // something needs its results
  std::vector<std::vector<size_t>> dropped_;
  std::vector<std::string> runReasons_;
  std::vector<std::string> liveReasons_;
};

CompiledGraph RenderGraph::compile() const { return GraphCompiler(*this).run(); }

}  // namespace bounce
