#include "gltf_lights_cameras.h"

#include "gltf_extras.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bounce::gltf {
namespace {

// Largest radiometric light intensity kept, W/sr or W/m². The sun delivers about
// 1000 W/m²; lighting divides intensity by d² ≥ 1e-8 m² (lights.glsl), so 1e6 keeps
// every product many orders below float's 3.4e38 where 1e30 would overflow.
constexpr double kMaxLightIntensity = 1.0e6;

bool beyondWorld(const glm::vec3& p) {
  return !(glm::all(glm::lessThanEqual(glm::abs(p), glm::vec3(kMaxWorldCoordinate))));
}

// Unit vector along `v`, or nullopt when `v` is zero, tiny or not finite.
std::optional<glm::vec3> unitOrNothing(const glm::vec3& v) {
  const float length = glm::length(v);
  if (!(length > 1e-30f) || !std::isfinite(length)) return std::nullopt;
  return v / length;
}

// Whether light `index` states a range in the file (tinygltf keeps the raw extension).
bool rangeGiven(const LoadContext& ctx, int index) {
  auto ext = ctx.model.extensions.find("KHR_lights_punctual");
  if (ext == ctx.model.extensions.end() || !ext->second.Has("lights")) return false;
  const tinygltf::Value& lights = ext->second.Get("lights");
  return lights.IsArray() && size_t(index) < lights.ArrayLen() && lights.Get(index).Has("range");
}

// The camera's position and orientation without the node's scale or shear: the view
// matrix is this frame's inverse, which a zero scale would make singular (NaN) and a
// non-uniform one would distort. Forward is the node's -Z, up its +Y made perpendicular.
glm::mat4 rigidCameraFrame(const LoadContext& ctx, std::string_view element, std::string_view nodeName,
                           const glm::mat4& world) {
  std::optional<glm::vec3> forward = unitOrNothing(-glm::vec3(world[2]));
  if (!forward) {
    ctx.warn(element, fmt::format("node '{}' scales the camera's -Z axis to zero; the camera looks down -Z",
                                  nodeName));
    forward = glm::vec3(0, 0, -1);
  }
  const glm::vec3 upHint(world[1]);
  std::optional<glm::vec3> up = unitOrNothing(upHint - glm::dot(upHint, *forward) * *forward);
  if (!up) {
    ctx.warn(element, fmt::format("node '{}' scales the camera's +Y axis to zero (or onto -Z); up is chosen",
                                  nodeName));
    const glm::vec3 axis = std::abs(forward->y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    up = glm::normalize(axis - glm::dot(axis, *forward) * *forward);
  }
  const glm::vec3 right = glm::cross(*forward, *up);
  glm::mat4 frame(1.0f);
  frame[0] = glm::vec4(right, 0.0f);
  frame[1] = glm::vec4(*up, 0.0f);
  frame[2] = glm::vec4(-*forward, 0.0f);
  frame[3] = world[3];
  return frame;
}

}  // namespace

LightUnits lightUnitsOf(const LoadContext& ctx) {
  const tinygltf::Value& extras = ctx.model.asset.extras;
  if (!extras.IsObject() || !extras.Has("BounceLightUnits")) return LightUnits::Photometric;
  const tinygltf::Value& v = extras.Get("BounceLightUnits");
  if (v.IsString() && v.Get<std::string>() == "radiometric") return LightUnits::Radiometric;
  if (v.IsString() && v.Get<std::string>() == "photometric") return LightUnits::Photometric;
  ctx.warn("asset",
           "extras.BounceLightUnits must be \"photometric\" or \"radiometric\"; using photometric "
           "(candela and lux, as KHR_lights_punctual specifies)");
  return LightUnits::Photometric;
}

void checkAssetVersion(const LoadContext& ctx) {
  const std::string& version = ctx.model.asset.version;
  if (!version.starts_with("2."))
    ctx.warn("asset", fmt::format("version '{}' is not glTF 2.x; loading it as glTF 2.0", version));
}

std::optional<Light> convertLight(const LoadContext& ctx, int index, const glm::mat4& world,
                                  std::string_view nodeName) {
  const tinygltf::Light& l = ctx.model.lights[size_t(index)];
  const std::string element = elementName("light", index, l.name);
  Light out;
  out.name = !l.name.empty() ? l.name : std::string(nodeName);
  if (l.type == "directional") {
    out.type = LightType::Directional;
  } else if (l.type == "point") {
    out.type = LightType::Point;
  } else if (l.type == "spot") {
    out.type = LightType::Spot;
  } else {
    ctx.warn(element, fmt::format("unknown type '{}'; light skipped", l.type));
    return std::nullopt;
  }

  if (l.color.size() == 3 &&
      std::all_of(l.color.begin(), l.color.end(), [](double c) { return std::isfinite(c); })) {
    out.color = glm::vec3(float(l.color[0]), float(l.color[1]), float(l.color[2]));
  } else if (!l.color.empty()) {
    ctx.warn(element, "color is not 3 finite numbers; using white");
  }
  const bool photometric = ctx.lightUnits == LightUnits::Photometric;
  const char* unit = out.type == LightType::Directional ? "W/m²" : "W/sr";
  if (std::isfinite(l.intensity) && l.intensity >= 0.0) {
    const double radiometric = photometric ? l.intensity / kLumensPerWatt : l.intensity;
    if (radiometric > kMaxLightIntensity) {
      ctx.warn(element, fmt::format("intensity {:g} ({:g} {}) is beyond any real light; clamped to {:g} {}",
                                    l.intensity, radiometric, unit, kMaxLightIntensity, unit));
    }
    out.intensity = float(std::min(radiometric, kMaxLightIntensity));
  } else {
    ctx.warn(element, fmt::format("intensity {} is not a finite non-negative number; using 1 {}", l.intensity,
                                  photometric ? (out.type == LightType::Directional ? "lx" : "cd") : unit));
    if (photometric) out.intensity = float(1.0 / kLumensPerWatt);
  }
  if (std::isfinite(l.range) && l.range > 0.0) {
    out.range = float(l.range);
  } else if (l.range != 0.0 || rangeGiven(ctx, index)) {
    // tinygltf reads an absent range as 0 too, which means unlimited; only a range the
    // file states is checked against the extension's rule (range > 0).
    ctx.warn(element, fmt::format("range {} is not a finite positive number (KHR_lights_punctual requires "
                                  "range > 0); using unlimited",
                                  l.range));
  }

  if (out.type == LightType::Spot) {
    // The spec requires 0 <= inner < outer <= pi/2.
    constexpr double kQuarterTurn = std::numbers::pi / 2.0;
    double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
    if (!std::isfinite(outer) || outer <= 0.0 || outer > kQuarterTurn) {
      ctx.warn(element, fmt::format("outerConeAngle {} is outside (0, pi/2]; clamped", outer));
      // Any positive angle keeps cone falloff from dividing by zero; a milliradian is
      // already narrower than any spot light a scene means.
      outer = std::isfinite(outer) ? std::clamp(outer, 1e-3, kQuarterTurn) : std::numbers::pi / 4.0;
    }
    if (!std::isfinite(inner) || inner < 0.0 || inner >= outer) {
      ctx.warn(element, fmt::format("innerConeAngle {} is outside [0, outerConeAngle); using 0", inner));
      inner = 0.0;
    }
    out.innerConeAngle = float(inner);
    out.outerConeAngle = float(outer);
  }

  out.position = glm::vec3(world[3]);
  if (out.type != LightType::Directional && beyondWorld(out.position)) {
    ctx.warn(element, fmt::format("node '{}' places the light {:g} m from the origin, beyond the {:g} m that "
                                  "rendering resolves; light skipped",
                                  nodeName, glm::length(out.position), double(kMaxWorldCoordinate)));
    return std::nullopt;
  }
  if (auto direction = unitOrNothing(-glm::vec3(world[2]))) {
    out.direction = *direction;
  } else if (out.type != LightType::Point) {
    ctx.warn(element,
             fmt::format("node '{}' scales its -Z axis to zero; the light points down -Z", nodeName));
  }
  out.parameters = parametersFromExtras(ctx, l.extras, ObjectKind::Light, element);
  return out;
}

std::optional<Camera> convertCamera(const LoadContext& ctx, int index, const glm::mat4& world,
                                    std::string_view nodeName) {
  const tinygltf::Camera& c = ctx.model.cameras[size_t(index)];
  const std::string element = elementName("camera", index, c.name);
  if (c.type != "perspective") {
    ctx.warn(element, fmt::format("type '{}' is not supported (perspective only); camera skipped", c.type));
    return std::nullopt;
  }
  const tinygltf::PerspectiveCamera& p = c.perspective;
  Camera out;
  out.name = !c.name.empty() ? c.name : std::string(nodeName);
  const glm::vec3 position(world[3]);
  if (beyondWorld(position)) {
    ctx.warn(element,
             fmt::format("node '{}' places the camera {:g} m from the origin, beyond the {:g} m that "
                         "rendering resolves; camera skipped",
                         nodeName, glm::length(position), double(kMaxWorldCoordinate)));
    return std::nullopt;
  }
  out.world = rigidCameraFrame(ctx, element, nodeName, world);
  if (std::isfinite(p.yfov) && p.yfov > 0.0 && p.yfov < std::numbers::pi) {
    out.yfov = float(p.yfov);
  } else {
    ctx.warn(element, fmt::format("yfov {} is outside (0, pi); using {}", p.yfov, out.yfov));
  }
  if (std::isfinite(p.znear) && p.znear > 0.0 && p.znear <= kMaxWorldCoordinate) {
    out.znear = float(p.znear);
  } else {
    ctx.warn(element, fmt::format("znear {} is outside (0, {:g}] m; using {}", p.znear,
                                  double(kMaxWorldCoordinate), out.znear));
  }
  if (p.zfar != 0.0) {
    if (std::isfinite(p.zfar) && p.zfar > out.znear) {
      out.zfar = float(p.zfar);
    } else {
      ctx.warn(element, fmt::format("zfar {} is not beyond znear; using an infinite far plane", p.zfar));
    }
  }
  if (std::isfinite(p.aspectRatio) && p.aspectRatio > 0.0) out.aspect = float(p.aspectRatio);
  return out;
}

}  // namespace bounce::gltf
