// loadGltf: the order in which the pieces of a glTF file become a Scene. Each piece
// lives in its own gltf_*.cpp; every one of them may throw LoadError, which ends the
// load with an error and no scene.

#include "bounce/scene/gltf_loader.h"

#include "gltf_context.h"
#include "gltf_file.h"
#include "gltf_images.h"
#include "gltf_lights_cameras.h"
#include "gltf_materials.h"
#include "gltf_meshes.h"
#include "gltf_nodes.h"

#include "bounce/core/log.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <new>

namespace bounce {
namespace {

// Extensions this loader understands. KHR_mesh_quantization only widens the accessor
// component types allowed, which the accessor reader accepts anyway.
constexpr std::array<std::string_view, 4> kSupportedExtensions = {
    "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_materials_specular",
    "KHR_mesh_quantization"};

void warnUnsupportedExtensions(const gltf::LoadContext& ctx) {
  for (const std::string& ext : ctx.model.extensionsRequired) {
    if (std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), ext) ==
        kSupportedExtensions.end()) {
      ctx.warn("extensionsRequired", fmt::format("'{}' is not supported; the scene may look wrong", ext));
    }
  }
}

std::unique_ptr<Scene> buildScene(const gltf::LoadContext& ctx, const std::string& path) {
  const tinygltf::Model& model = ctx.model;
  auto scene = std::make_unique<Scene>();
  scene->setSourcePath(path);
  warnUnsupportedExtensions(ctx);

  // Scene texture i is the file's image i, which is what material TextureRefs use.
  for (size_t i = 0; i < model.images.size(); ++i) scene->addTexture(gltf::convertImage(ctx, int(i)));
  for (size_t i = 0; i < model.materials.size(); ++i) scene->addMaterial(gltf::convertMaterial(ctx, int(i)));

  // Primitives without a material use a default one, appended after the file's.
  const auto defaultMaterial = uint32_t(model.materials.size());
  bool defaultMaterialUsed = false;
  std::vector<Mesh> meshes;
  for (size_t i = 0; i < model.meshes.size(); ++i) {
    meshes.push_back(gltf::convertMesh(ctx, int(i), defaultMaterial, defaultMaterialUsed));
  }
  if (defaultMaterialUsed) scene->addMaterial(gltf::defaultMaterial());
  std::vector<uint32_t> meshIndices;
  for (Mesh& mesh : meshes) meshIndices.push_back(scene->addMesh(std::move(mesh)));

  gltf::SceneMeshes sceneMeshes(*scene, std::move(meshIndices));
  gltf::placeNodes(ctx, *scene, sceneMeshes);
  ctx.reportUnknownKeys();
  return scene;
}

}  // namespace

GltfLoadResult loadGltf(const std::string& path, const SceneExtrasSchema* schema) {
  GltfLoadResult result;
  tinygltf::Model model;
  gltf::LoadContext ctx{model, path, schema, result.warnings};
  try {
    std::vector<std::string> tinygltfWarnings;
    gltf::readGltfFile(path, model, tinygltfWarnings);
    for (const std::string& w : tinygltfWarnings) ctx.warn("tinygltf", w);
    gltf::checkAssetVersion(ctx);
    ctx.lightUnits = gltf::lightUnitsOf(ctx);
    result.scene = buildScene(ctx, path);
  } catch (const gltf::LoadError& e) {
    result.error = e.what();
  } catch (const std::bad_alloc&) {
    result.error = fmt::format("{}: out of memory (the file declares more data than can be loaded)", path);
  }
  if (!result.error.empty()) {
    result.scene.reset();
    log::error("{}", result.error);
  }
  return result;
}

}  // namespace bounce
