// Reference: the path tracer as a GI technique (being written).
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>

namespace bounce::reference {
class ReferencePlugin final : public Plugin {
 public:
  void startup(PluginContext&) override {}
};
}  // namespace bounce::reference

BOUNCE_IMPLEMENT_PLUGIN(bounce::reference::ReferencePlugin)
