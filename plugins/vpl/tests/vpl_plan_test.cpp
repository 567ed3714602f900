// The VPL generation plan without a GPU: path shares, flux per path, the merge grid and
// the fixed-point scale.

#include "vpl_plan.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bounce::vpl {
namespace {

constexpr float kPi = 3.14159265358979f;

Scene roomWithLights(std::vector<Light> lights) {
  Scene s;
  Material m;
  const uint32_t mat = s.addMaterial(m);
  Mesh mesh;
  MeshPrimitive p;
  p.positions = {{0, 0, 0}, {4, 0, 0}, {0, 2, 3}};
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  p.indices = {0, 1, 2};
  p.material = mat;
  mesh.primitives.push_back(p);
  MeshInstance inst;
  inst.mesh = s.addMesh(mesh);
  s.addInstance(inst);
  for (const Light& l : lights) s.addLight(l);
  return s;
}

Light point(float intensity) {
  Light l;
  l.type = LightType::Point;
  l.intensity = intensity;
  return l;
}

TEST(VplPlan, PathsAreSharedByPowerAndAddUp) {
  const Scene s = roomWithLights({point(1.0f), point(3.0f), point(0.0f)});
  const VplPlan p = planVpls(s, {true, true, true}, {.paths = 1001});
  ASSERT_TRUE(p.lit) << p.reason;
  ASSERT_EQ(p.sources.size(), 2u);  // the dark light gets no paths
  EXPECT_EQ(p.paths, 1001u);
  EXPECT_EQ(p.sources[0].info.z + p.sources[1].info.z, 1001u);
  EXPECT_NEAR(double(p.sources[1].info.z) / p.sources[0].info.z, 3.0, 0.02);
  EXPECT_EQ(p.sources[1].info.y, p.sources[0].info.z);  // contiguous ranges
  // Σ over a light's paths of I × Ω/n = 4πI: the light's whole flux.
  for (const VplSource& src : p.sources) EXPECT_NEAR(src.scale.x * float(src.info.z), 4.0f * kPi, 1e-4f);
  EXPECT_NEAR(p.totalPower, 4.0f * kPi * 4.0f, 1e-3f);
}

TEST(VplPlan, NoFlaggedOrNoPowerfulLightMeansNothingToDo) {
  const Scene s = roomWithLights({point(1.0f)});
  VplPlan p = planVpls(s, {false}, {});
  EXPECT_FALSE(p.lit);
  EXPECT_NE(p.reason.find("no light casts VPLs"), std::string::npos) << p.reason;
  p = planVpls(roomWithLights({point(0.0f)}), {true}, {});
  EXPECT_FALSE(p.lit);
  p = planVpls(roomWithLights({}), {}, {});
  EXPECT_FALSE(p.lit);
  p = planVpls(s, {true}, {.enabled = false});
  EXPECT_FALSE(p.lit);
  EXPECT_NE(p.reason.find("r.VPL.Enable is 0"), std::string::npos);
}

TEST(VplPlan, SpotAndDirectionalFluxPerPath) {
  Light spot = point(2.0f);
  spot.type = LightType::Spot;
  spot.outerConeAngle = 0.5f;
  Light sun = point(5.0f);
  sun.type = LightType::Directional;
  const Scene s = roomWithLights({spot, sun});
  const VplPlan p = planVpls(s, {true, true}, {.paths = 4000});
  ASSERT_EQ(p.sources.size(), 2u);
  const float omega = 2.0f * kPi * (1.0f - std::cos(0.5f));
  EXPECT_NEAR(p.sources[0].scale.x * float(p.sources[0].info.z), omega, 1e-4f);
  const float radius = 0.5f * glm::length(glm::vec3(4, 2, 3));
  EXPECT_NEAR(p.sources[1].disk.w, radius, 1e-5f);
  EXPECT_NEAR(p.sources[1].scale.x * float(p.sources[1].info.z), kPi * radius * radius, 1e-3f);
}

TEST(VplPlan, GridCoversTheSceneWithAMarginAndIsCoarsenedWhenTooFine) {
  const Scene s = roomWithLights({point(1.0f)});
  VplPlan p = planVpls(s, {true}, {.gridResolution = 8});
  EXPECT_FLOAT_EQ(p.grid.cell, 0.5f);  // longest side 4 m / 8
  EXPECT_EQ(p.grid.dims, glm::uvec3(9, 5, 7));
  const glm::vec3 far = p.grid.origin + glm::vec3(p.grid.dims) * p.grid.cell;
  EXPECT_TRUE(glm::all(glm::lessThan(p.grid.origin, glm::vec3(0.0f))));
  EXPECT_TRUE(glm::all(glm::greaterThan(far, glm::vec3(4, 2, 3))));
  p = planVpls(s, {true}, {.gridCell = 1e-4f});
  EXPECT_LE(p.grid.slots(), kMaxSlots);
  EXPECT_LE(std::max({p.grid.dims.x, p.grid.dims.y, p.grid.dims.z}), kMaxCellsPerAxis);
  EXPECT_FALSE(p.notes.empty());
}

TEST(VplPlan, FixedPointScaleKeepsEverySumBelowTwoToThe30) {
  const Scene s = roomWithLights({point(7.0f), point(1.0f)});
  const VplPlan p = planVpls(s, {true, true}, {.paths = 100, .bounces = 3});
  EXPECT_NEAR(double(p.fluxQuantum) * double(1u << 30), double(p.totalPower) * 3.0, 1e-3 * p.totalPower);
  // The capacity of the list: every raw VPL, or every grid slot, whichever is fewer.
  EXPECT_EQ(p.capacity, std::min<uint64_t>(300, p.grid.slots()));
  const VplPlan unmerged = planVpls(s, {true, true}, {.paths = 100, .bounces = 3, .merge = false});
  EXPECT_EQ(unmerged.capacity, 300u);
}

TEST(VplPlan, EmissiveTrianglesAreOneMoreSourceWithAnExactWeight) {
  // The room's one triangle made emissive (Le = 2, area 0.5·|(4,0,0)×(0,2,3)|), and a point
  // light: the emitter gets its share of the paths by power π·A·Le, Σ_t p_t = 1, and
  // radiance × π × (area / p) / n over n paths is the emitter's whole flux.
  Scene s = roomWithLights({point(1.0f)});
  s.editMaterial(0, [](Material& m) { m.emissiveFactor = glm::vec3(2.0f); });
  double power = 0.0;
  const std::vector<VplEmitter> emitters = emissiveTriangles(s, power);
  ASSERT_EQ(emitters.size(), 1u);
  const float area = 0.5f * glm::length(glm::cross(glm::vec3(4, 0, 0), glm::vec3(0, 2, 3)));
  EXPECT_NEAR(power, kPi * area * 2.0, 1e-4);
  EXPECT_FLOAT_EQ(emitters[0].normal.w, 1.0f);
  EXPECT_NEAR(emitters[0].weight.x, area, 1e-5f);
  EXPECT_NEAR(glm::length(glm::vec3(emitters[0].normal)), 1.0f, 1e-6f);
  const VplPlan p = planVpls(s, {true}, {.paths = 1000}, emitters, power);
  ASSERT_EQ(p.sources.size(), 2u);
  EXPECT_EQ(p.sources[1].info.w, kSourceEmissive);
  EXPECT_EQ(p.vplsPerPath, 2u);  // the emitter's own VPL and one bounce
  const double expectedShare = 1000.0 * power / (power + 4.0 * kPi);
  EXPECT_NEAR(double(p.sources[1].info.z), expectedShare, 1.0);
  EXPECT_NEAR(p.sources[1].scale.x * float(p.sources[1].info.z) * emitters[0].weight.x * 2.0f, power, 1e-3);
  // Switched off: the point light alone, one VPL per path.
  const VplPlan off = planVpls(s, {true}, {.paths = 1000, .emissive = false}, emitters, power);
  EXPECT_EQ(off.sources.size(), 1u);
  EXPECT_EQ(off.vplsPerPath, 1u);
}

}  // namespace
}  // namespace bounce::vpl
