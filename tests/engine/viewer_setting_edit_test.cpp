// The viewer's Settings-panel widgets write through applySettingEdit: a value the
// variable's declaration refuses is refused with an error line in the console (the
// variable keeps its value), one it clamps is clamped with a warning — the same outcome
// and message the console gives for the same text. Compiled in from the viewer's app
// folder: it needs no window.

#include "bounce-viewer/setting_edit.h"
#include "bounce/config/console.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace bounce::viewer {
namespace {

class SettingEdit : public ::testing::Test {
 protected:
  CVarRegistry cvars;
  ConsoleLog log;
  CVarRef<int32_t> sparsity =
      cvars.add<int32_t>({.name = "r.T.Sparsity", .defaultValue = 2, .allowed = {1, 2, 4}});
  CVarRef<int32_t> cones = cvars.add<int32_t>(
      {.name = "r.T.Cones", .defaultValue = 8, .min = 1, .max = 32, .outOfRange = RangePolicy::Clamp});
  CVarRef<int32_t> size = cvars.add<int32_t>({.name = "r.T.Size", .defaultValue = 64, .min = 1});
  CVarRef<float> intensity =
      cvars.add<float>({.name = "r.T.Intensity", .defaultValue = 1.0f, .min = 0.0, .max = 10.0});

  // What the console says for the same text, from a registry in the same state.
  std::string consoleSays(const std::string& name, const std::string& text) {
    CVarRegistry fresh;
    fresh.add<int32_t>({.name = "r.T.Sparsity", .defaultValue = 2, .allowed = {1, 2, 4}});
    fresh.add<int32_t>(
        {.name = "r.T.Cones", .defaultValue = 8, .min = 1, .max = 32, .outOfRange = RangePolicy::Clamp});
    fresh.add<int32_t>({.name = "r.T.Size", .defaultValue = 64, .min = 1});
    fresh.add<float>({.name = "r.T.Intensity", .defaultValue = 1.0f, .min = 0.0, .max = 10.0});
    return Console(fresh).execute(name + " " + text).lines.at(0);
  }
  std::vector<ConsoleLine> linesOf(LineKind kind) const {
    std::vector<ConsoleLine> out;
    for (const ConsoleLine& l : log.lines())
      if (l.kind == kind) out.push_back(l);
    return out;
  }
};

TEST_F(SettingEdit, RefusedWidgetValuesKeepTheVariableAndSayWhyAsTheConsoleDoes) {
  // Texts as the widgets make them: std::to_string of an InputInt, fmt "{}" of a float.
  const std::pair<CVar*, std::string> refused[] = {{&sparsity.cvar(), std::to_string(3)},
                                                   {&sparsity.cvar(), std::to_string(0)},
                                                   {&size.cvar(), std::to_string(-1)},
                                                   {&intensity.cvar(), fmt::format("{}", 11.5f)}};
  for (const auto& [cvar, text] : refused) {
    const std::string before = cvar->valueText();
    EXPECT_FALSE(applySettingEdit(cvars, log, *cvar, text)) << cvar->name() << " " << text;
    EXPECT_EQ(cvar->valueText(), before);
    ASSERT_FALSE(linesOf(LineKind::Error).empty());
    EXPECT_EQ(linesOf(LineKind::Error).back().text, consoleSays(cvar->name(), text));
  }
  EXPECT_EQ(linesOf(LineKind::Error).size(), 4u);
  EXPECT_EQ(sparsity.get(), 2);
  EXPECT_EQ(size.get(), 64);
}

TEST_F(SettingEdit, ClampedWidgetValuesAreClampedWithAWarning) {
  EXPECT_TRUE(applySettingEdit(cvars, log, cones.cvar(), std::to_string(100)));
  EXPECT_EQ(cones.get(), 32);
  ASSERT_EQ(linesOf(LineKind::Warning).size(), 1u);
  EXPECT_EQ(linesOf(LineKind::Warning)[0].text, "r.T.Cones: 100 is outside [1, 32]; clamped to 32");
  EXPECT_EQ(linesOf(LineKind::Warning)[0].text, consoleSays("r.T.Cones", "100"));
  EXPECT_TRUE(applySettingEdit(cvars, log, sparsity.cvar(), "4"));
  EXPECT_EQ(sparsity.get(), 4);
  EXPECT_TRUE(linesOf(LineKind::Error).empty());
}

}  // namespace
}  // namespace bounce::viewer
