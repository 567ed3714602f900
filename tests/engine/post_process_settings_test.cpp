// Post-process volume blending, as Unreal does it.

#include "bounce/frame/post_process_settings.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace bounce {
namespace {

class PostProcessBlend : public ::testing::Test {
 protected:
  PostProcessVolume volume(std::string name, float priority, bool unbound, glm::mat4 world = glm::mat4(1.0f),
                           float radius = 1.0f) {
    PostProcessVolume v;
    v.name = std::move(name);
    v.priority = priority;
    v.unbound = unbound;
    v.world = world;
    v.blendRadius = radius;
    return v;
  }
  float intensity(const Scene& s, glm::vec3 p) {
    return PostProcessSettings::blend(s, cvars, p).get<float>(intensityVar.cvar());
  }
  CVarRegistry cvars;
  CVarRef<float> intensityVar = cvars.add<float>(
      {.name = "r.X.Intensity", .defaultValue = 1.0f, .min = 0.0, .max = 10.0, .postProcess = "Intensity"});
  CVarRef<int32_t> cones =
      cvars.add<int32_t>({.name = "r.X.Cones", .defaultValue = 8, .postProcess = "Cones"});
  CVarRef<bool> enabled =
      cvars.add<bool>({.name = "r.X.Enabled", .defaultValue = true, .postProcess = "Enabled"});
  CVarRef<float> notOverridable = cvars.add<float>({.name = "r.X.Other", .defaultValue = 3.0f});
};

TEST_F(PostProcessBlend, WithoutVolumesTheVariableValueIsUsed) {
  Scene s;
  EXPECT_FLOAT_EQ(intensity(s, {0, 0, 0}), 1.0f);
  cvars.set("r.X.Intensity", "2", SetBy::Console);
  EXPECT_FLOAT_EQ(intensity(s, {0, 0, 0}), 2.0f);
}

TEST_F(PostProcessBlend, UnboundVolumeAppliesEverywhereByItsWeight) {
  Scene s;
  PostProcessVolume v = volume("Global", 0, true);
  v.settings["Intensity"] = 5.0;
  v.blendWeight = 0.5f;
  s.addPostProcessVolume(v);
  EXPECT_FLOAT_EQ(intensity(s, {100, 0, 0}), 3.0f);  // 1 + (5 − 1) × 0.5
}

TEST_F(PostProcessBlend, BoundVolumeFadesOverItsBlendRadius) {
  Scene s;
  // A 2×2×2 box around the origin (the node's unit transform on [-1,1]³), radius 2.
  PostProcessVolume v = volume("Room", 0, false, glm::mat4(1.0f), 2.0f);
  v.settings["Intensity"] = 9.0;
  s.addPostProcessVolume(v);
  EXPECT_FLOAT_EQ(intensity(s, {0, 0, 0}), 9.0f);     // inside: full weight
  EXPECT_FLOAT_EQ(intensity(s, {1, 0.5f, 0}), 9.0f);  // on the face
  EXPECT_FLOAT_EQ(intensity(s, {2, 0, 0}), 5.0f);     // 1 m out of 2: weight 0.5
  EXPECT_FLOAT_EQ(intensity(s, {3, 0, 0}), 1.0f);     // at the radius: no effect
  EXPECT_FLOAT_EQ(intensity(s, {10, 0, 0}), 1.0f);
}

TEST_F(PostProcessBlend, DistanceHonoursRotationAndScale) {
  glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)) *
                    glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0)) *
                    glm::scale(glm::mat4(1.0f), glm::vec3(4, 1, 1));
  // Rotated 90° about y, the 4× x-extent points along −z.
  EXPECT_FLOAT_EQ(PostProcessSettings::distanceToVolume(world, {10, 0, -3.5f}), 0.0f);
  EXPECT_FLOAT_EQ(PostProcessSettings::distanceToVolume(world, {10, 0, -5.0f}), 1.0f);
  EXPECT_FLOAT_EQ(PostProcessSettings::distanceToVolume(world, {12, 0, 0}), 1.0f);
  EXPECT_NEAR(PostProcessSettings::distanceToVolume(world, {12, 2, 0}), std::sqrt(2.0f), 1e-5f);
  // A degenerate (zero-scale) box still gives a finite distance.
  glm::mat4 flat = glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1));
  EXPECT_FLOAT_EQ(PostProcessSettings::distanceToVolume(flat, {0, 2, 0}), 2.0f);
}

TEST_F(PostProcessBlend, UnboundFirstThenBoundByPriority) {
  Scene s;
  PostProcessVolume high = volume("High", 10, false);
  high.settings["Intensity"] = 8.0;
  PostProcessVolume low = volume("Low", 1, false);
  low.settings["Intensity"] = 2.0;
  PostProcessVolume global = volume("Global", 100, true);  // priority 100 but unbound: first
  global.settings["Intensity"] = 4.0;
  s.addPostProcessVolume(high);
  s.addPostProcessVolume(global);
  s.addPostProcessVolume(low);
  PostProcessSettings pp = PostProcessSettings::blend(s, cvars, {0, 0, 0});
  ASSERT_EQ(pp.weights().size(), 3u);
  EXPECT_EQ(pp.weights()[0].first, "Global");
  EXPECT_EQ(pp.weights()[1].first, "Low");
  EXPECT_EQ(pp.weights()[2].first, "High");
  EXPECT_FLOAT_EQ(pp.get<float>(intensityVar.cvar()), 8.0f);  // the highest-priority bound volume wins
}

TEST_F(PostProcessBlend, PartialWeightsChainLikeUnreal) {
  Scene s;
  PostProcessVolume a = volume("A", 0, true);
  a.settings["Intensity"] = 5.0;
  a.blendWeight = 0.5f;
  PostProcessVolume b = volume("B", 1, true);
  b.settings["Intensity"] = 9.0;
  b.blendWeight = 0.25f;
  s.addPostProcessVolume(a);
  s.addPostProcessVolume(b);
  // 1 → lerp(1, 5, 0.5) = 3 → lerp(3, 9, 0.25) = 4.5
  EXPECT_FLOAT_EQ(intensity(s, {0, 0, 0}), 4.5f);
}

TEST_F(PostProcessBlend, NonFloatSettingsSwitchAtHalfWeight) {
  Scene s;
  PostProcessVolume v = volume("Room", 0, false, glm::mat4(1.0f), 2.0f);
  v.settings["Cones"] = 16.0;
  v.settings["Enabled"] = false;
  s.addPostProcessVolume(v);
  auto at = [&](float x) { return PostProcessSettings::blend(s, cvars, {x, 0, 0}); };
  EXPECT_EQ(at(1.9f).get<int32_t>(cones.cvar()), 16);  // weight 0.55
  EXPECT_FALSE(at(1.9f).get<bool>(enabled.cvar()));
  EXPECT_EQ(at(2.1f).get<int32_t>(cones.cvar()), 8);  // weight 0.45
  EXPECT_TRUE(at(2.1f).get<bool>(enabled.cvar()));
}

TEST_F(PostProcessBlend, BadSettingsWarnAndAreIgnored) {
  Scene s;
  PostProcessVolume v = volume("Room", 0, true);
  v.settings["Intensty"] = 5.0;               // typo
  v.settings["Cones"] = std::string("many");  // wrong type
  v.settings["Intensity"] = 1.0e9;            // out of range: refused, as -set would (RangePolicy::Reject)
  s.addPostProcessVolume(v);
  std::vector<std::string> warnings;
  PostProcessSettings pp = PostProcessSettings::blend(s, cvars, {0, 0, 0}, &warnings);
  ASSERT_EQ(warnings.size(), 3u);
  std::string all = warnings[0] + "\n" + warnings[1] + "\n" + warnings[2];
  EXPECT_NE(all.find("post-process volume 'Room': unknown setting 'Intensty' (did you mean 'Intensity'"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("post-process volume 'Room': Cones: r.X.Cones: 'many' is text, not a number; ignored"),
            std::string::npos)
      << all;
  EXPECT_NE(
      all.find(
          "post-process volume 'Room': Intensity: r.X.Intensity: 1000000000 is outside [0, 10]; ignored"),
      std::string::npos)
      << all;
  EXPECT_EQ(pp.get<int32_t>(cones.cvar()), 8);
  EXPECT_FLOAT_EQ(pp.get<float>(intensityVar.cvar()), 1.0f);
  EXPECT_FLOAT_EQ(pp.get<float>(notOverridable.cvar()), 3.0f);
}

TEST_F(PostProcessBlend, DisabledVolumesAndZeroRadiusOutsideDoNothing) {
  Scene s;
  PostProcessVolume off = volume("Off", 0, true);
  off.enabled = false;
  off.settings["Intensity"] = 5.0;
  PostProcessVolume hard = volume("Hard", 0, false, glm::mat4(1.0f), 0.0f);
  hard.settings["Intensity"] = 7.0;
  s.addPostProcessVolume(off);
  s.addPostProcessVolume(hard);
  EXPECT_FLOAT_EQ(intensity(s, {1.5f, 0, 0}), 1.0f);
  EXPECT_FLOAT_EQ(intensity(s, {0.5f, 0, 0}), 7.0f);
}

}  // namespace
}  // namespace bounce
