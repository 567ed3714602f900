// Sunlit rooms against the path tracer (issue 16): closed rooms lit only by the sun through
// a window. The outer faces of the walls and the roof are lit some 90 times brighter than
// anything inside, so a little of their emittance reaching the room's cones outweighs the
// room's own one bounce. Each wall is held to the path tracer's one bounce (what VXGI
// computes, within the bounds each test gives) and to its every bounce (an upper bound for
// any one-bounce method: no wall may exceed it).

#include "vxgi_test_support.h"

#include "bounce/image/image_buffer.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace bounce::test {
namespace {

/// Surfaces of the view by the axis their normal is closest to: 0 +x (the left wall),
/// 1 −x (right wall), 2 +y (floor), 3 −y (ceiling), 4 +z (back wall), 5 −z (window wall).
constexpr std::array<const char*, 6> kWalls = {"left wall", "right wall", "floor",
                                               "ceiling",   "back wall",  "window wall"};

int wallOf(const ImageBuffer& normal, uint32_t x, uint32_t y) {
  int best = -1;
  float largest = 0.5f;  // background and unusable normals: none
  for (uint32_t a = 0; a < 3; ++a) {
    const float n = normal.at(x, y, a);
    if (std::abs(n) > largest) {
      largest = std::abs(n);
      best = int(2 * a) + (n < 0.0f ? 1 : 0);
    }
  }
  return best;
}

struct WallLight {
  // Mean indirect irradiance (rgb mean), W/m²: VXGI's, the path tracer's one bounce
  // (reference) and its every bounce (allBounces).
  std::array<double, 6> vxgi{}, reference{}, allBounces{};
  std::array<uint32_t, 6> pixels{};
  double vxgiAll = 0, referenceAll = 0, allBouncesAll = 0;  // over every surface pixel
  double ratio(int wall) const { return vxgi[wall] / std::max(reference[wall], 1e-9); }
};

class VxgiSunlitRoom : public RenderFixture {
 protected:
  WallLight measure(const std::string& scene, const std::vector<std::string>& sets);
};

// 2048 paths per pixel: over each wall's region (60..1500 pixels of the 64² view) two
// seeds of the one-bounce reference differ by at most 1.1% (measured on the 10 cm room).
WallLight VxgiSunlitRoom::measure(const std::string& scene, const std::vector<std::string>& sets) {
  VxgiSunlitRoom& t = *this;
  WallLight w;
  t.start(scene, with(kSmall, with({"r.VXGI.DiffuseSparsity=1"}, sets)), "VXGI");
  RenderedFrame vxgi = t.render(64, 64, {"indirect-irradiance"});
  for (const char* line : {"r.Reference.MaxBounces 1", "r.Reference.SamplesPerPixel 2048",
                           "r.Reference.PixelFilter Center", "r.GI.Technique Reference"})
    t.engine->console().execute(line);
  RenderedFrame reference = t.render(64, 64, {"indirect-irradiance", "normal"});
  // Every bounce, at 512 paths per pixel: its bound below has a margin of a third or more.
  t.engine->console().execute("r.Reference.MaxBounces -1");
  t.engine->console().execute("r.Reference.SamplesPerPixel 512");
  RenderedFrame allBounces = t.render(64, 64, {"indirect-irradiance"});
  const ImageBuffer &a = vxgi.images.at("indirect-irradiance"),
                    &b = reference.images.at("indirect-irradiance"), &n = reference.images.at("normal"),
                    &c = allBounces.images.at("indirect-irradiance");
  EXPECT_TRUE(allFinite(a));
  uint32_t all = 0;
  auto rgbMean = [](const ImageBuffer& image, uint32_t x, uint32_t y) {
    return (image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2)) / 3.0;
  };
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      const int wall = wallOf(n, x, y);
      if (wall < 0) continue;
      const double va = rgbMean(a, x, y), vb = rgbMean(b, x, y), vc = rgbMean(c, x, y);
      w.vxgi[wall] += va;
      w.reference[wall] += vb;
      w.allBounces[wall] += vc;
      ++w.pixels[wall];
      w.vxgiAll += va;
      w.referenceAll += vb;
      w.allBouncesAll += vc;
      ++all;
    }
  for (int i = 0; i < 6; ++i) {
    w.vxgi[i] /= std::max(w.pixels[i], 1u);
    w.reference[i] /= std::max(w.pixels[i], 1u);
    w.allBounces[i] /= std::max(w.pixels[i], 1u);
  }
  w.vxgiAll /= std::max(all, 1u);
  w.referenceAll /= std::max(all, 1u);
  w.allBouncesAll /= std::max(all, 1u);
  std::printf("%s:", scene.c_str());
  for (const std::string& s : sets) std::printf(" %s", s.c_str());
  std::printf("\n  interior: VXGI / one-bounce reference = %.3f, / all bounces = %.3f\n",
              w.vxgiAll / std::max(w.referenceAll, 1e-9), w.vxgiAll / std::max(w.allBouncesAll, 1e-9));
  // The floor reads 0 in the one-bounce reference: it cannot see the sun patch it holds, and
  // the only other sunlit surface inside, the sill, faces up too; its light is the second
  // bounce on.
  for (int i = 0; i < 6; ++i)
    if (w.pixels[i] > 0) {
      const std::string ratio = w.reference[i] > 1e-4 ? fmt::format("{:.3f}", w.ratio(i)) : "-";
      std::printf(
          "  %s (%u px): VXGI %.4f, reference %.4f W/m², ratio %s; all bounces %.4f W/m², ratio %.3f\n",
          kWalls[i], w.pixels[i], w.vxgi[i], w.reference[i], ratio.c_str(), w.allBounces[i],
          w.vxgi[i] / std::max(w.allBounces[i], 1e-9));
    }
  t.finish();
  return w;
}

// VXGI gathers one bounce of the light, so on no wall may it exceed what the path tracer
// finds with every bounce: light a one-bounce method shows beyond that did not reach the
// wall through the room. The full light is 3.0–3.4 times the one bounce on these walls and
// 1.9–2.1 times on the ceiling (albedo 0.6; with the sun at 50°, 2.1–2.2 and 1.5), and the
// floor, which holds the sun patch, has no one bounce at all, so this bound is looser than
// the one-bounce ratios and holds whatever the cones' pattern. Measured: at most 0.67 with
// the sun at 30° (the 20 cm room's right wall at 64³), 0.87 at 50° (its ceiling). At the
// defaults the high-sun room's ceiling reaches it (1.00; vxgi README, "Known gaps"), so that
// room is not among DefaultSettingsKeepTheOuterFacesOut's. Before the coarser fetch stayed in front of the
// apex (clip_map.glsl, vxgiCoarsePosition) the 10 cm room's window wall read 1.6 times
// the full light at the defaults.
void expectNoWallAboveAllBounces(const WallLight& w, const std::string& scene) {
  for (int i = 0; i < 6; ++i) {
    if (w.pixels[i] > 0) {
      EXPECT_LT(w.vxgi[i], w.allBounces[i])
          << scene << ", " << kWalls[i] << ": VXGI's one bounce " << w.vxgi[i]
          << " W/m² above the path tracer's every bounce " << w.allBounces[i];
    }
  }
}

double brightestWall(const WallLight& w) {
  double largest = 0;
  for (int i = 0; i < 6; ++i)
    if (w.pixels[i] > 0 && w.reference[i] > 1e-4) largest = std::max(largest, w.ratio(i));
  return largest;
}

TEST_F(VxgiSunlitRoom, SunlitOuterFacesDoNotFloodTheRoom) {
  // Four rooms seen from the back, facing the window wall: 10 cm walls, 20 cm walls,
  // 10 cm walls with the window 1 m off centre, and 20 cm walls with the sun at 50° instead
  // of 30° (its patch a metre nearer the window wall, its light on the roof 1.4 times as
  // strong); 10 cm voxels at level 0 (64³ × 3 levels), so the thin walls are a voxel thick
  // and share coarser voxels with the outside.
  //
  // Until the voxelizer took a fragment's depth span from the flat normal (voxelize.frag),
  // derivatives taken after a discard spread the sunlit outer faces' emittance two voxels
  // into the room: the window wall read 28 / 24 / 22 times the path tracer's one bounce and
  // the whole view 24 / 21 / 19 times. Then 2.6 / 2.3 / 2.9 and the view 3.5 / 3.2 / 3.9,
  // the side walls 5.2–12.7: the filters of the cones' samples, as wide as the cones,
  // reached behind the cones' apexes into the roof's and the outer faces' emittance. Now
  // that each facing direction reads only what lies in front of the apex (clip_map.glsl,
  // vxgiSampleAhead): window wall 1.14 / 1.12 / 1.04, view 1.21 / 1.21 / 1.08, the
  // brightest wall 1.97 / 2.15 / 1.44. Since the coarser level's fetch also stays in front
  // of the apex across the cone's main axis and in front of the surface the cone leaves
  // (vxgiCoarsePosition): window wall 1.28 / 1.26 / 1.19, view 1.30 / 1.30 / 1.16, the
  // brightest wall 1.92 / 2.10 / 1.20 (the right one; the left ones read 1.15 / 1.15 / 1.10,
  // the 8 cones are not mirror images on the two walls; with 32 they agreed, 0.91–1.22).
  // The high sun (added in stop 36, not tuned for): window wall 1.25, view 1.25, brightest
  // wall 1.36 (the left one), every wall at most 0.87 of every bounce. Since an opaque
  // voxel is α = 0.99 and a cone stops at 0.8 opacity (stop 41; clip_map.glsl,
  // trace_cone.glsl): window wall 1.27 / 1.26 / 1.16 / 1.31, view 1.29 / 1.30 / 1.13 /
  // 1.30, brightest wall 1.81 / 1.96 / 1.19 / 1.40, every wall at most 0.86 of every bounce.
  // Bounds: the measured values plus 10–25% (the reference's noise is ~2%): window wall
  // below 1.4, view below 1.5, every wall below 2.4; each fails the code before 6bc1895.
  // Against every bounce of the path tracer no wall is brighter (expectNoWallAboveAllBounces):
  // measured 0.23–0.87. Against its one bounce the side walls still differ (above).
  struct Case {
    const char* scene;
    double windowWall, view, brightest;  // measured ratios to the reference
  };
  for (const Case& c : {Case{"content/tests/sunlit_room_10cm_window_view.gltf", 1.27, 1.29, 1.81},
                        Case{"content/tests/sunlit_room_window_view.gltf", 1.26, 1.30, 1.96},
                        Case{"content/tests/sunlit_room_10cm_offset_window.gltf", 1.16, 1.13, 1.19},
                        Case{"content/tests/sunlit_room_high_sun_window_view.gltf", 1.31, 1.30, 1.40}}) {
    const WallLight w = measure(c.scene, {"r.VXGI.MapSize=64", "r.VXGI.VoxelSize=0.1"});
    ASSERT_GT(w.pixels[5], 1000u) << c.scene << ": the window wall fills most of the view";
    EXPECT_LT(w.ratio(5), 1.4) << c.scene << " (measured " << c.windowWall << ")";
    EXPECT_LT(w.vxgiAll / w.referenceAll, 1.5) << c.scene << " (measured " << c.view << ")";
    EXPECT_LT(brightestWall(w), 2.4) << c.scene << " (measured " << c.brightest << ")";
    // The light that is there comes from the sun patch: the window wall sees it at least
    // nearly as brightly as the reference (a fix that just darkened everything would fail here).
    EXPECT_GT(w.ratio(5), 0.8) << c.scene;
    expectNoWallAboveAllBounces(w, c.scene);
  }
}

TEST_F(VxgiSunlitRoom, DefaultSettingsKeepTheOuterFacesOut) {
  // The same 10 cm and 20 cm rooms at the defaults a new user gets: a 128³ map, 5 levels,
  // the finest voxel chosen from the scene's size (6.9 and 7.2 cm here), so the walls are
  // 1.4 and 2.8 voxels thick at the finest level and a tenth and a fifth of one at the
  // coarsest (1.1 m).
  // Before each facing direction read only what lies in front of the cone's apex, the view
  // read 7.8 and 4.4 times the one-bounce reference, the brightest wall 9.6 and 7.1. Then
  // the view read 4.07 and 2.11, the window wall 4.88 and 2.42: the sunlit outer faces,
  // through the coarser of each sample's two levels, which could still reach 1.5 of its
  // voxels behind the apex (1.1 m voxels at the coarsest level, and the pyramid's upper mip
  // coarser still; the z-facing slot of samples 1–3 m into the room carried it all,
  // measured by zeroing it by distance). Since that fetch moves until it cannot
  // (clip_map.glsl, vxgiCoarsePosition): view 1.19 and 1.15, window wall 1.00 and 1.03,
  // brightest wall 1.73 and 1.58 (the right one again). Since an opaque voxel is α = 0.99
  // and a cone stops at 0.8 opacity (stop 41): view 1.11 and 1.15, window wall 0.91 and
  // 1.01, brightest wall 1.62 and 1.55 (the left and the right one), every wall at most 0.71
  // of every bounce.
  // Bounds: the measured values plus about 25%: view below 1.5, every wall below 2.2, the
  // window wall within [0.8, 1.3]. The code before fails the view and window wall bounds,
  // and the 10 cm room's window wall is then above every bounce of the path tracer (1.63×);
  // now every wall is at most 0.66 of it.
  struct Case {
    const char* scene;
    double view, windowWall, brightest;
  };
  for (const Case& c : {Case{"content/tests/sunlit_room_10cm_window_view.gltf", 1.11, 0.91, 1.62},
                        Case{"content/tests/sunlit_room_window_view.gltf", 1.15, 1.01, 1.55}}) {
    const WallLight w = measure(c.scene, {"r.VXGI.MapSize=128", "r.VXGI.StackLevels=5"});
    EXPECT_LT(w.vxgiAll / w.referenceAll, 1.5) << c.scene << " (measured " << c.view << ")";
    EXPECT_LT(brightestWall(w), 2.2) << c.scene << " (measured " << c.brightest << ")";
    EXPECT_LT(w.ratio(5), 1.3) << c.scene << " (measured " << c.windowWall << ")";
    EXPECT_GT(w.ratio(5), 0.8) << c.scene;
    expectNoWallAboveAllBounces(w, c.scene);
  }
}

TEST_F(VxgiSunlitRoom, MultiBounceAtTheDefaultsLightsTheRoomAsEveryBounceDoes) {
  // The four rooms at the defaults (128³ × 5, r.VXGI.Bounces 3) against the path tracer's
  // every bounce, which is what lights a sunlit interior: most of its light has bounced more
  // than once (3.0–3.4 times the one bounce on the walls). With one bounce VXGI read 0.2–0.5
  // of it there, and the floor in front of the sun patch, which only light bounced twice or
  // more reaches, read 0.01 (bounce-bench; the one-bounce tests above).
  // Measured, as VXGI / every bounce (10 cm, 20 cm, window off centre, sun at 50°): view 0.95,
  // 0.96, 0.89, 1.17; walls 0.77–1.13 in the first three rooms and 0.82–1.42 in the high-sun
  // one, whose window wall and ceiling carry the one bounce's excess at the defaults ("Known
  // gaps", "A high sun"); floor 1.03, 1.03, 0.96, 1.02. With 4 bounces the views read 1.03–1.31:
  // every bounce adds the one bounce's excess of 1.0–1.2 again. Since an opaque voxel is
  // α = 0.99 and a cone stops at 0.8 opacity (stop 41): view 0.91, 0.91, 0.85, 1.16; walls
  // 0.73–1.16 and 0.80–1.40; floor 0.97, 0.96, 0.94, 1.01.
  // Bounds: the view within [0.8, 1.35], every wall within [0.6, 1.7], the floor at least
  // 0.8 (each with a margin of 10–25%; the reference's noise is ~2%). One bounce fails the
  // view's and the floor's bounds in every room.
  for (const char* scene :
       {"content/tests/sunlit_room_10cm_window_view.gltf", "content/tests/sunlit_room_window_view.gltf",
        "content/tests/sunlit_room_10cm_offset_window.gltf",
        "content/tests/sunlit_room_high_sun_window_view.gltf"}) {
    const WallLight w = measure(scene, {"r.VXGI.MapSize=128", "r.VXGI.StackLevels=5", "r.VXGI.Bounces=3"});
    const double view = w.vxgiAll / std::max(w.allBouncesAll, 1e-9);
    EXPECT_GT(view, 0.8) << scene;
    EXPECT_LT(view, 1.35) << scene;
    for (int i = 0; i < 6; ++i) {
      if (w.pixels[i] == 0) continue;
      const double ratio = w.vxgi[i] / std::max(w.allBounces[i], 1e-9);
      EXPECT_GT(ratio, 0.6) << scene << ", " << kWalls[i];
      EXPECT_LT(ratio, 1.7) << scene << ", " << kWalls[i];
    }
    ASSERT_GT(w.pixels[2], 1000u) << scene << ": the floor fills the lower part of the view";
    EXPECT_GT(w.vxgi[2] / std::max(w.allBounces[2], 1e-9), 0.8)
        << scene << ": the floor's light is bounced light";
  }
}

}  // namespace
}  // namespace bounce::test
