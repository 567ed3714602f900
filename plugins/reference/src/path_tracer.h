#pragma once
// A progressive CPU path tracer over the same Scene the rasterizer draws: Embree for
// intersection, TBB for threads, the material model of bounce/shaders/bounce/brdf.glsl
// (glTF metallic-roughness + KHR_materials_specular; Lambert at specular 0), the light
// model of bounce/shaders/bounce/lights.glsl (radiometric units), next-event estimation
// for punctual lights and emissive triangles with MIS, and the same camera and pixels
// as bounce-render: samples spread over each pixel's square (PixelFilter::Box, the image
// `bounce-render --accumulate` converges to) or all through its centre
// (PixelFilter::Center, the very surface point one raster frame's G-buffer holds).
//
// Output decomposition (matches the rasterizer's AOVs, so GI plugins can be compared):
//   direct               emission seen at the primary hit + punctual lights' direct
//                        light there (exactly what the deferred lighting pass computes)
//   indirect-irradiance  irradiance E (W/m²) at the primary hit from everything else:
//                        emissive surfaces and every multi-bounce path
//   radiance             the full estimate: direct + the BRDF applied to that light
//
// MaxBounces counts the surfaces between a light (punctual or emissive) and the
// primary hit: 0 = direct light only (including light from emissive surfaces),
// 1 = one indirect bounce (what VXGI computes), -1 = unlimited (Russian roulette that
// keeps the estimate unbiased).
//
// Conventions where the rasterizer leaves a choice (see the sources for the reasons):
// emission leaves front faces only, both faces of double-sided materials; a visible
// back face of a single-sided material (which the rasterizer culls; closed scenes never
// show one) is shaded with its geometric normal turned toward the ray; textures are
// read bilinearly from mip 0 with repeat wrapping, through TEXCOORD_0 as the G-buffer
// does; glTF alpha masks cut geometry out for every ray, shadow rays included; lights
// with castShadows off are never occluded; the background is black.

#include "bounce/frame/frame_context.h"
#include "bounce/image/image_buffer.h"
#include "bounce/scene/scene.h"
#include "camera_ray.h"

#include <glm/glm.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bounce::reference {

struct PathTracerSettings {
  int32_t maxBounces = -1;  ///< -1: unlimited
  uint32_t seed = 1;        ///< the same seed and sample count give the same image
  /// Centre by default here, where tests compare pixels with closed forms at their centres;
  /// the plugin's r.Reference.PixelFilter defaults to Box, the antialiased image users see.
  PixelFilter pixelFilter = PixelFilter::Center;
  bool operator==(const PathTracerSettings&) const = default;
};

/// Per-pixel running sums of one view; samples accumulate across addSamples calls.
class Accumulation {
 public:
  Accumulation(uint32_t width, uint32_t height);
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  /// Samples per pixel so far.
  uint32_t samples() const { return samples_; }

  /// Means over the samples so far (RGB, linear). Pixels that hit nothing are 0.
  ImageBuffer radiance() const;
  ImageBuffer direct() const;
  ImageBuffer indirectIrradiance() const;
  /// Standard error of the radiance mean per pixel and channel: sqrt(var / n).
  ImageBuffer radianceStandardError() const;
  /// Samples dropped because they were NaN or infinite (each pixel's means are over its
  /// finite samples only).
  uint64_t droppedSamples() const { return dropped_; }

 private:
  friend class PathTracer;
  uint32_t width_, height_;
  uint32_t samples_ = 0;
  uint64_t dropped_ = 0;
  std::vector<glm::dvec3> radiance_, radianceSquared_, direct_, indirect_;
  std::vector<uint32_t> counts_;  ///< finite samples per pixel
};

class PathTracer {
 public:
  /// Builds the Embree scene (world-space triangles of every instance). Throws
  /// std::runtime_error with a one-line reason if Embree fails.
  explicit PathTracer(const Scene& scene);
  ~PathTracer();
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  /// Adds `samplesPerPixel` samples to every pixel of `accumulation` for `view` (its
  /// jitter, if any, is ignored: the pixel filter places the samples).
  /// `progress` (optional) is called from one thread with the fraction done and may
  /// return false to stop early (the samples completed for every pixel still count,
  /// whole passes only). Returns the number of samples per pixel actually added.
  uint32_t addSamples(Accumulation& accumulation, const FrameView& view, uint32_t samplesPerPixel,
                      const PathTracerSettings& settings,
                      const std::function<bool(float fraction)>& progress = {}) const;

  /// Rays traced so far (primary, bounce and shadow rays), for throughput reports.
  uint64_t raysTraced() const { return rays_.load(); }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  mutable std::atomic<uint64_t> rays_{0};
};

}  // namespace bounce::reference
