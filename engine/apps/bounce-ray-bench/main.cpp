// bounce-ray-bench: the engine's scene ray tracing on the device against Embree on the
// CPU, the same rays in the same run. A benchmark, not a test: it prints a table (and
// writes it as JSON) with the device's and Embree's rays per second (median of --runs),
// their ratio, the hit/miss disagreements, the BVH build time and bytes per triangle.
//
//   bounce-ray-bench [--scene F.gltf | --generate TRIANGLES] [--rays N]
//                    [--kind camera|probe] [--any-hit] [--shade none|rays|maps]
//                    [--lights directional|point|spot] [--runs N] [--json FILE]
//                    [--device NAME]
//
// --shade adds directLightAt at every hit, its visibility from shadow rays or from the
// engine's shadow maps (what each costs per light type; --lights turns the scene's
// lights into one type first, keeping position and direction).
//
// lavapipe runs on the same cores as Embree, so Embree's rate on all of them is the
// physical reference ("ratio"); Embree on one thread is printed too. Exit status: 0, 1
// no usable Vulkan device, 2 bad arguments or input, 3 Vulkan validation errors
// (--validation), 4 the device and Embree disagree on hit or miss for more than 1 ray in
// 10,000 (rays grazing a silhouette may tie; the tests in tests/raytracing count those).

#include "bounce/core/log.h"
#include "bounce/engine.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/pass_context.h"
#include "bounce/raytracing/ray_tracing.h"
#include "raytracing/embree_reference.h"
#include "raytracing/ray_sets.h"
#include "renderer/renderer.h"
#include "scene/generated_meshes.h"

#include "parse_arguments.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>

namespace {

using namespace bounce;

struct Options {
  std::string scene = "content/cornell_box.gltf";
  uint32_t generate = 0;
  uint32_t rays = 1u << 18;
  std::string kind = "probe";
  bool anyHit = false;
  std::string shade = "none";
  std::string lights;
  uint32_t runs = 5;
  std::string json;
  std::string device;
  bool validation = false;
};

struct BenchHit {
  float t;
  uint32_t instance, triangle, flags;
  glm::vec4 radiance;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

/// A bumpy sphere of about `triangles` triangles inside a room.
std::unique_ptr<Scene> generatedScene(uint32_t triangles) {
  auto s = std::make_unique<Scene>();
  Material white;
  white.name = "white";
  white.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  const uint32_t m = s->addMaterial(white);
  const auto rings = uint32_t(std::max(4.0, std::sqrt(double(triangles) / 2.0)));
  const uint32_t segments = std::max(4u, triangles / (2 * rings));
  s->addInstance(
      {.name = "sphere", .mesh = s->addMesh(generated::bumpySphere(rings, segments, 1.0f, 0.08f, m))});
  s->addInstance({.name = "room", .mesh = s->addMesh(generated::box({6.0f, 4.0f, 6.0f}, true, m, "room"))});
  return s;
}

std::vector<rt::Ray> makeRays(const Scene& scene, const Options& o) {
  const Aabb b = scene.bounds();
  if (o.kind == "camera") {
    const auto side = uint32_t(std::ceil(std::sqrt(double(o.rays))));
    FrameView v = FrameView::fromCamera(scene.cameras().empty() ? Camera{} : scene.cameras().front(), 16, 16);
    glm::vec3 eye = v.position, target = b.center();
    if (scene.cameras().empty()) eye = b.center() + glm::vec3(0.45f, 0.2f, 0.45f) * b.size();
    std::vector<rt::Ray> rays = rt::cameraRays(eye, target, side);
    rays.resize(o.rays);
    return rays;
  }
  Aabb inner;
  inner.extend(b.min + 0.05f * b.size());
  inner.extend(b.max - 0.05f * b.size());
  const uint32_t perProbe = 128;
  const auto probes = uint32_t(std::ceil(std::cbrt(double(o.rays) / perProbe)));
  std::vector<rt::Ray> rays = rt::probeRays(inner, probes, perProbe);
  rays.resize(o.rays);
  return rays;
}

struct DeviceRun {
  std::vector<double> milliseconds;
  std::vector<BenchHit> hits;
  rt::BuildStats build;  ///< of the first frame, which built the acceleration structure
};

DeviceRun traceOnDevice(Engine& engine, Renderer& renderer, const gpu::Device& device,
                        const std::vector<rt::Ray>& rays, const Options& o) {
  DeviceRun run;
  const uint64_t rayBytes = rays.size() * sizeof(rt::Ray), hitBytes = rays.size() * sizeof(BenchHit);
  gpu::Buffer readback(device, hitBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUsage::Readback,
                       "bench.hits");
  engine.hooks().add(
      {.name = "RayBench",
       .point = ExtensionPoint::FrameBegin,
       .setup =
           [&](RenderGraph& g, const FrameContext&) {
             BufferHandle rayBuf, hits;
             g.addPass("RayBench.Rays", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
               rayBuf = b.write(b.createBuffer("bench.rays", {rayBytes}), Access::TransferDst);
               return [=, &rays](PassContext& ctx) { ctx.upload(rayBuf, rays.data(), rayBytes); };
             });
             g.addPass("RayBench.Trace", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
               RayTracingSceneHandles rt = readRayTracingScene(b, g.blackboard());
               const SceneLightHandles lights =
                   o.shade == "none" ? SceneLightHandles{} : readSceneLights(b, g.blackboard());
               const uint32_t lightCount = uint32_t(engine.scene()->lights().size());
               BufferHandle in = b.read(rayBuf, Access::StorageRead);
               hits = b.write(b.createBuffer("bench.hits", {hitBytes}), Access::StorageWrite);
               return [=, &o](PassContext& ctx) {
                 const std::string shade = o.shade == "rays" ? "1" : o.shade == "maps" ? "2" : "0";
                 const gpu::Pipeline& p = ctx.pipelines().compute(
                     {"engine/apps/bounce-ray-bench/trace_rays.comp", {{"SHADE", shade}}});
                 gpu::Bindings bindings;
                 bindRayTracingScene(bindings, rt).buffer("Rays", in).buffer("Hits", hits);
                 if (o.shade != "none") bindings.buffer("SceneLights", lights.lights);
                 if (o.shade == "maps")
                   bindings.buffer("ShadowMatrices", lights.shadowMatrices)
                       .texture("shadowMaps", lights.shadowMaps, gpu::SamplerKind::ShadowCompare);
                 const uint32_t push[3] = {uint32_t(rays.size()), o.anyHit ? 1u : 0u, lightCount};
                 ctx.dispatchThreads(p, bindings, {uint32_t(rays.size()), 1, 1}, push, sizeof push);
               };
             });
             g.addPass("RayBench.Readback", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
               BufferHandle src = b.read(hits, Access::TransferSrc);
               b.sideEffect("benchmark read-back");
               return [=, &readback](PassContext& ctx) {
                 VkBufferCopy copy{0, 0, hitBytes};
                 vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(src).handle(), readback.handle(), 1, &copy);
               };
             });
           }},
      kEngineOwner, "bounce-ray-bench", "");
  const FrameView view = FrameView::fromCamera(Camera{}, 8, 8);
  // Frame 0 builds the BVH and compiles the kernel; the runs after it are timed.
  for (uint32_t frame = 0; frame <= o.runs; ++frame) {
    RenderedFrame f = renderer.render(view, {}, frame);
    if (!f.gpu.ok()) throw std::runtime_error(f.gpu.errors.front());
    if (frame == 0) {
      run.build = renderer.rayTracingScene().stats();
      continue;
    }
    for (const gpu::PassTiming& t : f.gpu.passes)
      if (t.name == "RayBench.Trace") run.milliseconds.push_back(t.milliseconds);
  }
  engine.hooks().removeOwnedBy(kEngineOwner);
  run.hits.resize(rays.size());
  std::memcpy(run.hits.data(), readback.mapped(), hitBytes);
  return run;
}

/// Embree's rtcIntersect1 (rtcOccluded1 for any-hit rays) over the rays on
/// `threads` threads; returns the median milliseconds and the hits of the last run.
double traceWithEmbree(const rt::EmbreeReference& reference, const std::vector<rt::Ray>& rays, bool anyHit,
                       uint32_t threads, uint32_t runs, std::vector<rt::ReferenceHit>& hits) {
  hits.assign(rays.size(), {});
  std::vector<double> ms;
  for (uint32_t r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (uint32_t t = 0; t < threads; ++t)
      // Contiguous ranges: interleaved indices would share cache lines between threads.
      pool.emplace_back([&, t] {
        const size_t begin = rays.size() * t / threads, end = rays.size() * (t + 1) / threads;
        for (size_t i = begin; i < end; ++i)
          if (anyHit)
            hits[i].hit = reference.occluded(glm::vec3(rays[i].origin), glm::vec3(rays[i].direction),
                                             rays[i].origin.w, rays[i].direction.w);
          else
            hits[i] = reference.intersect(glm::vec3(rays[i].origin), glm::vec3(rays[i].direction),
                                          rays[i].origin.w, rays[i].direction.w);
      });
    for (std::thread& th : pool) th.join();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return median(ms);
}

int run(const Options& o) {
  EngineOptions eo;
  eo.userIni = std::filesystem::path();
  eo.technique = "none";
  Engine engine(std::move(eo));
  if (auto failure = app::commandLineFailure(engine, "bounce-ray-bench")) return *failure;
  std::string sceneName = o.scene;
  if (o.generate > 0) {
    engine.setScene(generatedScene(o.generate));
    sceneName = fmt::format("generated ({} triangles)", engine.scene()->triangleCount());
  } else {
    GltfLoadResult r = engine.loadScene(o.scene);
    if (!r.scene && !engine.scene()) {
      app::printError("bounce-ray-bench", r.error);
      return 2;
    }
  }
  std::string error;
  std::unique_ptr<gpu::Device> device =
      gpu::Device::create({.preferredDevice = o.device, .validation = o.validation}, &error);
  if (!device) {
    app::printError("bounce-ray-bench", error);
    return 1;
  }
  Renderer renderer(engine, *device);
  if (!o.lights.empty()) {
    const LightType type = o.lights == "directional" ? LightType::Directional
                           : o.lights == "point"     ? LightType::Point
                                                     : LightType::Spot;
    for (uint32_t i = 0; i < engine.scene()->lights().size(); ++i)
      engine.scene()->editLight(i, [&](Light& l) {
        l.type = type;
        if (type == LightType::Spot) l.outerConeAngle = 0.9f;
      });
  }
  const Scene& scene = *engine.scene();
  const std::vector<rt::Ray> rays = makeRays(scene, o);

  DeviceRun dev = traceOnDevice(engine, renderer, *device, rays, o);
  const rt::RayTracingScene& rts = renderer.rayTracingScene();
  const rt::BuildStats& stats = dev.build;

  rt::EmbreeReference reference(scene);
  std::vector<rt::ReferenceHit> ref;
  const uint32_t cores = std::max(1u, std::thread::hardware_concurrency());
  const double embreeOneMs = traceWithEmbree(reference, rays, o.anyHit, 1, o.runs, ref);
  const double embreeAllMs = traceWithEmbree(reference, rays, o.anyHit, cores, o.runs, ref);
  uint64_t disagreements = 0, hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const bool h = dev.hits[i].flags & 1u;
    disagreements += h != ref[i].hit;
    hits += h;
  }
  const double deviceMs = median(dev.milliseconds);
  auto rate = [&](double ms) { return ms > 0.0 ? double(rays.size()) / (ms * 1e-3) : 0.0; };
  const uint64_t triangles = rts.triangles().size();
  const double bytesPerTriangle = triangles ? double(rts.bytes()) / double(triangles) : 0.0;

  fmt::print("bounce-ray-bench: {} | {} rays, {} ({}{}), {} lights{}, {} runs, device {}\n", sceneName,
             rays.size(), o.kind, o.anyHit ? "any hit" : "closest hit",
             o.shade == "none"   ? ""
             : o.shade == "rays" ? ", directLightAt with shadow rays"
                                 : ", directLightAt with shadow maps",
             scene.lights().size(), o.lights.empty() ? "" : " (" + o.lights + ")", o.runs, device->name());
  fmt::print(
      "| triangles | BVH build ms (bottom + top) | bytes/triangle | depth | device Mrays/s | Embree Mrays/s "
      "({} threads) | Embree Mrays/s (1 thread) | device / Embree | hit rate | hit/miss disagreements |\n",
      cores);
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  fmt::print("| {} | {:.1f} + {:.2f} | {:.0f} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.3f} | {} |\n",
             triangles, stats.bottomLevelMs, stats.topLevelMs, bytesPerTriangle, stats.maxDepth,
             rate(deviceMs) / 1e6, rate(embreeAllMs) / 1e6, rate(embreeOneMs) / 1e6,
             rate(deviceMs) / std::max(rate(embreeAllMs), 1e-9),
             double(hits) / double(std::max<size_t>(rays.size(), 1)), disagreements);
  if (!o.json.empty()) {
    nlohmann::json j = {{"scene", sceneName},
                        {"rays", rays.size()},
                        {"kind", o.kind},
                        {"anyHit", o.anyHit},
                        {"shade", o.shade},
                        {"lights", o.lights},
                        {"runs", o.runs},
                        {"device", device->name()},
                        {"triangles", triangles},
                        {"bottomLevelBuildMs", stats.bottomLevelMs},
                        {"topLevelBuildMs", stats.topLevelMs},
                        {"bytes", rts.bytes()},
                        {"bytesPerTriangle", bytesPerTriangle},
                        {"depth", stats.maxDepth},
                        {"deviceMilliseconds", dev.milliseconds},
                        {"deviceRaysPerSecond", rate(deviceMs)},
                        {"embreeThreads", cores},
                        {"embreeRaysPerSecond", rate(embreeAllMs)},
                        {"embreeSingleThreadRaysPerSecond", rate(embreeOneMs)},
                        {"deviceToEmbree", rate(deviceMs) / std::max(rate(embreeAllMs), 1e-9)},
                        {"hitRate", double(hits) / double(std::max<size_t>(rays.size(), 1))},
                        {"hitMissDisagreements", disagreements}};
    std::ofstream out(o.json);
    out << j.dump(2) << "\n";
    out.close();
    if (!out) {
      app::printError("bounce-ray-bench", fmt::format("--json {}: cannot write", o.json));
      return 2;
    }
  }
  if (device->validationErrorCount() > 0) {
    app::printError("bounce-ray-bench",
                    fmt::format("{} Vulkan validation errors", device->validationErrorCount()));
    return 3;
  }
  if (disagreements * 10000 > rays.size()) {
    app::printError("bounce-ray-bench", fmt::format("the device and Embree disagree on {} of {} rays",
                                                    disagreements, rays.size()));
    return 4;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Scene ray tracing on the device against Embree on the CPU, same rays, same run"};
  app::acceptUnrealSpellings(app);
  Options o;
  app.add_option("--scene", o.scene, "glTF scene (default content/cornell_box.gltf)");
  app.add_option("--generate", o.generate, "Trace a generated scene of about this many triangles instead")
      ->check(CLI::Range(1u, 20000000u));
  app.add_option("--rays", o.rays, "Rays per run (default 262144)")->check(CLI::Range(1u, 1u << 24));
  app.add_option("--kind", o.kind, "camera: pinhole rays; probe: spherical rays from a grid of probes")
      ->check(CLI::IsMember({"camera", "probe"}));
  app.add_flag("--any-hit", o.anyHit, "Visibility rays (stop at the first hit) instead of closest hit");
  app.add_option("--shade", o.shade,
                 "Shade hits with directLightAt: none, rays (shadow rays) or maps (shadow maps)")
      ->check(CLI::IsMember({"none", "rays", "maps"}));
  app.add_option("--lights", o.lights, "Turn every light into this type first")
      ->check(CLI::IsMember({"directional", "point", "spot"}));
  app.add_option("--runs", o.runs, "Timed runs (the median is reported; default 5)")
      ->check(CLI::Range(1u, 1000u));
  app.add_option("--json", o.json, "Also write the results to this JSON file");
  app.add_option("--device", o.device, "Vulkan device name (substring)");
  app.add_flag("--validation", o.validation, "Vulkan validation layer on; any error exits with status 3");
  // Bad values exit 2 with one line, as in every app (CLI11's own codes, 105 for an
  // out-of-range value, are not Bounce's).
  if (auto status = bounce::app::parseArguments(app, argc, argv, "bounce-ray-bench")) return *status;
  try {
    return run(o);
  } catch (const std::exception& e) {
    app::printError("bounce-ray-bench", e.what());
    return 2;
  }
}
