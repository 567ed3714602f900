// libFuzzer target: ini parsing and layering. The input is up to three ini files
// separated by a line "%%" (base, default, user); each is parsed on its own, layered
// in a ConfigStack, queried, and applied to a registry of each kind of variable.

#include "bounce/config/config_stack.h"
#include "bounce/config/cvar_registry.h"
#include "bounce/config/ini_document.h"
#include "fuzz_support.h"

namespace {

using namespace bounce;

void addVariables(CVarRegistry& cvars) {
  cvars.add(CVarDesc<int32_t>{
      .name = "r.Size", .defaultValue = 64, .min = 1, .max = 4096, .ini = {"Plugin", "Size"}});
  cvars.add(CVarDesc<int32_t>{
      .name = "r.Clamped", .defaultValue = 4, .min = 0, .max = 16, .outOfRange = RangePolicy::Clamp});
  cvars.add(CVarDesc<float>{.name = "r.Scale",
                            .defaultValue = 1.0f,
                            .min = 0.0,
                            .max = 100.0,
                            .ini = {"Plugin", "Scale"},
                            .postProcess = "Scale"});
  cvars.add(CVarDesc<bool>{.name = "r.On", .defaultValue = true});
  cvars.add(CVarDesc<int32_t>{.name = "r.Mode", .defaultValue = 0, .enumNames = {"Off", "Low", "High"}});
  cvars.add(CVarDesc<int32_t>{.name = "r.Allowed", .defaultValue = 1, .allowed = {1, 2, 4}});
  cvars.add(CVarDesc<std::string>{.name = "r.Name", .defaultValue = "x"});
  cvars.add(CVarDesc<int32_t>{.name = "r.Restart", .defaultValue = 1, .flags = CVarFlags::RequiresRestart});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<std::string_view> files = fuzz::split(fuzz::text(data, size), "\n%%\n");
  const SetBy levels[] = {SetBy::BaseIni, SetBy::DefaultIni, SetBy::UserIni};
  ConfigStack stack;
  for (size_t i = 0; i < files.size() && i < 3; ++i) {
    std::vector<IniDiagnostic> diagnostics;
    IniDocument doc = IniDocument::parse(files[i], "f.ini", diagnostics);
    const std::vector<IniEntry> entries = doc.entries();  // set() may add entries
    for (const IniEntry& e : entries) doc.set(e.section, e.key, "1");
    (void)IniDocument::parse(doc.text(), "edited.ini", diagnostics);
    stack.addText(files[i], "layer" + std::to_string(i) + ".ini", levels[i]);
  }
  for (const std::string& section : stack.sections())
    for (const std::string& key : stack.keys(section)) {
      (void)stack.get(section, key);
      (void)stack.array(section, key);
    }
  CVarRegistry cvars;
  addVariables(cvars);
  stack.applyTo(cvars, {"Plugins", "MaterialDefaults", "LightDefaults"});
  // Variables registered after the ini was applied take their deferred values.
  cvars.add(CVarDesc<float>{
      .name = "late.Value", .defaultValue = 0.5f, .min = 0.0, .max = 1.0, .ini = {"Late", "Value"}});
  return 0;
}
