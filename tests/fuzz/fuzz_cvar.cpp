// libFuzzer target: console-variable value parsing. The input is a value text; it is
// parsed and set as every kind of variable (bool, int with a range, clamped int, float,
// enum, allowed values, string), and each accepted value must print and parse back to
// itself.

#include "bounce/config/cvar_registry.h"
#include "fuzz_support.h"

#include <cmath>
#include <cstdlib>

namespace {

using namespace bounce;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view value = fuzz::text(data, size);
  CVarRegistry cvars;
  std::vector<CVar*> all{
      &cvars.add(CVarDesc<bool>{.name = "b", .defaultValue = false}).cvar(),
      &cvars.add(CVarDesc<int32_t>{.name = "i", .defaultValue = 8, .min = 1, .max = 4096}).cvar(),
      &cvars
           .add(CVarDesc<int32_t>{
               .name = "ic", .defaultValue = 8, .min = -5, .max = 16, .outOfRange = RangePolicy::Clamp})
           .cvar(),
      &cvars.add(CVarDesc<int32_t>{.name = "iu", .defaultValue = 0}).cvar(),
      &cvars.add(CVarDesc<float>{.name = "f", .defaultValue = 1.0f}).cvar(),
      &cvars
           .add(CVarDesc<float>{
               .name = "fc", .defaultValue = 1.0f, .min = 0.0, .max = 10.0, .outOfRange = RangePolicy::Clamp})
           .cvar(),
      &cvars.add(CVarDesc<int32_t>{.name = "e", .defaultValue = 0, .enumNames = {"A", "Bb", "C"}}).cvar(),
      &cvars.add(CVarDesc<int32_t>{.name = "a", .defaultValue = 1, .allowed = {1, 2, 4}}).cvar(),
      &cvars.add(CVarDesc<float>{.name = "af", .defaultValue = 0.5f, .allowed = {0.5f, 1.0f}}).cvar(),
      &cvars.add(CVarDesc<std::string>{.name = "s", .defaultValue = "x"}).cvar(),
  };
  for (CVar* cvar : all) {
    std::string error;
    const std::optional<CVarValue> parsed = cvar->parse(value, &error);
    const SetResult result = cvars.set(*cvar, value, SetBy::Console, "fuzz");
    if (!result.ok()) continue;
    // What a variable holds prints as text that parses back to the same value (the
    // user ini is written this way).
    const std::optional<CVarValue> again = cvar->parse(cvar->valueText(), &error);
    if (!again || *again != cvar->value()) {
      fprintf(stderr, "%s: '%s' does not parse back (%s)\n", cvar->name().c_str(), cvar->valueText().c_str(),
              error.c_str());
      std::abort();
    }
    if (cvar->type() == CVarType::Float && !std::isfinite(cvar->getFloat())) {
      fprintf(stderr, "%s holds a non-finite value after '%.*s'\n", cvar->name().c_str(), int(size),
              reinterpret_cast<const char*>(data));
      std::abort();
    }
    (void)parsed;
  }
  return 0;
}
