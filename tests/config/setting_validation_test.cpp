// One validator for every path that writes a setting: a value an ini file, -set, the
// console or a post-process volume gives is refused, clamped or accepted the same way
// (CVar::check / checkNumber), whichever path it arrives by. The benchmark paths
// (quality knobs, --variant) are in tests/bench; viewer scripts in tests/viewer.

#include "bounce/config/config_stack.h"
#include "bounce/config/console.h"
#include "bounce/config/cvar_registry.h"
#include "bounce/core/log.h"
#include "bounce/frame/post_process_settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

namespace bounce {
namespace {

/// What a path made of one value: refused (the variable keeps its value) or stored.
struct Outcome {
  bool refused = false;
  double stored = 0.0;  ///< the variable's (or blended) value afterwards
  std::string message;
};

class SettingValidation : public ::testing::Test {
 protected:
  // Declared as VXGI declares its sparsity and cones, plus a size and a float range.
  CVarRegistry cvars;
  CVarRef<int32_t> sparsity = cvars.add<int32_t>(
      {.name = "r.T.Sparsity", .defaultValue = 2, .allowed = {1, 2, 4}, .postProcess = "TSparsity"});
  CVarRef<int32_t> cones = cvars.add<int32_t>({.name = "r.T.Cones",
                                               .defaultValue = 8,
                                               .min = 1,
                                               .max = 32,
                                               .outOfRange = RangePolicy::Clamp,
                                               .postProcess = "TCones"});
  CVarRef<int32_t> size =
      cvars.add<int32_t>({.name = "r.T.Size", .defaultValue = 64, .min = 1, .postProcess = "TSize"});
  CVarRef<float> intensity = cvars.add<float>(
      {.name = "r.T.Intensity", .defaultValue = 1.0f, .min = 0.0, .max = 10.0, .postProcess = "TIntensity"});

  double current(const std::string& name) const {
    const CVar* c = cvars.find(name);
    return c->type() == CVarType::Float ? double(c->getFloat()) : double(c->getInt());
  }

  Outcome viaIni(const std::string& name, const std::string& text) {
    ConfigStack stack;
    stack.addText("[SystemSettings]\n" + name + "=" + text + "\n", "test.ini", SetBy::UserIni);
    log::Capture log;  // a clamped ini value is a logged warning; a refused one an error too
    const std::vector<CVarRegistry::Refused> refused = stack.applyTo(cvars, {});
    return {!refused.empty(), current(name), refused.empty() ? log.joined() : refused.front().message};
  }
  Outcome viaCommandLine(const std::string& name, const std::string& text) {
    const SetResult r = cvars.set(name, text, SetBy::CommandLine, "command line");
    return {r.status == SetResult::Status::Rejected, current(name), r.message};
  }
  Outcome viaConsole(const std::string& name, const std::string& text) {
    Console console(cvars);
    const ConsoleResult r = console.execute(name + " " + text);
    return {!r.ok, current(name), r.lines.empty() ? "" : r.lines.front()};
  }
  Outcome viaVolume(const std::string& name, double number) {
    Scene scene;
    PostProcessVolume v;
    v.name = "Room";
    v.unbound = true;
    v.settings[cvars.find(name)->postProcessName()] = number;
    scene.addPostProcessVolume(v);
    std::vector<std::string> warnings;
    const PostProcessSettings pp = PostProcessSettings::blend(scene, cvars, {0, 0, 0}, &warnings);
    const CVar& c = *cvars.find(name);
    const double value = c.type() == CVarType::Float ? double(pp.get<float>(c)) : double(pp.get<int32_t>(c));
    // A refused volume value leaves the variable's own value and says it was ignored.
    const bool ignored = !warnings.empty() && warnings.front().find("; ignored") != std::string::npos;
    return {ignored, value, warnings.empty() ? "" : warnings.front()};
  }
};

struct Case {
  const char* setting;
  const char* text;  ///< as an ini file, -set or the console spells it
  double number;     ///< as a post-process volume's JSON gives it
  bool refused;
  double stored;  ///< the value afterwards (the unchanged one when refused)
  const char* message;
};

class SameOutcomeOnEveryPath : public SettingValidation, public ::testing::WithParamInterface<Case> {};

TEST_P(SameOutcomeOnEveryPath, IniCommandLineConsoleAndVolumesAgree) {
  const Case& c = GetParam();
  log::Capture quiet;  // the registry logs ini and command-line refusals; asserted below instead
  struct Path {
    const char* name;
    Outcome outcome;
  };
  // Each path starts from the declared defaults: a fresh registry per path would hide
  // nothing here, since refused values never change the variable.
  const Path paths[] = {{"ini", viaIni(c.setting, c.text)},
                        {"command line", viaCommandLine(c.setting, c.text)},
                        {"console", viaConsole(c.setting, c.text)},
                        {"post-process volume", viaVolume(c.setting, c.number)}};
  for (const Path& p : paths) {
    EXPECT_EQ(p.outcome.refused, c.refused) << p.name << ": " << p.outcome.message;
    EXPECT_DOUBLE_EQ(p.outcome.stored, c.stored) << p.name << ": " << p.outcome.message;
    EXPECT_NE(p.outcome.message.find(c.message), std::string::npos) << p.name << ": " << p.outcome.message;
  }
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

INSTANTIATE_TEST_SUITE_P(
    Values, SameOutcomeOnEveryPath,
    ::testing::Values(
        // Sparsity divides a resolution: 0 and 3 are not allowed values.
        Case{"r.T.Sparsity", "0", 0.0, true, 2, "r.T.Sparsity: 0 is not one of 1, 2, 4"},
        Case{"r.T.Sparsity", "3", 3.0, true, 2, "r.T.Sparsity: 3 is not one of 1, 2, 4"},
        Case{"r.T.Sparsity", "4", 4.0, false, 4, ""},
        // 3e9 does not fit an int32: out of range (clamped, as the declaration says), never wrapped.
        Case{"r.T.Cones", "3e9", 3e9, false, 32, "r.T.Cones: 3000000000 is outside [1, 32]; clamped to 32"},
        Case{"r.T.Cones", "3000000000", 3e9, false, 32, "clamped to 32"},
        Case{"r.T.Cones", "-1", -1.0, false, 1, "r.T.Cones: -1 is outside [1, 32]; clamped to 1"},
        Case{"r.T.Size", "-1", -1.0, true, 64, "r.T.Size: -1 is outside [1, ...]"},
        Case{"r.T.Size", "1e10", 1e10, true, 64, "r.T.Size: 10000000000 is not a 32-bit integer"},
        Case{"r.T.Intensity", "nan", kNaN, true, 1, "is not a finite number"},
        Case{"r.T.Intensity", "11", 11.0, true, 1, "r.T.Intensity: 11 is outside [0, 10]"},
        Case{"r.T.Intensity", "2.5", 2.5, false, 2.5, ""}),
    [](const ::testing::TestParamInfo<Case>& info) { return "Case" + std::to_string(info.index); });

TEST_F(SettingValidation, TextWhereANumberBelongsIsRefusedOnEveryPath) {
  log::Capture quiet;
  EXPECT_TRUE(viaIni("r.T.Size", "abc").refused);
  EXPECT_TRUE(viaCommandLine("r.T.Size", "abc").refused);
  EXPECT_TRUE(viaConsole("r.T.Size", "abc").refused);
  EXPECT_TRUE(viaIni("r.T.Intensity", "1e400").refused);  // beyond double: not a number at all
  EXPECT_TRUE(viaIni("r.T.Cones", "2.5").refused);        // not an integer
  Scene scene;
  PostProcessVolume v;
  v.name = "Room";
  v.unbound = true;
  v.settings["TSize"] = std::string("abc");
  scene.addPostProcessVolume(v);
  std::vector<std::string> warnings;
  const PostProcessSettings pp = PostProcessSettings::blend(scene, cvars, {0, 0, 0}, &warnings);
  EXPECT_EQ(pp.get<int32_t>(size.cvar()), 64);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("r.T.Size: 'abc' is text, not a number; ignored"), std::string::npos)
      << warnings[0];
  EXPECT_EQ(size.get(), 64);
}

TEST_F(SettingValidation, ABlendOfAllowedFloatsSnapsToTheNearestAllowedValue) {
  // Ints switch at weight 0.5, so a blend of two allowed ints is always one of them; a
  // float interpolates, and one with an allowed list snaps to the nearest allowed value.
  CVarRef<float> scale = cvars.add<float>(
      {.name = "r.T.Scale", .defaultValue = 2.0f, .allowed = {0.5f, 1.0f, 2.0f}, .postProcess = "TScale"});
  Scene scene;
  PostProcessVolume v;
  v.name = "Half";
  v.unbound = true;
  v.settings["TScale"] = 0.5;
  auto blendAt = [&](float weight) {
    Scene s;
    PostProcessVolume w = v;
    w.blendWeight = weight;
    s.addPostProcessVolume(w);
    return PostProcessSettings::blend(s, cvars, {0, 0, 0}).get<float>(scale.cvar());
  };
  EXPECT_FLOAT_EQ(blendAt(1.0f), 0.5f);
  EXPECT_FLOAT_EQ(blendAt(0.3f), 2.0f);  // 2 − 1.5 × 0.3 = 1.55: nearest is 2
  EXPECT_FLOAT_EQ(blendAt(0.4f), 1.0f);  // 1.4: nearest is 1
  EXPECT_FLOAT_EQ(blendAt(0.0f), 2.0f);
  // Sparsity switches: weight 0.49 keeps 2, 0.5 takes the volume's 4; never 3.
  PostProcessVolume s4;
  s4.name = "Sparse";
  s4.unbound = true;
  s4.settings["TSparsity"] = 4.0;
  for (float weight : {0.0f, 0.25f, 0.49f, 0.5f, 0.75f, 1.0f}) {
    Scene s;
    s4.blendWeight = weight;
    s.addPostProcessVolume(s4);
    const int32_t k = PostProcessSettings::blend(s, cvars, {0, 0, 0}).get<int32_t>(sparsity.cvar());
    EXPECT_EQ(k, weight >= 0.5f ? 4 : 2) << weight;
  }
}

}  // namespace
}  // namespace bounce
