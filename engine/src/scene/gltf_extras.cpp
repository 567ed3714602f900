#include "gltf_extras.h"

#include "gltf_values.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace bounce::gltf {
namespace {

// Note: tinygltf drops `null` members and empty objects or arrays while parsing, so
// those never reach here and cannot be reported.

/// " (did you mean 'X'?)" for an unknown key. names.h skips candidates that differ only
/// in case (console names are case-insensitive), but extras keys compare exactly, so a
/// case slip is suggested here.
std::string suggestion(std::string_view key, std::span<const std::string> known) {
  for (const std::string& k : known) {
    if (equalsIgnoreCase(k, key)) return fmt::format(" (did you mean '{}'?)", k);
  }
  return didYouMean(key, known);
}

}  // namespace

ObjectParameterValues parametersFromExtras(const LoadContext& ctx, const tinygltf::Value& extras,
                                           ObjectKind kind, std::string_view element) {
  ObjectParameterValues values;
  if (!extras.IsObject()) return values;  // extras may hold anything; only objects carry parameters
  const std::vector<std::string>* known = nullptr;
  if (ctx.schema) known = kind == ObjectKind::Material ? &ctx.schema->materialKeys : &ctx.schema->lightKeys;

  for (const std::string& key : extras.Keys()) {
    const tinygltf::Value& v = extras.Get(key);
    if (known && std::find(known->begin(), known->end(), key) == known->end()) {
      auto& entry = ctx.unknownKeys[fmt::format("{}\n{}", objectKindName(kind), key)];
      entry.message = fmt::format("unknown extras key '{}'{}; no loaded plugin declares this {} parameter",
                                  key, suggestion(key, *known), toLower(objectKindName(kind)));
      entry.elements.push_back(std::string(element));
    }
    if (v.IsBool()) {
      values.set(key, v.Get<bool>());
    } else if (v.IsInt()) {
      values.set(key, int32_t(v.GetNumberAsInt()));
    } else if (v.IsNumber()) {
      values.set(key, float(v.GetNumberAsDouble()));
    } else {
      ctx.warn(element, fmt::format("extras key '{}' is a JSON {}; parameters are bool or number, ignored",
                                    key, valueTypeName(v)));
    }
  }
  return values;
}

std::optional<PostProcessVolume> postProcessVolumeFromExtras(const LoadContext& ctx,
                                                             const tinygltf::Node& node,
                                                             std::string_view element,
                                                             const glm::mat4& world) {
  if (!node.extras.IsObject() || !node.extras.Has("PostProcessVolume")) return std::nullopt;
  const tinygltf::Value& desc = node.extras.Get("PostProcessVolume");
  const std::string where = fmt::format("{} PostProcessVolume", element);
  if (!desc.IsObject()) {
    ctx.warn(where, fmt::format("is a JSON {}, not an object; ignored", valueTypeName(desc)));
    return std::nullopt;
  }

  PostProcessVolume volume;
  volume.name = node.name;
  volume.world = world;
  static const std::vector<std::string> kFields = {"Priority", "BlendRadius", "BlendWeight",
                                                   "Unbound",  "Enabled",     "Settings"};
  auto boolField = [&](const char* key, bool fallback) {
    if (!desc.Has(key)) return fallback;
    const tinygltf::Value& v = desc.Get(key);
    if (v.IsBool()) return v.Get<bool>();
    ctx.warn(where, fmt::format("'{}' is a JSON {}, not a bool; using {}", key, valueTypeName(v), fallback));
    return fallback;
  };
  volume.priority = float(numberMember(ctx, desc, "Priority", volume.priority, where));
  volume.blendRadius = float(numberMember(ctx, desc, "BlendRadius", volume.blendRadius, where));
  volume.blendWeight = float(numberMember(ctx, desc, "BlendWeight", volume.blendWeight, where));
  if (volume.blendRadius < 0.0f) {
    ctx.warn(where, fmt::format("BlendRadius {} is negative; using 0", volume.blendRadius));
    volume.blendRadius = 0.0f;
  }
  if (volume.blendWeight < 0.0f || volume.blendWeight > 1.0f) {
    ctx.warn(where, fmt::format("BlendWeight {} is outside 0..1; clamped", volume.blendWeight));
    volume.blendWeight = std::clamp(volume.blendWeight, 0.0f, 1.0f);
  }
  volume.unbound = boolField("Unbound", volume.unbound);
  volume.enabled = boolField("Enabled", volume.enabled);
  for (const std::string& key : desc.Keys()) {
    if (std::find(kFields.begin(), kFields.end(), key) == kFields.end()) {
      ctx.warn(where, fmt::format("unknown field '{}'{}; ignored", key, suggestion(key, kFields)));
    }
  }

  if (!desc.Has("Settings")) return volume;
  const tinygltf::Value& settings = desc.Get("Settings");
  if (!settings.IsObject()) {
    ctx.warn(where, fmt::format("'Settings' is a JSON {}, not an object; ignored", valueTypeName(settings)));
    return volume;
  }
  for (const std::string& name : settings.Keys()) {
    // Settings name console variables by their post-process name, and console
    // variables are case-insensitive, so a case difference is not a typo here.
    if (ctx.schema) {
      const auto& known = ctx.schema->postProcessSettings;
      if (std::none_of(known.begin(), known.end(),
                       [&](const std::string& k) { return equalsIgnoreCase(k, name); })) {
        ctx.warn(where, fmt::format("unknown setting '{}'{}; no loaded plugin declares it", name,
                                    didYouMean(name, known)));
      }
    }
    const tinygltf::Value& v = settings.Get(name);
    if (v.IsBool()) {
      volume.settings[name] = v.Get<bool>();
    } else if (v.IsNumber()) {
      volume.settings[name] = v.GetNumberAsDouble();
    } else if (v.IsString()) {
      volume.settings[name] = v.Get<std::string>();
    } else {
      ctx.warn(where, fmt::format("setting '{}' is a JSON {}; settings are bool, number or string, ignored",
                                  name, valueTypeName(v)));
    }
  }
  return volume;
}

std::vector<SceneVolume> sceneVolumesFromExtras(const LoadContext& ctx, const tinygltf::Node& node,
                                                std::string_view element, const glm::mat4& world) {
  std::vector<SceneVolume> out;
  if (!ctx.schema || !node.extras.IsObject()) return out;
  for (const SceneVolumeKindDesc& kind : ctx.schema->volumeKinds) {
    if (!node.extras.Has(kind.name)) continue;
    const tinygltf::Value& desc = node.extras.Get(kind.name);
    const std::string where = fmt::format("{} {}", element, kind.name);
    if (!desc.IsObject()) {
      ctx.warn(where, fmt::format("is a JSON {}, not an object; ignored", valueTypeName(desc)));
      continue;
    }
    SceneVolume volume;
    volume.kind = kind.name;
    volume.name = node.name;
    volume.world = world;
    for (const std::string& key : desc.Keys()) {
      if (!kind.fields.empty() &&
          std::find(kind.fields.begin(), kind.fields.end(), key) == kind.fields.end()) {
        ctx.warn(where, fmt::format("unknown field '{}'{}; ignored", key, suggestion(key, kind.fields)));
        continue;
      }
      const tinygltf::Value& v = desc.Get(key);
      if (v.IsBool()) {
        volume.settings[key] = v.Get<bool>();
      } else if (v.IsNumber()) {
        const double d = v.GetNumberAsDouble();
        if (!std::isfinite(d)) {
          ctx.warn(where, fmt::format("'{}' is not finite; ignored", key));
          continue;
        }
        volume.settings[key] = d;
      } else if (v.IsString()) {
        volume.settings[key] = v.Get<std::string>();
      } else if (v.IsArray()) {
        std::vector<double> numbers;
        bool ok = true;
        for (size_t i = 0; i < v.ArrayLen(); ++i) {
          const tinygltf::Value& e = v.Get(int(i));
          if (!e.IsNumber() || !std::isfinite(e.GetNumberAsDouble())) {
            ok = false;
            break;
          }
          numbers.push_back(e.GetNumberAsDouble());
        }
        if (!ok) {
          ctx.warn(where,
                   fmt::format("'{}' is an array of something other than finite numbers; ignored", key));
          continue;
        }
        volume.settings[key] = std::move(numbers);
      } else {
        ctx.warn(where,
                 fmt::format("'{}' is a JSON {}; fields are bool, number, string or an array of numbers, "
                             "ignored",
                             key, valueTypeName(v)));
      }
    }
    out.push_back(std::move(volume));
  }
  return out;
}

}  // namespace bounce::gltf
