#include "bounce-render-bench/light_move_convergence.h"

#include "bounce/image/image_buffer.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bounce {

LightMoveConvergence measureLightMoveConvergence(Engine& engine, Renderer& renderer, const FrameView& view,
                                                 glm::vec3 offset, uint32_t warmup, uint32_t frames) {
  LightMoveConvergence out;
  Scene* scene = engine.scene();
  if (!scene || scene->lights().empty()) {
    out.error = "the scene has no light to move";
    return out;
  }
  FrameOutputs outputs;
  outputs.aovs = {"indirect-irradiance"};
  uint64_t index = 1u << 20;  // frame numbers after the per-pass runs
  for (uint32_t f = 0; f < warmup; ++f) {
    RenderedFrame r = renderer.render(view, outputs, index++);
    if (!r.gpu.ok()) {
      out.error = r.gpu.errors.front();
      return out;
    }
  }
  scene->editLight(0, [&](Light& l) { l.position += offset; });
  std::vector<ImageBuffer> images;
  std::vector<double> ms;
  for (uint32_t f = 0; f < frames; ++f) {
    RenderedFrame r = renderer.render(view, outputs, index++);
    if (!r.gpu.ok()) {
      out.error = r.gpu.errors.front();
      return out;
    }
    images.push_back(r.images.at("indirect-irradiance"));
    ms.push_back(r.gpu.frameMilliseconds);
  }
  out.framesRun = frames;
  // The settled image: the mean of the last 10% of the frames (at least one).
  const size_t tail = std::max<size_t>(1, images.size() / 10);
  ImageBuffer settled = images.back();
  std::fill(settled.pixels.begin(), settled.pixels.end(), 0.0f);
  for (size_t i = images.size() - tail; i < images.size(); ++i)
    for (size_t p = 0; p < settled.pixels.size(); ++p) settled.pixels[p] += images[i].pixels[p] / float(tail);
  // Frames averaged over a window of 8 (the window's lag, 3.5 frames, is reported with
  // the count) against the settled image, less the averaged frames' own noise: what a
  // settled technique still shows from window to window (the tail's RMSE against its mean)
  // comes off in quadrature, so the error is how far the light itself still has to go.
  const size_t window = std::min<size_t>(8, tail);
  std::vector<ImageBuffer> averaged(images.size(), settled);
  for (size_t i = 0; i < images.size(); ++i) {
    const size_t from = i + 1 >= window ? i + 1 - window : 0;
    std::fill(averaged[i].pixels.begin(), averaged[i].pixels.end(), 0.0f);
    for (size_t j = from; j <= i; ++j)
      for (size_t p = 0; p < settled.pixels.size(); ++p)
        averaged[i].pixels[p] += images[j].pixels[p] / float(i + 1 - from);
  }
  std::vector<double> rmse(images.size());
  for (size_t i = 0; i < images.size(); ++i) rmse[i] = compareImages(averaged[i], settled).relativeRmse;
  double noise2 = 0.0;
  for (size_t i = images.size() - tail; i < images.size(); ++i) noise2 = std::max(noise2, rmse[i] * rmse[i]);
  std::vector<double> error(images.size());
  for (size_t i = 0; i < images.size(); ++i) error[i] = std::sqrt(std::max(0.0, rmse[i] * rmse[i] - noise2));
  out.noise = std::sqrt(noise2);
  // The first frame after which the error stays under the bound, within the frames before the tail.
  auto settle = [&](double bound, uint32_t& framesTo, double& msTo) {
    const size_t last = images.size() - tail;
    size_t first = last;
    for (size_t i = last; i-- > 0;) {
      if (!(error[i] < bound)) break;
      first = i;
    }
    if (first >= last) return;
    framesTo = uint32_t(first + 1);
    for (size_t i = 0; i <= first; ++i) msTo += ms[i];
  };
  settle(0.05, out.framesTo5, out.msTo5);
  settle(0.02, out.framesTo2, out.msTo2);
  return out;
}

}  // namespace bounce
