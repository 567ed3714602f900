// bounce-bench's flicker metric on real renders: a technique whose image depends only on
// the scene and the view (no GI, the constant ambient term, VXGI re-voxelizing nothing)
// gives the same image every frame, so its flicker is exactly 0; the same metric reads
// a view jittered within its pixels as flicker, so a zero here is not a blind metric.

#include "render_fixture.h"
#include "temporal_stability.h"

namespace bounce::test {
namespace {

class TemporalFlicker : public RenderFixture {
 protected:
  std::vector<ImageBuffer> stillFrames(uint32_t count, bool jitter) {
    std::vector<ImageBuffer> frames;
    for (uint32_t i = 0; i < count; ++i) {
      FrameView v = view(32, 32);
      if (jitter) v.setJitter({0.25f * float(i % 3) - 0.25f, 0.25f * float(i % 2) - 0.125f});
      frames.push_back(render(v, {"radiance"}).images.at("radiance"));
    }
    return frames;
  }
};

TEST_F(TemporalFlicker, AStaticTechniqueOnAStillSceneFlickersExactlyZero) {
  for (const char* technique : {"none", "Ambient", "VXGI"}) {
    start("content/cornell_box.gltf", {"r.VXGI.MapSize=32", "r.Bloom.Intensity=0"}, technique);
    // Until the technique says it has settled (VXGI's sparse tracing fills its history
    // over k² frames), at most 64 frames.
    for (int i = 0; i < 64 && !render(32, 32, {}).settling.empty(); ++i) {
    }
    const bench::Flicker f = bench::flicker(stillFrames(32, false));
    std::printf("%s: flicker mean %.3g p95 %.3g\n", technique, f.mean, f.p95);
    EXPECT_EQ(f.mean, 0.0) << technique;
    EXPECT_EQ(f.p95, 0.0) << technique;
    finish();
  }
}

TEST_F(TemporalFlicker, TheMetricSeesAViewJitteredWithinItsPixels) {
  start("content/cornell_box.gltf", {"r.Bloom.Intensity=0"}, "none");
  const bench::Flicker f = bench::flicker(stillFrames(8, true));
  std::printf("jittered: flicker mean %.3g p95 %.3g\n", f.mean, f.p95);
  // Edges move by a quarter pixel: their pixels change by a good fraction of their value.
  EXPECT_GT(f.p95, 0.01);
  EXPECT_GT(f.mean, 0.0);
}

}  // namespace
}  // namespace bounce::test
