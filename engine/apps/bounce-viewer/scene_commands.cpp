// `material` and `light`: the outliner's parameter checkboxes and fields as console
// commands. Both go through Scene::editMaterial / editLight, the path the outliner
// uses, so a technique that caches per-object work sees the same recorded change.

#include "scene_commands.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace bounce::viewer {

namespace {

ConsoleResult fail(std::string line) { return ConsoleResult{false, {std::move(line)}}; }

/// The object named `key` (case-insensitive) or with that index among `names`.
std::optional<uint32_t> findObject(const std::vector<std::string>& names, const std::string& key) {
  for (uint32_t i = 0; i < names.size(); ++i)
    if (!names[i].empty() && equalsIgnoreCase(names[i], key)) return i;
  uint32_t index = 0;
  auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), index);
  if (ec == std::errc() && end == key.data() + key.size() && index < names.size()) return index;
  return std::nullopt;
}

/// `text` as the declared parameter's type, within its declared range.
std::optional<ObjectParameterValue> parseParameter(const ObjectParameterRegistry::Entry& p,
                                                   const std::string& text, std::string* error) {
  const CVar& def = *p.defaultValue;
  const std::optional<CVarValue> parsed = def.parse(text, error);
  if (!parsed) return std::nullopt;
  ObjectParameterValue value;
  double number = 0.0;
  if (const bool* b = std::get_if<bool>(&*parsed)) {
    value = *b;
    number = *b ? 1.0 : 0.0;
  } else if (const int32_t* i = std::get_if<int32_t>(&*parsed)) {
    value = *i;
    number = *i;
  } else if (const float* f = std::get_if<float>(&*parsed)) {
    value = *f;
    number = *f;
  } else {
    *error = fmt::format("parameter '{}' is not a bool, int or float", p.name);
    return std::nullopt;
  }
  if ((def.min() && number < *def.min()) || (def.max() && number > *def.max())) {
    *error = fmt::format("{} is outside {}'s range [{}, {}]", text, p.name,
                         def.min() ? *def.min() : -INFINITY, def.max() ? *def.max() : INFINITY);
    return std::nullopt;
  }
  return value;
}

std::string valueText(const ObjectParameterValue& v) {
  return std::visit(
      [](auto x) -> std::string {
        if constexpr (std::is_same_v<decltype(x), bool>)
          return x ? "true" : "false";
        else
          return fmt::format("{}", x);
      },
      v);
}

/// One command for one kind of object; `names` and `values` read the scene at each call,
/// `edit` applies a parameter through the scene's tracked edit.
template <class Object>
ConsoleCommandDesc objectCommand(Engine& engine, ObjectKind kind,
                                 const std::vector<Object>& (Scene::*objects)() const,
                                 void (Scene::*edit)(uint32_t, const std::function<void(Object&)>&)) {
  const std::string word = toLower(objectKindName(kind));
  return ConsoleCommandDesc{
      .name = word,
      .help = fmt::format(
          "{0} list | {0} NAME|INDEX PARAMETER VALUE: shows or sets the plugin-declared parameters of a {0}, "
          "as the Scene panel's checkboxes do.",
          word),
      .run = [&engine, kind, objects, edit, word](const std::vector<std::string>& args) -> ConsoleResult {
        Scene* scene = engine.scene();
        if (!scene) return fail("no scene is loaded");
        const std::vector<Object>& all = (scene->*objects)();
        std::vector<std::string> names;
        for (const Object& o : all) names.push_back(o.name);
        const ObjectParameterRegistry& registry = engine.parameters();
        if (args.size() == 1 && equalsIgnoreCase(args[0], "list")) {
          ConsoleResult r;
          for (uint32_t i = 0; i < all.size(); ++i) {
            std::string line = fmt::format("{} {}:", i, names[i].empty() ? "(unnamed)" : names[i]);
            for (const ObjectParameterRegistry::Entry* p : registry.list(kind)) {
              const ObjectParameterValue* set = all[i].parameters.find(p->name);
              line += fmt::format(" {}={}{}", p->name, set ? valueText(*set) : p->defaultValue->valueText(),
                                  set ? "" : " (default)");
            }
            r.lines.push_back(std::move(line));
          }
          return r;
        }
        if (args.size() != 3)
          return fail(fmt::format("usage: {0} list | {0} NAME|INDEX PARAMETER VALUE", word));
        const std::optional<uint32_t> index = findObject(names, args[0]);
        if (!index)
          return fail(fmt::format("no {} named or numbered '{}' (try '{} list')", word, args[0], word));
        const ObjectParameterRegistry::Entry* p = registry.find(kind, args[1]);
        if (!p)
          return fail(fmt::format("no {} parameter '{}'; declared: {}", word, args[1],
                                  fmt::join(registry.names(kind), ", ")));
        std::string error;
        const std::optional<ObjectParameterValue> value = parseParameter(*p, args[2], &error);
        if (!value) return fail(fmt::format("{} {}: {}", word, p->name, error));
        (scene->*edit)(*index, [&](Object& o) { o.parameters.set(p->name, *value); });
        return ConsoleResult{true,
                             {fmt::format("{} {}: {} = {}", word, args[0], p->name, valueText(*value))}};
      }};
}

}  // namespace

void registerSceneCommands(Engine& engine) {
  engine.console().addCommand(
      objectCommand<Material>(engine, ObjectKind::Material, &Scene::materials, &Scene::editMaterial));
  engine.console().addCommand(
      objectCommand<Light>(engine, ObjectKind::Light, &Scene::lights, &Scene::editLight));
}

}  // namespace bounce::viewer
