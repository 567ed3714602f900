#include "scene/generated_scenes.h"

#include "scene/generated_meshes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace bounce::generated {

std::unique_ptr<Scene> litRoom(uint32_t triangles) {
  auto s = std::make_unique<Scene>();
  Material white;
  white.name = "white";
  white.baseColorFactor = glm::vec4(0.75f, 0.75f, 0.75f, 1.0f);
  white.metallicFactor = 0.0f;
  Material red = white;
  red.name = "red";
  red.baseColorFactor = glm::vec4(0.7f, 0.15f, 0.1f, 1.0f);
  const uint32_t w = s->addMaterial(white), r = s->addMaterial(red);
  s->addInstance({.name = "room",
                  .mesh = s->addMesh(box({8.0f, 4.0f, 8.0f}, true, w, "room")),
                  .world = glm::translate(glm::mat4(1.0f), {0.0f, 2.0f, 0.0f})});
  // A 4 × 4 grid of spheres on the floor, each 2·rings·segments triangles.
  const uint32_t perSphere = std::max(triangles / 16u, 32u);
  const auto rings = uint32_t(std::max(4.0, std::sqrt(double(perSphere) / 2.0)));
  const uint32_t segments = std::max(4u, perSphere / (2 * rings));
  const uint32_t sphere = s->addMesh(bumpySphere(rings, segments, 0.5f, 0.1f, r));
  for (int i = 0; i < 16; ++i) {
    const glm::vec3 at(-3.0f + 2.0f * float(i % 4), 0.6f, -3.0f + 2.0f * float(i / 4));
    s->addInstance({.name = "sphere " + std::to_string(i),
                    .mesh = sphere,
                    .world = glm::translate(glm::mat4(1.0f), at)});
  }
  Light light;
  light.name = "light";
  light.type = LightType::Point;
  light.intensity = 40.0f;
  light.position = {0.0f, 3.6f, 0.0f};
  s->addLight(light);
  Camera camera;
  camera.name = "corner";
  camera.yfov = 1.0f;
  camera.world = glm::inverse(
      glm::lookAt(glm::vec3(3.6f, 2.5f, 3.6f), glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
  s->addCamera(camera);
  return s;
}

}  // namespace bounce::generated
