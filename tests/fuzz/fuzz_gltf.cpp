// libFuzzer target: glTF loading with extras and post-process volumes. The input is a
// .gltf (JSON; buffers as data: URIs) or, when it starts with "glTF", a .glb; it is
// loaded with the engine's extras schema (plugin material, light and post-process keys),
// and the post-process settings are blended at the scene's cameras and at the volumes'
// origins as the renderer does every frame.

#include "bounce/frame/post_process_settings.h"
#include "bounce/scene/gltf_loader.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  bounce::Engine& engine = bounce::fuzz::engine();
  const std::string_view input = bounce::fuzz::text(data, size);
  const std::string path = bounce::fuzz::scratchFile(input, input.starts_with("glTF") ? ".glb" : ".gltf");
  const bounce::SceneExtrasSchema schema = engine.extrasSchema();
  bounce::GltfLoadResult loaded = bounce::loadGltf(path, &schema);
  if (!loaded.scene) return 0;
  std::vector<glm::vec3> positions{glm::vec3(0.0f)};
  for (const bounce::Camera& camera : loaded.scene->cameras()) positions.push_back(camera.position());
  for (const glm::vec3& p : positions) {
    std::vector<std::string> warnings;
    (void)bounce::PostProcessSettings::blend(*loaded.scene, engine.cvars(), p, &warnings);
  }
  return 0;
}
