#include "bounce-render-bench/light_move_convergence.h"

#include "bounce/image/image_buffer.h"

#include <algorithm>
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
  std::vector<double> error(images.size());
  for (size_t i = 0; i < images.size(); ++i) error[i] = compareImages(images[i], settled).relativeRmse;
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
