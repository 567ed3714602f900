#include "gltf_lights_cameras.h"

#include "gltf_extras.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bounce::gltf {

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
  if (std::isfinite(l.intensity) && l.intensity >= 0.0) {
    out.intensity = float(l.intensity);
  } else {
    ctx.warn(element, fmt::format("intensity {} is not a finite non-negative number; using 1", l.intensity));
  }
  if (std::isfinite(l.range) && l.range >= 0.0) {
    out.range = float(l.range);
  } else {
    ctx.warn(element, fmt::format("range {} is not a finite non-negative number; using unlimited", l.range));
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
  const glm::vec3 minusZ = -glm::vec3(world[2]);
  const float length = glm::length(minusZ);
  if (length > 0.0f && std::isfinite(length)) {
    out.direction = minusZ / length;
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
  out.world = world;
  if (std::isfinite(p.yfov) && p.yfov > 0.0 && p.yfov < std::numbers::pi) {
    out.yfov = float(p.yfov);
  } else {
    ctx.warn(element, fmt::format("yfov {} is outside (0, pi); using {}", p.yfov, out.yfov));
  }
  if (std::isfinite(p.znear) && p.znear > 0.0) {
    out.znear = float(p.znear);
  } else {
    ctx.warn(element, fmt::format("znear {} is not positive; using {}", p.znear, out.znear));
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
