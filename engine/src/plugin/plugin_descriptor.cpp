#include "bounce/plugin/plugin_descriptor.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace bounce {

std::filesystem::path PluginDescriptor::libraryPath() const {
  return file.parent_path() / ("lib" + library + ".so");
}

std::optional<PluginDescriptor> PluginDescriptor::load(const std::filesystem::path& file,
                                                       std::string* error) {
  std::ifstream in(file);
  if (!in) {
    if (error) *error = fmt::format("{}: cannot read plugin descriptor", file.string());
    return std::nullopt;
  }
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str(), file, error);
}

std::optional<PluginDescriptor> PluginDescriptor::parse(const std::string& json,
                                                        const std::filesystem::path& file,
                                                        std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<PluginDescriptor> {
    if (error) *error = fmt::format("{}: invalid plugin descriptor: {}", file.string(), why);
    return std::nullopt;
  };
  nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
  if (j.is_discarded()) return fail("not valid JSON");
  if (!j.is_object()) return fail("expected a JSON object");

  PluginDescriptor d;
  d.file = file;
  auto string = [&](const char* key, std::string& out, bool required) -> bool {
    auto it = j.find(key);
    if (it == j.end()) return !required;
    if (!it->is_string()) return false;
    out = it->get<std::string>();
    return !required || !out.empty();
  };
  auto number = [&](const char* key, uint32_t& out, bool required) -> bool {
    auto it = j.find(key);
    if (it == j.end()) return !required;
    if (!it->is_number_unsigned()) return false;
    out = it->get<uint32_t>();
    return true;
  };
  if (!string("Name", d.name, true)) return fail("\"Name\" must be a non-empty string");
  if (!string("Library", d.library, true)) return fail("\"Library\" must be a non-empty string");
  if (!number("EngineApiVersion", d.engineApiVersion, true))
    return fail("\"EngineApiVersion\" must be a non-negative integer");
  if (!string("FriendlyName", d.friendlyName, false)) return fail("\"FriendlyName\" must be a string");
  if (!number("Version", d.version, false)) return fail("\"Version\" must be a non-negative integer");
  if (!string("VersionName", d.versionName, false)) return fail("\"VersionName\" must be a string");
  if (!string("Description", d.description, false)) return fail("\"Description\" must be a string");
  if (!string("Category", d.category, false)) return fail("\"Category\" must be a string");
  if (!string("ConfigSection", d.configSection, false)) return fail("\"ConfigSection\" must be a string");
  if (!string("ConsoleVariablePrefix", d.consoleVariablePrefix, false))
    return fail("\"ConsoleVariablePrefix\" must be a string");
  if (auto it = j.find("EnabledByDefault"); it != j.end()) {
    if (!it->is_boolean()) return fail("\"EnabledByDefault\" must be true or false");
    d.enabledByDefault = it->get<bool>();
  }
  if (auto it = j.find("Dependencies"); it != j.end()) {
    if (!it->is_array()) return fail("\"Dependencies\" must be an array of plugin names");
    for (const auto& dep : *it) {
      if (!dep.is_string()) return fail("\"Dependencies\" must be an array of plugin names");
      d.dependencies.push_back(dep.get<std::string>());
    }
  }
  if (d.friendlyName.empty()) d.friendlyName = d.name;
  return d;
}

}  // namespace bounce
