#include "embree_scene.h"

#include "texture_lookup.h"

#include "bounce/core/log.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace bounce::reference {

namespace {

glm::mat3 normalMatrix(const glm::mat4& world) { return glm::transpose(glm::inverse(glm::mat3(world))); }

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

const char* errorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}

// glTF alpha mask: a hit whose base-colour alpha is below the cutoff is no hit, for
// camera, bounce and shadow rays alike (the rasterizer discards those fragments).
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
  const auto* record = static_cast<const GeometryRecord*>(args->geometryUserPtr);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const uint32_t primID = RTCHitN_primID(args->hit, args->N, i);
    if (record->cutOut(primID, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)))
      args->valid[i] = 0;
  }
}

}  // namespace

glm::vec2 GeometryRecord::uvAt(uint32_t primID, float u, float v) const {
  if (uvs.empty()) return glm::vec2(0.0f);
  const glm::uvec3& tri = triangles[primID];
  return (1.0f - u - v) * uvs[tri.x] + u * uvs[tri.y] + v * uvs[tri.z];
}

bool GeometryRecord::cutOut(uint32_t primID, float u, float v) const {
  if (alphaCutoff < 0.0f) return false;
  float alpha = alphaFactor;
  // Alpha is linear in sRGB textures too, so the linear read gives the right value.
  if (alphaTexture) alpha *= sampleBilinear(*alphaTexture, uvAt(primID, u, v), ColorSpace::Linear).a;
  return alpha < alphaCutoff;  // as gbuffer.frag's discard
}

void EmbreeScene::DeviceDeleter::operator()(void* device) const {
  rtcReleaseDevice(static_cast<RTCDevice>(device));
}
void EmbreeScene::SceneDeleter::operator()(void* scene) const {
  rtcReleaseScene(static_cast<RTCScene>(scene));
}

void EmbreeScene::recordError(int code, const char* message) {
  const std::string line =
      fmt::format("Embree: {} ({})", message ? message : "no message", errorName(RTCError(code)));
  log::error("{}", line);
  std::lock_guard lock(errorMutex_);
  if (firstError_.empty()) firstError_ = line;
}

void EmbreeScene::throwIfFailed(const char* what) const {
  const RTCError code = rtcGetDeviceError(static_cast<RTCDevice>(device_.get()));
  std::lock_guard lock(errorMutex_);
  if (code != RTC_ERROR_NONE || !firstError_.empty())
    throw std::runtime_error(fmt::format("reference path tracer: {} failed: {}", what,
                                         firstError_.empty() ? errorName(code) : firstError_));
}

EmbreeScene::EmbreeScene(const Scene& scene, const std::vector<Texture>& textures) {
  device_.reset(rtcNewDevice(nullptr));
  if (!device_) {
    throw std::runtime_error(fmt::format("reference path tracer: cannot create an Embree device ({})",
                                         errorName(rtcGetDeviceError(nullptr))));
  }
  RTCDevice device = static_cast<RTCDevice>(device_.get());
  rtcSetDeviceErrorFunction(
      device,
      [](void* self, RTCError code, const char* message) {
        static_cast<EmbreeScene*>(self)->recordError(int(code), message);
      },
      this);

  scene_.reset(rtcNewScene(device));
  throwIfFailed("creating the scene");
  RTCScene rtcScene = static_cast<RTCScene>(scene_.get());
  // Robust traversal: no rays slip between the triangles of a closed mesh at shared
  // edges, which would leak light into closed rooms.
  rtcSetSceneFlags(rtcScene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(rtcScene, RTC_BUILD_QUALITY_HIGH);

  Aabb bounds;
  for (uint32_t i = 0; i < scene.instances().size(); ++i) {
    const MeshInstance& instance = scene.instances()[i];
    if (instance.mesh >= scene.meshes().size()) continue;
    const glm::mat4& world = instance.world;
    const glm::mat3 nm = normalMatrix(world);
    const Mesh& mesh = scene.meshes()[instance.mesh];
    for (uint32_t p = 0; p < mesh.primitives.size(); ++p) {
      const MeshPrimitive& prim = mesh.primitives[p];
      if (prim.material >= scene.materials().size()) continue;  // nothing to shade it with
      GeometryRecord rec;
      rec.instance = i;
      rec.primitive = p;
      rec.material = prim.material;
      const size_t n = prim.positions.size();
      rec.positions.reserve(n);
      for (const glm::vec3& q : prim.positions)
        rec.positions.push_back(glm::vec3(world * glm::vec4(q, 1.0f)));
      rec.normals.resize(n, glm::vec3(0.0f));
      for (size_t v = 0; v < n && v < prim.normals.size(); ++v) rec.normals[v] = nm * prim.normals[v];
      if (prim.tangents.size() == n) {
        rec.tangents.reserve(n);
        for (const glm::vec4& t : prim.tangents)
          rec.tangents.push_back(glm::vec4(glm::mat3(world) * glm::vec3(t), t.w));
      }
      if (prim.texcoords0.size() == n) rec.uvs = prim.texcoords0;
      for (size_t t = 0; t + 2 < prim.indices.size(); t += 3) {
        const glm::uvec3 tri(prim.indices[t], prim.indices[t + 1], prim.indices[t + 2]);
        if (tri.x >= n || tri.y >= n || tri.z >= n) continue;
        if (!finite(rec.positions[tri.x]) || !finite(rec.positions[tri.y]) || !finite(rec.positions[tri.z]))
          continue;
        rec.triangles.push_back(tri);
        for (int k = 0; k < 3; ++k) bounds.extend(rec.positions[tri[k]]);
      }
      if (rec.triangles.empty()) continue;
      const Material& material = scene.materials()[prim.material];
      if (material.alphaMode == AlphaMode::Mask) {
        rec.alphaCutoff = material.alphaCutoff;
        rec.alphaFactor = material.baseColorFactor.a;
        const int32_t tex = material.baseColorTexture.texture;
        if (tex >= 0 && size_t(tex) < textures.size()) rec.alphaTexture = &textures[size_t(tex)];
      }
      geometries_.push_back(std::move(rec));
    }
  }

  for (uint32_t id = 0; id < geometries_.size(); ++id) {
    GeometryRecord& rec = geometries_[id];
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree pads its own buffers as its SIMD loads require; the data is copied.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), rec.positions.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), rec.triangles.size()));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geom);
      throwIfFailed("allocating geometry buffers");
      throw std::runtime_error("reference path tracer: Embree could not allocate geometry buffers");
    }
    for (size_t v = 0; v < rec.positions.size(); ++v) {
      // Non-finite vertices are referenced by no kept triangle; zero keeps Embree's
      // bounds finite.
      const glm::vec3 q = finite(rec.positions[v]) ? rec.positions[v] : glm::vec3(0.0f);
      vertices[3 * v] = q.x, vertices[3 * v + 1] = q.y, vertices[3 * v + 2] = q.z;
    }
    for (size_t t = 0; t < rec.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) indices[3 * t + size_t(k)] = rec.triangles[t][k];
    if (rec.alphaCutoff >= 0.0f) {
      rtcSetGeometryUserData(geom, &rec);
      rtcSetGeometryIntersectFilterFunction(geom, alphaMaskFilter);
      rtcSetGeometryOccludedFilterFunction(geom, alphaMaskFilter);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(rtcScene, geom, id);
    rtcReleaseGeometry(geom);  // the scene holds its own reference
    throwIfFailed("adding geometry");
  }
  rtcCommitScene(rtcScene);
  throwIfFailed("building the BVH");
  extent_ = bounds.empty() ? 0.0f : glm::length(bounds.size());
}

EmbreeScene::~EmbreeScene() = default;

bool EmbreeScene::traceable(const glm::vec3& org, const glm::vec3& dir, float tNear, float tFar) {
  // Embree asserts (or, without assertions, returns garbage) on rays it calls invalid:
  // origin and direction components within ±FLT_LARGE (1.844e18, embree/common/math),
  // no NaN anywhere. Such a ray can hit nothing a scene places (kMaxWorldCoordinate).
  constexpr float kFltLarge = 1.844e18f;
  const bool inRange = glm::all(glm::lessThanEqual(glm::abs(org), glm::vec3(kFltLarge))) &&
                       glm::all(glm::lessThanEqual(glm::abs(dir), glm::vec3(kFltLarge)));
  return inRange && !std::isnan(tNear) && !std::isnan(tFar) && tNear >= 0.0f && tNear <= tFar;
}

bool EmbreeScene::intersect(const glm::vec3& org, const glm::vec3& dir, float tNear, float tFar,
                            RayHit& hit) const {
  if (!traceable(org, dir, tNear, tFar)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = org.x, rh.ray.org_y = org.y, rh.ray.org_z = org.z;
  rh.ray.dir_x = dir.x, rh.ray.dir_y = dir.y, rh.ray.dir_z = dir.z;
  rh.ray.tnear = tNear;
  rh.ray.tfar = tFar;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(static_cast<RTCScene>(scene_.get()), &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = rh.ray.tfar;
  hit.geomID = rh.hit.geomID;
  hit.primID = rh.hit.primID;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  return true;
}

bool EmbreeScene::occluded(const glm::vec3& org, const glm::vec3& dir, float tNear, float tFar) const {
  if (!traceable(org, dir, tNear, tFar)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = org.x, ray.org_y = org.y, ray.org_z = org.z;
  ray.dir_x = dir.x, ray.dir_y = dir.y, ray.dir_z = dir.z;
  ray.tnear = tNear;
  ray.tfar = tFar;
  ray.mask = 0xFFFFFFFFu;
  rtcOccluded1(static_cast<RTCScene>(scene_.get()), &context, &ray);
  // Embree marks an occluded ray by setting tfar to −∞.
  return ray.tfar < 0.0f;
}

}  // namespace bounce::reference
