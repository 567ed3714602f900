#include "bounce/graph/extension_point.h"

#include "bounce/core/names.h"

namespace bounce {

std::string_view extensionPointName(ExtensionPoint point) {
  switch (point) {
    case ExtensionPoint::FrameBegin:
      return "FrameBegin";
    case ExtensionPoint::AfterGBuffer:
      return "AfterGBuffer";
    case ExtensionPoint::IndirectDiffuse:
      return "IndirectDiffuse";
    case ExtensionPoint::IndirectSpecular:
      return "IndirectSpecular";
    case ExtensionPoint::AmbientOcclusion:
      return "AmbientOcclusion";
    case ExtensionPoint::BeforePostProcess:
      return "BeforePostProcess";
    case ExtensionPoint::DebugView:
      return "DebugView";
    case ExtensionPoint::Count:
      break;
  }
  return "?";
}

std::optional<ExtensionPoint> extensionPointFromName(std::string_view name) {
  for (ExtensionPoint p : kAllExtensionPoints)
    if (equalsIgnoreCase(extensionPointName(p), name)) return p;
  return std::nullopt;
}

}  // namespace bounce
