// The ini files checked in under config/ must load cleanly: a syntax error there would
// greet every user of the engine with an error at start-up.

#include "bounce/config/config_stack.h"
#include "bounce/config/ini_document.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bounce {
namespace {

class CheckedInConfig : public testing::TestWithParam<std::string> {
 protected:
  std::string path() const { return std::string(BOUNCE_SOURCE_DIR) + "/config/" + GetParam(); }
};

TEST_P(CheckedInConfig, ParsesWithoutDiagnostics) {
  std::vector<IniDiagnostic> diagnostics;
  std::optional<IniDocument> doc = IniDocument::load(path(), diagnostics);
  ASSERT_TRUE(doc.has_value());
  for (const IniDiagnostic& d : diagnostics) ADD_FAILURE() << d.where() << ": " << d.message;
}

TEST_P(CheckedInConfig, HasTheSectionsTheEngineReads) {
  std::vector<IniDiagnostic> diagnostics;
  std::optional<IniDocument> doc = IniDocument::load(path(), diagnostics);
  ASSERT_TRUE(doc.has_value());
  // The sections may be empty (only comments), so look at the headers themselves.
  const std::string text = "\n" + doc->text();
  for (const char* section : {"[SystemSettings]", "[Plugins]", "[MaterialDefaults]", "[LightDefaults]"})
    EXPECT_NE(text.find(std::string("\n") + section + "\n"), std::string::npos) << section;
}

INSTANTIATE_TEST_SUITE_P(Files, CheckedInConfig, testing::Values("BaseEngine.ini", "DefaultEngine.ini"));

TEST(CheckedInConfigStack, BaseAndDefaultLoadAsRequiredLayers) {
  ConfigStack stack;
  EXPECT_TRUE(stack.addFile(std::string(BOUNCE_SOURCE_DIR) + "/config/BaseEngine.ini", SetBy::BaseIni, true));
  EXPECT_TRUE(
      stack.addFile(std::string(BOUNCE_SOURCE_DIR) + "/config/DefaultEngine.ini", SetBy::DefaultIni, true));
  EXPECT_TRUE(stack.diagnostics().empty());
}

}  // namespace
}  // namespace bounce
