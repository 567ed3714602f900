#include "temporal_measure.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace bounce::bench {

std::optional<uint32_t> strongestLight(const Scene& scene) {
  const Aabb bounds = scene.bounds();
  const float radius = bounds.empty() ? 1.0f : 0.5f * glm::length(bounds.size());
  std::optional<uint32_t> best;
  double bestPower = -1.0;
  for (uint32_t i = 0; i < scene.lights().size(); ++i) {
    const Light& l = scene.lights()[i];
    const glm::vec3 c = l.radiometricIntensity();
    const double luminance = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
    double reach = 4.0 * glm::pi<double>();
    if (l.type == LightType::Directional) reach = glm::pi<double>() * radius * radius;
    if (l.type == LightType::Spot)
      reach = 2.0 * glm::pi<double>() * (1.0 - std::cos(double(l.outerConeAngle)));
    const double power = luminance * reach;
    if (std::isfinite(power) && power > bestPower) {
      bestPower = power;
      best = i;
    }
  }
  return best;
}

Light movedLight(const Light& light, const Aabb& bounds) {
  Light moved = light;
  const float distance = bounds.empty() ? 0.1f : 0.1f * glm::length(bounds.size());
  if (light.type == LightType::Directional) {
    glm::vec3 axis = glm::cross(light.direction, glm::vec3(0.0f, 1.0f, 0.0f));
    if (glm::dot(axis, axis) < 1e-8f)
      axis = glm::vec3(1.0f, 0.0f, 0.0f);  // straight down: any horizontal axis
    // Rodrigues' rotation of the direction about the (unit, perpendicular) axis.
    axis = glm::normalize(axis);
    moved.direction = light.direction * std::cos(0.1f) + glm::cross(axis, light.direction) * std::sin(0.1f);
    return moved;
  }
  const glm::vec3 toCentre = (bounds.empty() ? glm::vec3(0.0f) : bounds.center()) - light.position;
  const float length = glm::length(toCentre);
  moved.position +=
      length > 1e-6f ? toCentre * (std::min(distance, length) / length) : glm::vec3(distance, 0.0f, 0.0f);
  return moved;
}

std::vector<ImageBuffer> framesUntilSettled(Renderer& renderer, const FrameView& view, uint64_t& frameIndex,
                                            uint32_t most, std::string* error, bool orAtTheNoiseFloor) {
  std::vector<ImageBuffer> frames;
  std::vector<double> changes;
  FrameOutputs outputs;
  outputs.aovs = {"radiance"};
  uint32_t quiet = 0;
  while (frames.size() < most && quiet < 3) {
    RenderedFrame f = renderer.render(view, outputs, frameIndex++);
    if (!f.gpu.ok()) {
      if (error) *error = f.gpu.errors.front();
      return {};
    }
    ImageBuffer image = std::move(f.images.at("radiance"));
    // A technique that adapts by blending (a probe volume's hysteresis) has no settling
    // note after a change of light, only a changing image: it has settled when the image
    // stops changing. 1e-4 of the mean is far below any visible step and above float rounding.
    const double change = frames.empty() ? 1.0 : relativeMae(image, frames.back(), meanValue(image));
    quiet = f.settling.empty() && change < 1e-4 ? quiet + 1 : 0;
    if (!frames.empty()) changes.push_back(change);
    frames.push_back(std::move(image));
    if (orAtTheNoiseFloor && f.settling.empty() && changesHaveLevelledOff(changes)) break;
  }
  return frames;
}

TemporalMeasure measureTemporal(
    Engine& engine, Renderer& renderer, const FrameView& view, uint64_t& frameIndex,
    const std::function<std::optional<ImageBuffer>(uint32_t light)>& freshWithoutLight,
    const TemporalOptions& options) {
  TemporalMeasure out;
  FrameOutputs outputs;
  outputs.aovs = {"radiance"};
  // Settle first on the unjittered view: the scored still before this jittered the view,
  // and a history filled from jittered frames (sparse tracing's) takes its own frames to
  // be replaced, which read as flicker (a p95 of 0.044 on the Cornell box).
  // A technique whose frames carry noise never stands still: it has settled when its frame
  // -to-frame change stops falling (a probe volume tracing random rays changes every frame).
  if (framesUntilSettled(renderer, view, frameIndex, options.mostFrames, &out.error, true).empty())
    return out;
  std::vector<ImageBuffer> still;
  for (uint32_t i = 0; i < options.flickerFrames; ++i) {
    RenderedFrame f = renderer.render(view, outputs, frameIndex++);
    if (!f.gpu.ok()) {
      out.error = f.gpu.errors.front();
      return out;
    }
    still.push_back(std::move(f.images.at("radiance")));
  }
  out.flicker = flicker(still);
  Scene& scene = *engine.scene();
  const std::optional<uint32_t> light = strongestLight(scene);
  if (!light) {
    out.error = "the scene has no light to switch";
    return out;
  }
  const ImageBuffer lit = still.back();
  const Light original = scene.lights()[*light];
  const std::optional<ImageBuffer> dark = freshWithoutLight(*light);
  if (!dark) {
    out.error = "the scene without its strongest light did not render";
    return out;
  }
  auto respond = [&](const std::function<void(Light&)>& edit, const ImageBuffer& before,
                     const ImageBuffer& target, Response& response) {
    scene.editLight(*light, edit);
    std::vector<ImageBuffer> after =
        framesUntilSettled(renderer, view, frameIndex, options.mostFrames, &out.error);
    if (after.empty()) return ImageBuffer();
    response = bench::response(before, after, target);
    return after.back();
  };
  const ImageBuffer off = respond([](Light& l) { l.intensity = 0.0f; }, lit, *dark, out.off);
  if (!out.error.empty()) return out;
  out.offResidue = relativeMae(off, *dark, meanValue(lit));
  respond([&](Light& l) { l = original; }, off, lit, out.on);
  if (!out.error.empty()) return out;
  const Light moved = movedLight(original, scene.bounds());
  respond([&](Light& l) { l = moved; }, lit, ImageBuffer(), out.move);
  scene.editLight(*light, [&](Light& l) { l = original; });
  return out;
}

}  // namespace bounce::bench
