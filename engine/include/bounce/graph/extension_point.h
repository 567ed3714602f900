#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace bounce {

/// Where plugins hook passes into the engine's frame, in execution order. The engine's
/// own passes sit between them:
///
///   FrameBegin  → shadow maps → G-buffer → AfterGBuffer → IndirectDiffuse →
///   IndirectSpecular → AmbientOcclusion → lighting + composite → BeforePostProcess →
///   bloom + tone mapping → DebugView → output
///
/// FrameBegin: persistent updates that need no view data (probe ray tracing, VPLs).
/// AfterGBuffer: shadow maps and the G-buffer exist (voxelization with shadowed lights).
/// IndirectDiffuse / IndirectSpecular / AmbientOcclusion: publish the GI channels
///   (see channels.h); the composite reads whichever exist, and none costs nothing.
/// BeforePostProcess: the HDR scene colour exists and may be modified or replaced.
/// DebugView: publish channels::DebugView to show a debug visualisation instead of the
///   tone-mapped image (only kept when a debug view is selected).
enum class ExtensionPoint : uint8_t {
  FrameBegin,
  AfterGBuffer,
  IndirectDiffuse,
  IndirectSpecular,
  AmbientOcclusion,
  BeforePostProcess,
  DebugView,
  Count,
};

inline constexpr std::array<ExtensionPoint, size_t(ExtensionPoint::Count)> kAllExtensionPoints = {
    ExtensionPoint::FrameBegin,       ExtensionPoint::AfterGBuffer,     ExtensionPoint::IndirectDiffuse,
    ExtensionPoint::IndirectSpecular, ExtensionPoint::AmbientOcclusion, ExtensionPoint::BeforePostProcess,
    ExtensionPoint::DebugView};

std::string_view extensionPointName(ExtensionPoint point);
std::optional<ExtensionPoint> extensionPointFromName(std::string_view name);

}  // namespace bounce
