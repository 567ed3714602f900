#pragma once
// What every part of the glTF loader shares: the parsed file, the plugins' extras
// schema and the warnings collected so far, plus the one-line message format.

#include "bounce/scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::gltf {

/// Input that cannot be loaded. Thrown anywhere inside the loader and turned into
/// GltfLoadResult::error by loadGltf, so no half-built scene ever escapes. The text is
/// the complete one-line message, file name included.
class LoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How the file states light intensities (asset `extras.BounceLightUnits`).
enum class LightUnits {
  Photometric,  ///< KHR_lights_punctual: candela (point, spot) and lux (directional)
  Radiometric,  ///< W/sr and W/m², as Bounce's scene model holds them
};

/// Farthest a placed object may be from the origin, in metres. Rendering runs in 32-bit
/// floats, whose spacing reaches 1 m at 1.7e7 m: beyond this nothing in the scene can be
/// resolved, and a shadow map fitted to such bounds shadows everything.
inline constexpr float kMaxWorldCoordinate = 1.0e7f;

struct LoadContext {
  const tinygltf::Model& model;
  std::string file;  ///< the path as the caller gave it; starts every message
  const SceneExtrasSchema* schema = nullptr;
  std::vector<std::string>& warnings;
  LightUnits lightUnits = LightUnits::Photometric;  ///< set from the asset before nodes are placed

  /// Records and logs "<file>: <element>: <message>".
  void warn(std::string_view element, std::string_view message) const;

  /// Extras keys no plugin declared, with the elements carrying them. Reported once per
  /// key after loading (a scene flags every material alike, so one line per material
  /// would bury the message).
  struct UnknownKey {
    std::string message;                ///< "unknown extras key 'X' (did you mean 'Y'?)"
    std::vector<std::string> elements;  ///< "material 'White'", ...
  };
  mutable std::map<std::string, UnknownKey> unknownKeys;  ///< by "<kind>\n<key>"
  void reportUnknownKeys() const;
  /// Throws LoadError("<file>: <element>: <message>").
  [[noreturn]] void fail(std::string_view element, std::string_view message) const;
};

/// "mesh 'Box'", or "mesh 3" when the element has no name.
std::string elementName(std::string_view kind, int index, std::string_view name);

/// "1 triangle", "3 triangles".
std::string countOf(size_t count, std::string_view singular);

}  // namespace bounce::gltf
