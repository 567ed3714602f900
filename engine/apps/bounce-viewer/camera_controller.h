#pragma once
// The viewer's camera: flies (WASD + mouse look) or orbits a target (drag to turn,
// scroll to zoom), starts at the scene's glTF camera and can be reset to it. The
// `camera ...` console command drives it from scripts.

#include "bounce/config/console.h"
#include "bounce/scene/camera.h"

#include <glm/glm.hpp>

#include <string>
#include <utility>
#include <vector>

namespace bounce::viewer {

/// One frame of user input, already filtered (nothing while the UI has the focus).
struct CameraInput {
  glm::vec2 mouseDelta{0.0f};  ///< pixels since the last frame
  bool turning = false;        ///< right button (fly) or left button (orbit) held
  float scroll = 0.0f;         ///< wheel steps
  glm::vec3 move{0.0f};        ///< -1..1 per axis: right, up, forward
  bool fast = false;           ///< shift
};

class CameraController {
 public:
  enum class Mode { Fly, Orbit };

  /// `home`: the glTF camera; `sceneCentre` and `sceneSize` set the orbit target and
  /// a speed that suits the scene's scale.
  CameraController(const Camera& home, glm::vec3 sceneCentre, float sceneSize);

  void update(const CameraInput& input, float seconds);
  /// Back to the glTF camera, in fly mode.
  void reset();
  /// True once after the camera jumped (reset, or `camera position`) rather than moved:
  /// the renderer should cut its history, since no pixel of the last frame is worth
  /// reprojecting into the new view.
  bool takeCut() { return std::exchange(cut_, false); }

  Camera camera() const;
  Mode mode() const { return mode_; }
  void setMode(Mode mode);
  float speed() const { return speed_; }
  void setSpeed(float metresPerSecond) { speed_ = metresPerSecond; }
  glm::vec3 position() const { return position_; }
  float yawDegrees() const;
  float pitchDegrees() const;

  /// `camera reset | fly | orbit | speed S | position X Y Z | lookat X Y Z |
  ///  rotate YAW PITCH | print` (angles in degrees).
  ConsoleResult execute(const std::vector<std::string>& args);

 private:
  glm::vec3 forward() const;
  /// Turns toward `point`; false (nothing changes) when it is where the camera is.
  bool lookAt(glm::vec3 point);
  void placeOnOrbit();

  Camera home_;
  glm::vec3 sceneCentre_;
  float defaultSpeed_;
  Mode mode_ = Mode::Fly;
  glm::vec3 position_{0.0f};
  float yaw_ = 0.0f;    // radians about +Y; 0 looks down -Z
  float pitch_ = 0.0f;  // radians, positive looks up
  float speed_ = 1.0f;
  glm::vec3 target_{0.0f};
  float distance_ = 1.0f;
  bool cut_ = false;
};

}  // namespace bounce::viewer
