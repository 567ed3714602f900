#include "path_tracer.h"

#include "camera_ray.h"
#include "path_integrator.h"

#include "bounce/core/log.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>

namespace bounce::reference {

namespace {

// Square tiles: neighbouring pixels share BVH nodes and textures in cache, and 256
// pixels per task keep scheduling overhead negligible.
constexpr uint32_t kTileSize = 16;

}  // namespace

struct PathTracer::Impl {
  explicit Impl(const Scene& scene) : scene(scene) {}
  TraceScene scene;
  std::atomic<bool> warnedNonFinite{false};
};

PathTracer::PathTracer(const Scene& scene) : impl_(std::make_unique<Impl>(scene)) {
  log::debug("reference path tracer: {} geometries, {} punctual lights, {} emissive triangles",
             impl_->scene.embree.geometries().size(), impl_->scene.lights.size(),
             impl_->scene.emitters.triangleCount());
}

PathTracer::~PathTracer() = default;

uint32_t PathTracer::addSamples(Accumulation& acc, const FrameView& view, uint32_t samplesPerPixel,
                                const PathTracerSettings& settings,
                                const std::function<bool(float fraction)>& progress) const {
  if (acc.width() != view.width || acc.height() != view.height) {
    throw std::invalid_argument(
        fmt::format("reference path tracer: accumulation is {}x{} but the view is {}x{}", acc.width(),
                    acc.height(), view.width, view.height));
  }
  const uint32_t width = acc.width(), height = acc.height();
  const uint32_t tilesX = (width + kTileSize - 1) / kTileSize;
  const uint32_t tilesY = (height + kTileSize - 1) / kTileSize;
  const PathIntegrator integrator(impl_->scene, settings);
  FrameView centred = view;
  centred.setJitter(glm::vec2(0.0f));
  const bool box = settings.pixelFilter == PixelFilter::Box;

  uint32_t added = 0;
  uint64_t droppedNow = 0;
  while (added < samplesPerPixel) {
    // One pass: one more sample for every pixel. The sample index continues across
    // calls, so 2 × 8 samples give the same image as 16.
    const uint32_t sampleIndex = acc.samples_;
    std::atomic<uint64_t> rays{0}, dropped{0};
    tbb::parallel_for(
        tbb::blocked_range<uint32_t>(0, tilesX * tilesY, 1), [&](const tbb::blocked_range<uint32_t>& r) {
          uint64_t localRays = 0, localDropped = 0;
          for (uint32_t tile = r.begin(); tile != r.end(); ++tile) {
            const uint32_t x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
            for (uint32_t y = y0; y < std::min(y0 + kTileSize, height); ++y) {
              for (uint32_t x = x0; x < std::min(x0 + kTileSize, width); ++x) {
                const uint32_t pixel = y * width + x;
                const glm::vec2 offset =
                    box ? pixelFootprintOffset(pixel, sampleIndex, settings.seed) : glm::vec2(0.0f);
                const PathEstimate e = integrator.estimate(cameraRay(centred, x, y, width, height, offset),
                                                           pixel, sampleIndex, localRays);
                if (!e.finite()) {
                  ++localDropped;  // never reaches the sums
                  continue;
                }
                const glm::dvec3 radiance(e.radiance);
                acc.radiance_[pixel] += radiance;
                acc.radianceSquared_[pixel] += radiance * radiance;
                acc.direct_[pixel] += glm::dvec3(e.direct);
                acc.indirect_[pixel] += glm::dvec3(e.irradiance);
                ++acc.counts_[pixel];
              }
            }
          }
          rays += localRays;
          dropped += localDropped;
        });
    rays_ += rays.load();
    acc.dropped_ += dropped.load();
    droppedNow += dropped.load();
    ++acc.samples_;
    ++added;
    // Whole passes only: every pixel has the same number of samples when we stop.
    if (progress && !progress(float(added) / float(samplesPerPixel))) break;
  }
  if (droppedNow > 0 && !impl_->warnedNonFinite.exchange(true)) {
    log::warn(
        "reference path tracer: dropped {} NaN/Inf samples (left out of the means; further drops are only "
        "counted)",
        droppedNow);
  }
  return added;
}

}  // namespace bounce::reference
