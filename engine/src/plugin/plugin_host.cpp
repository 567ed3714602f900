#include "bounce/plugin/plugin_host.h"

#include "core/file_kind.h"

#include "bounce/core/log.h"
#include "bounce/core/names.h"
#include "plugin/shared_library.h"

#include <fmt/format.h>

#include <algorithm>
#include <system_error>

namespace bounce {

// Member order matters: the plugin object's code lives in the library, so the object
// must be destroyed before the library is closed (members die in reverse order).
struct PluginHost::Loaded {
  PluginDescriptor descriptor;
  OwnerId owner;
  std::unique_ptr<SharedLibrary> library;
  std::unique_ptr<Plugin> plugin;
};

void EngineServices::removeOwnedBy(OwnerId owner) {
  hooks.removeOwnedBy(owner);
  debugViews.removeOwnedBy(owner);
  aovs.removeOwnedBy(owner);
  knobs.removeOwnedBy(owner);
  volumeKinds.removeOwnedBy(owner);
  sceneData.removeOwnedBy(owner);
  events.removeOwnedBy(owner);
  console.removeOwnedBy(owner);
  parameters.removeOwnedBy(owner);  // before the variables holding its defaults
  cvars.removeOwnedBy(owner);
}

PluginHost::PluginHost(EngineServices& services) : services_(services) {}

PluginHost::~PluginHost() { unloadAll(); }

void PluginHost::discover(const std::vector<std::filesystem::path>& roots) {
  namespace fs = std::filesystem;
  auto consider = [&](const fs::path& found) {
    if (found.extension() != ".bplugin") return;
    // Before opening it: a FIFO named X.bplugin blocked start-up forever.
    if (const std::optional<std::string> kind = notARegularFile(found)) {
      log::warn("{}: is {}, not a regular file; not a plugin descriptor, skipped", found.string(), *kind);
      return;
    }
    // Absolute: plugins name their shaders and content relative to their folder
    // (PluginContext::shaderPath), and a relative folder would mean the working directory.
    std::error_code absoluteError;
    const fs::path file = fs::absolute(found, absoluteError).lexically_normal();
    std::string error;
    std::optional<PluginDescriptor> d = PluginDescriptor::load(file, &error);
    if (!d) {
      log::error("{}", error);
      return;
    }
    if (equalsIgnoreCase(d->name, "none")) {
      // `--gi none` / r.GI.Technique none means no technique: a plugin may not take it over.
      log::error("{}: plugin name '{}' is reserved (--gi none means no GI technique); not loaded",
                 file.string(), d->name);
      return;
    }
    if (const PluginDescriptor* existing = descriptor(d->name)) {
      // Documented precedence: the first folder on the search path wins, so a plugin built
      // in development (--plugin-dir) replaces an installed one of the same name.
      log::warn(
          "{}: plugin '{}' is already provided by {}, earlier on the plugin search path; ignoring this one",
          file.string(), d->name, existing->file.string());
      return;
    }
    available_.push_back(std::move(*d));
  };
  for (const fs::path& root : roots) {
    std::error_code ec;
    if (!fs::is_directory(root, ec)) continue;
    std::vector<fs::path> entries;
    for (const auto& entry : fs::directory_iterator(root, ec)) entries.push_back(entry.path());
    std::sort(entries.begin(), entries.end());  // deterministic order
    for (const fs::path& p : entries) {
      if (fs::is_directory(p, ec)) {
        std::vector<fs::path> files;
        for (const auto& f : fs::directory_iterator(p, ec)) files.push_back(f.path());
        std::sort(files.begin(), files.end());
        for (const fs::path& f : files) consider(f);
      } else {
        consider(p);
      }
    }
  }
}

const PluginDescriptor* PluginHost::descriptor(std::string_view name) const {
  for (const PluginDescriptor& d : available_)
    if (equalsIgnoreCase(d.name, name)) return &d;
  return nullptr;
}

bool PluginHost::enabled(const PluginDescriptor& d, const Enablement& e) const {
  std::string key = toLower(d.name);
  if (auto it = e.commandLine.find(key); it != e.commandLine.end()) return it->second;
  if (auto it = e.config.find(key); it != e.config.end()) return it->second;
  return d.enabledByDefault;
}

size_t PluginHost::loadEnabled(const Enablement& e) {
  std::vector<std::string> known;
  for (const PluginDescriptor& d : available_) known.push_back(d.name);
  for (const auto* source : {&e.config, &e.commandLine})
    for (const auto& [name, on] : *source)
      if (!descriptor(name))
        log::warn("unknown plugin '{}' {}{}", name, on ? "enabled" : "disabled", didYouMean(name, known));

  const size_t before = loaded_.size();
  for (const PluginDescriptor& d : available_) {
    if (!enabled(d, e) || isLoaded(d.name)) continue;
    // Dependencies must be enabled too: loading one the user disabled would be a surprise.
    bool ok = true;
    for (const std::string& dep : d.dependencies) {
      const PluginDescriptor* depDesc = descriptor(dep);
      if (depDesc && !enabled(*depDesc, e)) {
        std::string reason = fmt::format("plugin '{}' needs '{}', which is disabled", d.name, dep);
        log::error("{}", reason);
        failures_[toLower(d.name)] = reason;
        ok = false;
      }
    }
    if (!ok) continue;
    std::vector<std::string> stack;
    loadResolved(d, stack);  // failures are logged and remembered; the rest go on
  }
  return loaded_.size() - before;
}

bool PluginHost::load(std::string_view name) {
  const PluginDescriptor* d = descriptor(name);
  if (!d) {
    std::vector<std::string> known;
    for (const PluginDescriptor& p : available_) known.push_back(p.name);
    log::error("unknown plugin '{}'{}", name, didYouMean(name, known));
    return false;
  }
  std::vector<std::string> stack;
  return loadResolved(*d, stack);
}

bool PluginHost::loadResolved(const PluginDescriptor& d, std::vector<std::string>& stack) {
  if (isLoaded(d.name)) return true;
  auto fail = [&](std::string reason) {
    log::error("{}", reason);
    failures_[toLower(d.name)] = std::move(reason);
    return false;
  };
  if (std::find(stack.begin(), stack.end(), d.name) != stack.end())
    return fail(fmt::format("plugin '{}' has a dependency cycle: {} -> {}", d.name, fmt::join(stack, " -> "),
                            d.name));
  stack.push_back(d.name);
  for (const std::string& dep : d.dependencies) {
    const PluginDescriptor* depDesc = descriptor(dep);
    if (!depDesc) return fail(fmt::format("plugin '{}' needs '{}', which is not installed", d.name, dep));
    if (!loadResolved(*depDesc, stack))
      return fail(fmt::format("plugin '{}' needs '{}', which failed to load", d.name, dep));
  }
  stack.pop_back();

  if (d.engineApiVersion != kPluginApiVersion)
    return fail(fmt::format("plugin '{}' ({}) targets plugin API {}, this engine provides {}", d.name,
                            d.file.string(), d.engineApiVersion, kPluginApiVersion));
  std::filesystem::path libPath = d.libraryPath();
  std::error_code ec;
  if (!std::filesystem::exists(libPath, ec))
    return fail(
        fmt::format("plugin '{}': library {} not found (is the plugin built?)", d.name, libPath.string()));
  std::string error;
  auto library = SharedLibrary::open(libPath, &error);
  if (!library) return fail(fmt::format("plugin '{}': cannot load {}: {}", d.name, libPath.string(), error));
  auto entryFn = reinterpret_cast<PluginEntryFunction>(library->symbol(kPluginEntrySymbol));
  if (!entryFn)
    return fail(fmt::format("plugin '{}': {} does not export {}() (missing BOUNCE_IMPLEMENT_PLUGIN?)", d.name,
                            libPath.string(), kPluginEntrySymbol));
  const PluginEntry* entry = entryFn();
  if (!entry) return fail(fmt::format("plugin '{}': {}() returned nothing", d.name, kPluginEntrySymbol));
  if (entry->apiVersion != kPluginApiVersion)
    return fail(
        fmt::format("plugin '{}' was built against plugin API {}, this engine provides {}; rebuild it",
                    d.name, entry->apiVersion, kPluginApiVersion));

  auto loaded = std::make_unique<Loaded>();
  loaded->descriptor = d;
  loaded->owner = nextOwner_++;
  loaded->library = std::move(library);
  try {
    loaded->plugin = entry->create();
    if (!loaded->plugin) throw PluginError("its factory returned no plugin");
    PluginContext context(services_, loaded->descriptor, loaded->owner);
    loaded->plugin->startup(context);
  } catch (const std::exception& ex) {
    // Roll back whatever it registered before failing, then drop it.
    services_.removeOwnedBy(loaded->owner);
    return fail(fmt::format("plugin '{}' failed to start: {}", d.name, ex.what()));
  }
  failures_.erase(toLower(d.name));
  log::info("loaded plugin {} {} ({})", d.name,
            d.versionName.empty() ? std::to_string(d.version) : d.versionName, d.friendlyName);
  loaded_.push_back(std::move(loaded));
  return true;
}

bool PluginHost::unload(std::string_view name) {
  auto it = std::find_if(loaded_.begin(), loaded_.end(),
                         [&](const auto& l) { return equalsIgnoreCase(l->descriptor.name, name); });
  if (it == loaded_.end()) return false;
  // Plugins that depend on this one go first.
  for (const auto& other : std::vector<std::string>(loaded())) {
    const PluginDescriptor* d = descriptor(other);
    if (d && std::any_of(d->dependencies.begin(), d->dependencies.end(),
                         [&](const std::string& dep) { return equalsIgnoreCase(dep, name); }))
      unload(other);
  }
  it = std::find_if(loaded_.begin(), loaded_.end(),
                    [&](const auto& l) { return equalsIgnoreCase(l->descriptor.name, name); });
  Loaded& l = **it;
  try {
    l.plugin->shutdown();
  } catch (const std::exception& ex) {
    log::error("plugin '{}' failed to shut down cleanly: {}", l.descriptor.name, ex.what());
  }
  services_.removeOwnedBy(l.owner);
  loaded_.erase(it);
  return true;
}

void PluginHost::unloadAll() {
  while (!loaded_.empty()) unload(std::string(loaded_.back()->descriptor.name));
}

bool PluginHost::isLoaded(std::string_view name) const {
  return std::any_of(loaded_.begin(), loaded_.end(),
                     [&](const auto& l) { return equalsIgnoreCase(l->descriptor.name, name); });
}

std::vector<std::string> PluginHost::loaded() const {
  std::vector<std::string> out;
  for (const auto& l : loaded_) out.push_back(l->descriptor.name);
  return out;
}

std::string PluginHost::failure(std::string_view name) const {
  auto it = failures_.find(toLower(name));
  return it == failures_.end() ? std::string() : it->second;
}

}  // namespace bounce
