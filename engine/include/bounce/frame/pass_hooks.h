#pragma once
// Pass hooks: how plugins (and the engine) add passes to the frame at extension points.

#include "bounce/core/owner.h"
#include "bounce/frame/frame_context.h"
#include "bounce/graph/extension_point.h"
#include "bounce/graph/render_graph.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

struct PassHookDesc {
  std::string name;  ///< e.g. "Ambient.Irradiance" (for the report and errors)
  ExtensionPoint point = ExtensionPoint::IndirectDiffuse;
  int order = 0;  ///< among hooks at the same point, lower runs first
  /// Adds this hook's passes to the frame's graph.
  std::function<void(RenderGraph&, const FrameContext&)> setup;
};

class PassHookRegistry {
 public:
  struct Hook {
    PassHookDesc desc;
    OwnerId owner;
    std::string origin;     ///< plugin name, or "engine"
    std::string technique;  ///< non-empty: runs only while this GI technique is selected
    uint64_t sequence;      ///< registration order, the tie-break after `order`
  };

  void add(PassHookDesc desc, OwnerId owner, std::string origin, std::string technique);
  /// Hooks at `point` that run with `technique` selected, in order.
  std::vector<const Hook*> at(ExtensionPoint point, std::string_view technique) const;
  const std::vector<Hook>& all() const { return hooks_; }
  void removeOwnedBy(OwnerId owner);

 private:
  std::vector<Hook> hooks_;
  uint64_t sequence_ = 0;
};

/// A debug visualisation a plugin offers (the viewer lists them). Selecting it runs
/// `activate` in the console; leaving it runs `deactivate`.
struct DebugViewDesc {
  std::string name;  ///< e.g. "Ambient: irradiance"
  std::string description;
  std::string activate;    ///< console line, e.g. "r.Ambient.DebugMode 1"
  std::string deactivate;  ///< console line, e.g. "r.Ambient.DebugMode 0"
};

class DebugViewRegistry {
 public:
  struct View {
    DebugViewDesc desc;
    OwnerId owner;
    std::string origin;
  };
  void add(DebugViewDesc desc, OwnerId owner, std::string origin);
  const std::vector<View>& all() const { return views_; }
  const View* find(std::string_view name) const;
  void removeOwnedBy(OwnerId owner);

 private:
  std::vector<View> views_;
};

}  // namespace bounce
