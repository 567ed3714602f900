#include "bounce-soak/soak_animation.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace bounce::soak {
namespace {

constexpr float kTwoPi = 6.28318530718f;

/// 0 → 1 → 0 over one period, smooth at both ends.
float wave(uint64_t frame, uint32_t period) {
  const float phase = float(frame % period) / float(period);
  return 0.5f * (1.0f - std::cos(kTwoPi * phase));
}

bool endsWith(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

uint32_t SoakPeriods::fullCycle() const {
  // The waves are symmetric (every value is reached in half a period), the sideways sway
  // is a sine (its whole range by three quarters of one), the light needs two toggles.
  return std::max({camera / 2, object * 3 / 4, 2 * lightToggle, volumeWeight / 2});
}

SoakAnimation::SoakAnimation(Scene& scene, const CVarRegistry& cvars, SoakPeriods periods)
    : scene_(scene), periods_(periods) {
  if (!scene.cameras().empty()) camera_ = scene.cameras().front();
  const Aabb bounds = scene.bounds();
  // Travel most of the way to the scene's centre: into a room that is open towards the
  // camera, short of what is in the middle.
  const float distance = bounds.empty() ? 1.0f : glm::length(bounds.center() - camera_.position());
  travel_ = std::max(0.1f, 0.6f * distance);

  // The smallest instance (by the diagonal of its bounds: a wall is flat but large) moves:
  // in a room, an object inside it rather than a wall.
  float smallest = std::numeric_limits<float>::infinity();
  for (uint32_t i = 0; i < scene.instances().size(); ++i) {
    const float diagonal = glm::length(scene.instances()[i].worldBounds.size());
    if (diagonal < smallest) {
      smallest = diagonal;
      object_ = i;
    }
  }
  if (object_) {
    objectWorld_ = scene.instances()[*object_].world;
    const glm::vec3 size = scene.instances()[*object_].worldBounds.size();
    swing_ = std::max(0.05f, 0.25f * std::max({size.x, size.y, size.z}));
  }
  if (!scene.lights().empty()) {
    light_ = 0;
    lightIntensity_ = scene.lights().front().intensity;
  }

  // A bound volume half-way along the camera's path, smaller than the path, so the camera
  // enters, crosses and leaves it (and its blend radius) every cycle.
  PostProcessVolume v;
  v.name = "Soak";
  v.priority = 10.0f;
  v.blendRadius = 0.15f * travel_;
  v.unbound = false;
  const glm::vec3 centre = camera_.position() + camera_.forward() * (0.5f * travel_);
  v.world = glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(0.15f * travel_));
  v.settings["ExposureCompensation"] = 1.0;
  v.settings["BloomIntensity"] = 0.5;
  for (const std::string& name : cvars.names()) {
    const CVar* c = cvars.find(name);
    if (c && c->type() == CVarType::Float && endsWith(c->postProcessName(), "Intensity") &&
        !v.settings.count(c->postProcessName()))
      v.settings[c->postProcessName()] = 0.5 * double(c->getFloat());
  }
  for (const auto& [name, value] : v.settings)
    volumeSettings_.push_back(fmt::format("{}={}", name, std::get<double>(value)));
  volume_ = scene.addPostProcessVolume(std::move(v));
}

FrameView SoakAnimation::apply(uint64_t frame, uint32_t width, uint32_t height) {
  if (object_) {
    const float offset = swing_ * (2.0f * wave(frame, periods_.object) - 1.0f);
    scene_.setInstanceTransform(
        *object_, glm::translate(glm::mat4(1.0f), glm::vec3(offset, 0.0f, 0.0f)) * objectWorld_);
  }
  if (light_) {
    const bool on = (frame / periods_.lightToggle) % 2 == 0;
    const float want = on ? lightIntensity_ : 0.0f;
    if (scene_.lights()[*light_].intensity != want)
      scene_.editLight(*light_, [want](Light& l) { l.intensity = want; });
  }
  scene_.editPostProcessVolume(
      volume_, [&](PostProcessVolume& v) { v.blendWeight = wave(frame, periods_.volumeWeight); });

  // The camera flies forward and back along its view axis, swaying sideways and turning
  // by up to 10° either way, so the view (and any view-anchored structure) keeps moving.
  Camera c = camera_;
  const float along = travel_ * wave(frame, periods_.camera);
  const float sway = std::sin(kTwoPi * float(frame % periods_.object) / float(periods_.object));
  const glm::vec3 right = glm::normalize(glm::vec3(camera_.world[0]));
  const glm::vec3 position = camera_.position() + camera_.forward() * along + right * (0.1f * travel_ * sway);
  c.world = glm::rotate(glm::mat4(1.0f), glm::radians(10.0f) * sway, camera_.up()) * camera_.world;
  c.world[3] = glm::vec4(position, 1.0f);
  return FrameView::fromCamera(c, width, height);
}

std::vector<std::string> SoakAnimation::describe() const {
  std::vector<std::string> lines;
  lines.push_back(
      fmt::format("camera '{}': {:.2f} m forward and back every {} frames, swaying and turning ±10°",
                  camera_.name, travel_, periods_.camera));
  if (object_)
    lines.push_back(fmt::format("object '{}': ±{:.2f} m along x every {} frames",
                                scene_.instances()[*object_].name, swing_, periods_.object));
  else
    lines.push_back("object: none (the scene has no instance)");
  if (light_)
    lines.push_back(fmt::format("light '{}': off and on every {} frames", scene_.lights()[*light_].name,
                                periods_.lightToggle));
  else
    lines.push_back("light: none (the scene has no light)");
  lines.push_back(
      fmt::format("post-process volume 'Soak' on the camera's path, BlendWeight 0..1 every {} "
                  "frames: {}",
                  periods_.volumeWeight, fmt::join(volumeSettings_, ", ")));
  return lines;
}

}  // namespace bounce::soak
