#include "camera_controller.h"

#include "bounce/core/names.h"

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace bounce::viewer {

namespace {

constexpr float kMaxPitch = 1.55f;  // just short of straight up: keeps "up" defined
constexpr float kRadiansPerPixel = 0.004f;
// The farthest a camera may be from the origin on any axis. A float resolves 64 m steps
// at 1e9 m, so nothing there can be looked at usefully, and differences between two
// such points (at most 2e9) and their squares (4e18, for lengths) stay far below
// FLT_MAX (3.4e38): forward vectors and view matrices stay finite.
constexpr float kMaxCoordinate = 1e9f;
constexpr float kMinSpeed = 0.01f, kMaxSpeed = 1000.0f;  // m/s, as the wheel allows

bool parseFloat(const std::string& text, float* out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, *out);
  return ec == std::errc() && ptr == end && std::isfinite(*out);
}

ConsoleResult fail(std::string message) { return ConsoleResult{false, {std::move(message)}}; }

}  // namespace

CameraController::CameraController(const Camera& home, glm::vec3 sceneCentre, float sceneSize)
    : home_(home), sceneCentre_(sceneCentre), defaultSpeed_(std::max(0.1f, 0.5f * sceneSize)) {
  reset();
}

void CameraController::reset() {
  cut_ = true;
  mode_ = Mode::Fly;
  position_ = home_.position();
  lookAt(position_ + home_.forward());
  speed_ = defaultSpeed_;
  target_ = sceneCentre_;
  distance_ = std::max(0.1f, glm::length(position_ - target_));
}

glm::vec3 CameraController::forward() const {
  return {-std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_)};
}

bool CameraController::lookAt(glm::vec3 point) {
  const glm::vec3 d = point - position_;
  // Normalise by the largest component first: the length of a vector of 1e20s would
  // overflow in its squares. The test is written so that NaN fails it.
  const float largest = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
  if (!(largest > 1e-6f) || !std::isfinite(largest)) return false;
  const glm::vec3 f = glm::normalize(d / largest);
  pitch_ = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  yaw_ = std::atan2(-f.x, -f.z);
  return true;
}

void CameraController::placeOnOrbit() { position_ = target_ - forward() * distance_; }

void CameraController::setMode(Mode mode) {
  mode_ = mode;
  if (mode_ == Mode::Orbit) {
    // Orbit what the camera looks at, at the scene centre's distance.
    distance_ = std::max(0.1f, glm::length(sceneCentre_ - position_));
    target_ = position_ + forward() * distance_;
  }
}

void CameraController::update(const CameraInput& input, float seconds) {
  if (input.turning) {
    yaw_ -= input.mouseDelta.x * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ - input.mouseDelta.y * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
  }
  if (mode_ == Mode::Orbit) {
    distance_ = std::max(0.05f, distance_ * std::pow(0.9f, input.scroll));
    placeOnOrbit();
    return;
  }
  if (input.scroll != 0.0f) speed_ = std::clamp(speed_ * std::pow(1.2f, input.scroll), 0.01f, 1000.0f);
  const glm::vec3 f = forward();
  const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
  const float step = speed_ * seconds * (input.fast ? 4.0f : 1.0f);
  position_ += (right * input.move.x + glm::vec3(0, 1, 0) * input.move.y + f * input.move.z) * step;
  position_ = glm::clamp(position_, glm::vec3(-kMaxCoordinate), glm::vec3(kMaxCoordinate));
}

Camera CameraController::camera() const {
  Camera c = home_;
  const glm::vec3 f = forward();
  const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, f);
  c.world =
      glm::mat4(glm::vec4(right, 0.0f), glm::vec4(up, 0.0f), glm::vec4(-f, 0.0f), glm::vec4(position_, 1.0f));
  c.aspect = 0.0f;  // the window decides
  return c;
}

float CameraController::yawDegrees() const { return glm::degrees(yaw_); }
float CameraController::pitchDegrees() const { return glm::degrees(pitch_); }

ConsoleResult CameraController::execute(const std::vector<std::string>& args) {
  const std::string usage =
      "usage: camera reset | fly | orbit | speed S | position X Y Z | lookat X Y Z | rotate YAW PITCH | "
      "print";
  if (args.empty()) return fail(usage);
  const std::string& what = args[0];
  std::vector<float> numbers;
  for (size_t i = 1; i < args.size(); ++i) {
    float v = 0.0f;
    if (!parseFloat(args[i], &v))
      return fail(fmt::format("camera {}: '{}' is not a finite number", printable(what), printable(args[i])));
    numbers.push_back(v);
  }
  auto expect = [&](size_t n) { return numbers.size() == n; };
  auto point = [&]() { return glm::vec3(numbers[0], numbers[1], numbers[2]); };
  auto outOfReach = [&]() {
    return std::any_of(numbers.begin(), numbers.end(), [](float v) { return std::abs(v) > kMaxCoordinate; });
  };
  if ((what == "position" || what == "lookat") && expect(3) && outOfReach())
    return fail(fmt::format("camera {}: coordinates must lie within ±{:g} m; the camera is unchanged", what,
                            kMaxCoordinate));
  if (what == "reset" && expect(0)) {
    reset();
  } else if (what == "fly" && expect(0)) {
    setMode(Mode::Fly);
  } else if (what == "orbit" && expect(0)) {
    setMode(Mode::Orbit);
  } else if (what == "speed" && expect(1)) {
    if (!(numbers[0] >= kMinSpeed && numbers[0] <= kMaxSpeed))
      return fail(fmt::format("camera speed: {:g} is outside [{:g}, {:g}] m/s; keeps {:g}", numbers[0],
                              kMinSpeed, kMaxSpeed, speed_));
    speed_ = numbers[0];
  } else if (what == "position" && expect(3)) {
    position_ = point();
    cut_ = true;
  } else if (what == "lookat" && expect(3)) {
    if (!lookAt(point()))
      return fail(
          fmt::format("camera lookat: ({:g}, {:g}, {:g}) is where the camera is; the camera is unchanged",
                      numbers[0], numbers[1], numbers[2]));
  } else if (what == "rotate" && expect(2)) {
    yaw_ = glm::radians(numbers[0]);
    pitch_ = std::clamp(glm::radians(numbers[1]), -kMaxPitch, kMaxPitch);
  } else if (what != "print") {
    return fail(fmt::format("camera {}: {}", printable(what), usage));
  }
  if (mode_ == Mode::Orbit && what != "position") placeOnOrbit();
  return ConsoleResult{
      true,
      {fmt::format("camera {} at ({:.3f}, {:.3f}, {:.3f}) yaw {:.1f} pitch {:.1f} speed {:.2f} m/s",
                   mode_ == Mode::Fly ? "fly" : "orbit", position_.x, position_.y, position_.z, yawDegrees(),
                   pitchDegrees(), speed_)}};
}

}  // namespace bounce::viewer
