// Sunlit rooms against the one-bounce path tracer (issue 16): closed rooms lit only by the
// sun through a window. The outer faces of the walls and the roof are lit some 90 times
// brighter than anything inside, so a little of their emittance reaching the room's cones
// outweighs the room's own one bounce.

#include "vxgi_test_support.h"

#include "bounce/image/image_buffer.h"

#include <fmt/format.h>

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
  std::array<double, 6> vxgi{}, reference{};  // mean indirect irradiance (rgb mean), W/m²
  std::array<uint32_t, 6> pixels{};
  double vxgiAll = 0, referenceAll = 0;  // over every surface pixel
  double ratio(int wall) const { return vxgi[wall] / std::max(reference[wall], 1e-9); }
};

class VxgiSunlitRoom : public RenderFixture {
 protected:
  WallLight measure(const std::string& scene, const std::vector<std::string>& sets);
};

// 2048 paths per pixel: over each wall's region (60..1500 pixels of the 64² view) two
// seeds of the reference differ by at most 1.1% (measured on the 10 cm room).
WallLight VxgiSunlitRoom::measure(const std::string& scene, const std::vector<std::string>& sets) {
  VxgiSunlitRoom& t = *this;
  WallLight w;
  t.start(scene, with(kSmall, with({"r.VXGI.DiffuseSparsity=1"}, sets)), "VXGI");
  RenderedFrame vxgi = t.render(64, 64, {"indirect-irradiance"});
  for (const char* line :
       {"r.Reference.MaxBounces 1", "r.Reference.SamplesPerPixel 2048", "r.GI.Technique Reference"})
    t.engine->console().execute(line);
  RenderedFrame reference = t.render(64, 64, {"indirect-irradiance", "normal"});
  const ImageBuffer &a = vxgi.images.at("indirect-irradiance"),
                    &b = reference.images.at("indirect-irradiance"), &n = reference.images.at("normal");
  EXPECT_TRUE(allFinite(a));
  uint32_t all = 0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      const int wall = wallOf(n, x, y);
      if (wall < 0) continue;
      const double va = (a.at(x, y, 0) + a.at(x, y, 1) + a.at(x, y, 2)) / 3.0;
      const double vb = (b.at(x, y, 0) + b.at(x, y, 1) + b.at(x, y, 2)) / 3.0;
      w.vxgi[wall] += va;
      w.reference[wall] += vb;
      ++w.pixels[wall];
      w.vxgiAll += va;
      w.referenceAll += vb;
      ++all;
    }
  for (int i = 0; i < 6; ++i) {
    w.vxgi[i] /= std::max(w.pixels[i], 1u);
    w.reference[i] /= std::max(w.pixels[i], 1u);
  }
  w.vxgiAll /= std::max(all, 1u);
  w.referenceAll /= std::max(all, 1u);
  std::printf("%s:", scene.c_str());
  for (const std::string& s : sets) std::printf(" %s", s.c_str());
  std::printf("\n  interior: VXGI / one-bounce reference = %.3f\n",
              w.vxgiAll / std::max(w.referenceAll, 1e-9));
  // The floor reads 0 in the reference: it cannot see the sun patch it holds, and the only
  // other sunlit surface inside, the sill, faces up too; its light is the second bounce on.
  for (int i = 0; i < 6; ++i)
    if (w.pixels[i] > 0) {
      const std::string ratio = w.reference[i] > 1e-4 ? fmt::format("{:.3f}", w.ratio(i)) : "-";
      std::printf("  %s (%u px): VXGI %.4f, reference %.4f W/m², ratio %s\n", kWalls[i], w.pixels[i],
                  w.vxgi[i], w.reference[i], ratio.c_str());
    }
  t.finish();
  return w;
}

TEST_F(VxgiSunlitRoom, SunlitOuterFacesDoNotFloodTheRoom) {
  // Three rooms seen from the back, facing the window wall: 10 cm walls, 20 cm walls, and
  // 10 cm walls with the window 1 m off centre; 10 cm voxels at level 0 (64³ × 3 levels),
  // so the thin walls are a voxel thick and share coarser voxels with the outside.
  //
  // Until the voxelizer took a fragment's depth span from the flat normal (voxelize.frag),
  // derivatives taken after a discard spread the sunlit outer faces' emittance two voxels
  // into the room: the window wall read 28 / 24 / 22 times the path tracer's one bounce and
  // the whole view 24 / 21 / 19 times. Now it reads 2.6 / 2.3 / 2.9 and the view 3.5 / 3.2
  // / 3.9 (the cone filter's width, trace_cone.glsl, brought 5.0 → 2.6 of that).
  // Bounds: the window wall below 4 and the view below 5 times the reference, the measured
  // values plus 40% (well above the reference's ~2% noise), and far below the old leak.
  //
  // Not met yet: no wall brighter than the reference. What remains is the roof's and the
  // outer faces' emittance in voxels of the coarser levels and the mip pyramid, which
  // straddle the 10–20 cm walls and ceiling; a filter around a sample inside the room
  // weighs them from behind or beside the cone. With the roof and the window wall's outer
  // face left unlit in the voxelization (a shader experiment), the same view reads 0.71 of
  // the reference (walls 0.68–0.90): their few percent of filter weight, 90 times brighter,
  // make the rest.
  struct Case {
    const char* scene;
    double windowWall, view;  // measured ratios to the reference
  };
  for (const Case& c : {Case{"content/tests/sunlit_room_10cm_window_view.gltf", 2.63, 3.48},
                        Case{"content/tests/sunlit_room_window_view.gltf", 2.30, 3.20},
                        Case{"content/tests/sunlit_room_10cm_offset_window.gltf", 2.88, 3.94}}) {
    const WallLight w = measure(c.scene, {"r.VXGI.MapSize=64", "r.VXGI.VoxelSize=0.1"});
    ASSERT_GT(w.pixels[5], 1000u) << c.scene << ": the window wall fills most of the view";
    EXPECT_LT(w.ratio(5), 4.0) << c.scene << " (measured " << c.windowWall << ")";
    EXPECT_LT(w.vxgiAll / w.referenceAll, 5.0) << c.scene << " (measured " << c.view << ")";
    // The light that is there comes from the sun patch: the window wall sees it at least
    // as brightly as the reference (a fix that just darkened everything would fail here).
    EXPECT_GT(w.ratio(5), 0.8) << c.scene;
  }
}

}  // namespace
}  // namespace bounce::test
