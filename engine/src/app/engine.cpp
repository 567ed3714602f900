#include "bounce/engine.h"

#include "bounce/core/log.h"
#include "bounce/core/names.h"
#include "bounce/gpu/device_memory.h"
#include "bounce/graph/channels.h"
#include "plugin/plugin_search_path.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <system_error>

namespace bounce {
namespace fs = std::filesystem;

fs::path executableDirectory() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : exe.parent_path();
}

std::vector<std::string> normalizeCommandLine(int argc, const char* const* argv) {
  std::vector<std::string> out;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    const bool unrealLong = i > 0 && a.size() > 2 && a[0] == '-' && a[1] != '-' &&
                            std::isalpha(uint8_t(a[1])) && std::isalpha(uint8_t(a[2]));
    if (!unrealLong) {
      out.push_back(std::move(a));
      continue;
    }
    // -set=r.X=V: the first '=' separates the option from its value.
    size_t eq = a.find('=');
    if (eq != std::string::npos) {
      out.push_back("-" + a.substr(0, eq));
      out.push_back(a.substr(eq + 1));
    } else {
      out.push_back("-" + a);
    }
  }
  return out;
}

namespace {

fs::path defaultUserIni() {
  if (const char* p = std::getenv("BOUNCE_USER_INI"); p && *p) return p;
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x)
    return fs::path(x) / "bounce" / "UserEngine.ini";
  if (const char* h = std::getenv("HOME"); h && *h)
    return fs::path(h) / ".config" / "bounce" / "UserEngine.ini";
  return {};
}

// The apps' defaults ("content/cornell_box.gltf", bounce-soak's "config/Soak.ini") are
// named relative to the root, and an installed app runs from anywhere: a relative path that
// is not there from the working directory is taken from the root when it is there.
fs::path fromWorkingDirectoryOrRoot(const fs::path& path, const fs::path& root) {
  std::error_code ec;
  if (path.is_absolute() || fs::exists(path, ec) || !fs::exists(root / path, ec)) return path;
  return root / path;
}

// [Plugins] SearchPaths=DIR:DIR: more folders to find plugins in (plugin_search_path.h).
constexpr std::string_view kSearchPathsKey = "SearchPaths";

std::optional<bool> parsePluginSwitch(std::string_view text) {
  std::string t = toLower(text);
  if (t == "true" || t == "1" || t == "on" || t == "yes") return true;
  if (t == "false" || t == "0" || t == "off" || t == "no") return false;
  return std::nullopt;
}

}  // namespace

fs::path Engine::locateRoot(const fs::path& hint) const {
  auto hasConfig = [](const fs::path& p) {
    std::error_code ec;
    return !p.empty() && fs::exists(p / "config" / "BaseEngine.ini", ec);
  };
  if (!hint.empty()) return hint;
  if (const char* env = std::getenv("BOUNCE_ROOT"); env && hasConfig(env)) return env;
  // An installed SDK (docs/architecture.md, "The SDK"), before the parents: a prefix
  // inside a source tree must not pick up that tree.
  if (const fs::path installed = executableDirectory().parent_path() / "share" / "bounce";
      hasConfig(installed))
    return installed;
  for (fs::path p = executableDirectory(); !p.empty(); p = p.parent_path()) {
    if (hasConfig(p)) return p;
    if (p == p.parent_path()) break;
  }
#ifdef BOUNCE_SOURCE_DIR
  if (hasConfig(BOUNCE_SOURCE_DIR)) return BOUNCE_SOURCE_DIR;
#endif
  return fs::current_path();
}

Engine::Engine(EngineOptions options) {
  root_ = locateRoot(options.root);
  keepGoing_ = options.keepGoing;
  for (std::string& ini : options.iniFiles) ini = fromWorkingDirectoryOrRoot(ini, root_).string();
  iniOptions_ = options.iniFiles;

  // 1. Configuration layers, lowest priority first.
  config_.addFile((root_ / "config" / "BaseEngine.ini").string(), SetBy::BaseIni, true);
  config_.addFile((root_ / "config" / "DefaultEngine.ini").string(), SetBy::DefaultIni, false);
  userIni_ = options.userIni ? *options.userIni : defaultUserIni();
  if (!userIni_.empty()) config_.addFile(userIni_.string(), SetBy::UserIni, false);
  for (const std::string& ini : options.iniFiles)
    if (!config_.addFile(ini, SetBy::UserIni, true)) requestFailed(fmt::format("cannot use -ini {}", ini));

  // 2. Plugins are discovered first so that r.GI.Technique can be validated.
  plugins_ = std::make_unique<PluginHost>(services_);
  PluginSearchPathSources search{.commandLine = options.pluginDirs};
  if (options.defaultPluginDirs) {
    if (const char* env = std::getenv("BOUNCE_PLUGIN_PATH")) search.environment = env;
    if (const ConfigStack::Value* v = config_.find("Plugins", kSearchPathsKey))
      for (size_t i = 0; i < v->array.size(); ++i) search.ini.push_back({v->array[i], v->arraySources[i]});
    const fs::path prefix = executableDirectory().parent_path();
    search.defaults = {prefix / "plugins", prefix / "lib" / "bounce" / "plugins"};
  }
  std::vector<fs::path> dirs;
  for (const PluginSearchFolder& folder : resolvePluginSearchPath(search)) dirs.push_back(folder.path);
  plugins_->discover(dirs);

  // 3. Engine variables, then ini values and the command line on top of them.
  registerEngineVariables();
  const std::vector<CVarRegistry::Refused> iniRefused = config_.applyTo(cvars_, {"Plugins"});
  for (const std::string& set : options.sets) {
    size_t eq = set.find('=');
    if (eq == std::string::npos || eq == 0) {
      commandLineErrors_.push_back(fmt::format("-set {}: expected NAME=VALUE", set));
      continue;
    }
    SetResult r = cvars_.set(set.substr(0, eq), set.substr(eq + 1), SetBy::CommandLine, "command line");
    if (r.status == SetResult::Status::Rejected) commandLineErrors_.push_back(r.message);
  }

  // 4. Which plugins load: descriptor default < [Plugins] < command line.
  PluginHost::Enablement enablement;
  if (const std::vector<std::string> keys = config_.keys("Plugins"); !keys.empty()) {
    for (const std::string& key : keys) {
      if (equalsIgnoreCase(key, kSearchPathsKey)) continue;  // where to look, not a plugin's name
      const ConfigStack::Value* v = config_.find("Plugins", key);
      if (auto on = parsePluginSwitch(v->text))
        enablement.config[toLower(key)] = *on;
      else
        log::warn("{}: [Plugins] {}: '{}' is not True or False", v->source, key, v->text);
    }
  }
  for (const std::string& name : options.enablePlugins) enablement.commandLine[toLower(name)] = true;
  for (const std::string& name : options.disablePlugins) enablement.commandLine[toLower(name)] = false;
  if (!options.technique.empty()) {
    SetResult r = cvars_.set(technique_.cvar(), options.technique, SetBy::CommandLine, "--gi");
    if (r.status == SetResult::Status::Rejected)
      commandLineErrors_.push_back(r.message);
    else if (!equalsIgnoreCase(options.technique, "none"))
      enablement.commandLine[toLower(options.technique)] = true;
  }
  plugins_->loadEnabled(enablement);
  reportRequestedPlugins(options);

  reportIniRefusals(iniRefused);
  reportUnclaimedSettings();
  for (const CVarRegistry::Refused& r : cvars_.refusedDeferred())
    if (r.value.by == SetBy::CommandLine) commandLineErrors_.push_back(r.message);
  reportIniRefusals(cvars_.refusedDeferred());
  cvars_.markStartupComplete();
}

void Engine::requestFailed(std::string message) {
  // With --keep-going the message has already been logged where it arose (the registry,
  // the plugin host); without it the application stops with status 2.
  if (!keepGoing_) commandLineErrors_.push_back(std::move(message));
}

bool Engine::fromIniOption(std::string_view source) const {
  // Sources read "FILE:LINE", FILE spelled as it was given to -ini.
  return std::any_of(iniOptions_.begin(), iniOptions_.end(), [&](const std::string& file) {
    return source.size() > file.size() && source.substr(0, file.size()) == file && source[file.size()] == ':';
  });
}

void Engine::reportIniRefusals(const std::vector<CVarRegistry::Refused>& refused) {
  // Values the user named on this command line (through -ini) fail as -set values do;
  // the user ini and the checked-in config stay logged errors (the defaults are used).
  for (const CVarRegistry::Refused& r : refused)
    if (r.value.by == SetBy::UserIni && fromIniOption(r.value.source))
      requestFailed(fmt::format("{}: {}", r.value.source, r.message));
}

void Engine::reportRequestedPlugins(const EngineOptions& options) {
  std::vector<std::string> requested = options.enablePlugins;
  // A --gi name r.GI.Technique refused (unknown, not a technique) is already an error.
  const bool gi = !options.technique.empty() && !equalsIgnoreCase(options.technique, "none") &&
                  equalsIgnoreCase(technique_.cvar().getString(), options.technique);
  if (gi) requested.push_back(options.technique);
  for (size_t i = 0; i < requested.size(); ++i) {
    const std::string& name = requested[i];
    const std::string option = gi && i + 1 == requested.size() ? "--gi" : "--enable-plugin";
    const PluginDescriptor* d = plugins_->descriptor(name);
    if (!d) {
      std::vector<std::string> names;
      for (const PluginDescriptor& p : plugins_->available()) names.push_back(p.name);
      commandLineErrors_.push_back(
          fmt::format("{} {}: no such plugin{}", option, printable(name), didYouMean(name, names)));
      continue;
    }
    if (plugins_->isLoaded(d->name)) continue;
    if (std::any_of(options.disablePlugins.begin(), options.disablePlugins.end(),
                    [&](const std::string& n) { return equalsIgnoreCase(n, name); }))
      continue;  // enabled and disabled on one command line: the disable wins, as before
    requestFailed(
        fmt::format("{} {}: the plugin failed to load: {}", option, d->name, plugins_->failure(d->name)));
  }
}

Engine::~Engine() {
  // Plugins go first: their passes and resources may refer to the scene and registries.
  plugins_->unloadAll();
}

void Engine::registerEngineVariables() {
  allowCheats_ = cvars_.add<bool>({.name = "con.AllowCheats",
                                   .defaultValue = true,
                                   .help = "Allows console and command-line writes to cheat variables.",
                                   .category = "Engine"});
  technique_ = cvars_.add<std::string>(
      {.name = "r.GI.Technique",
       .defaultValue = "none",
       .help = "Global-illumination technique: the name of a GlobalIllumination plugin, or none.",
       .category = "Engine",
       .validate = [this](const std::string& value) -> std::string {
         if (equalsIgnoreCase(value, "none")) return {};
         const PluginDescriptor* d = plugins_ ? plugins_->descriptor(value) : nullptr;
         std::vector<std::string> names{"none"};
         if (plugins_)
           for (const PluginDescriptor& p : plugins_->available())
             if (p.isGlobalIllumination()) names.push_back(p.name);
         if (!d) return fmt::format("no GI technique '{}' (available: {})", value, fmt::join(names, ", "));
         if (!d->isGlobalIllumination()) return fmt::format("plugin '{}' is not a GI technique", d->name);
         return {};
       }});
  renderer_ = std::make_unique<RendererSettings>(cvars_);
  // The engine's own outputs; plugins add theirs.
  aovs_.add({"radiance", std::string(channels::SceneColor), 3, "HDR radiance before tone mapping, W/(m²·sr)"},
            kEngineOwner, "engine");
  aovs_.add({"direct", std::string(channels::DirectLighting), 3,
             "emission + direct lighting from punctual lights, W/(m²·sr)"},
            kEngineOwner, "engine");
  aovs_.add({"indirect-irradiance", std::string(channels::IndirectDiffuse), 3,
             "indirect diffuse irradiance E at the visible surface before albedo, W/m² (0 without GI)"},
            kEngineOwner, "engine");
  aovs_.add({"indirect-specular", std::string(channels::IndirectSpecular), 3,
             "indirect specular: incident radiance from the reflected direction, pre-filtered by roughness, "
             "W/(m²·sr) (0 without GI or where a technique traces none)"},
            kEngineOwner, "engine");
  aovs_.add({"albedo", std::string(channels::GBufferBaseColor), 3, "linear base colour"}, kEngineOwner,
            "engine");
  aovs_.add({"normal", std::string(channels::GBufferNormalRoughness), 3, "world-space unit normal"},
            kEngineOwner, "engine");
  aovs_.add({"depth", std::string(channels::GBufferDepth), 1,
             "distance along the view axis in metres, 0 where nothing was hit"},
            kEngineOwner, "engine");
}

void Engine::reportUnclaimedSettings() {
  // Values for variables and keys nobody registered: typos, or settings of plugins that
  // are not loaded (those are expected and stay quiet).
  auto ownedByAbsentPlugin = [&](const CVarRegistry::Deferred& d) -> const PluginDescriptor* {
    for (const PluginDescriptor& p : plugins_->available()) {
      if (plugins_->isLoaded(p.name)) continue;
      if (!d.section.empty() && !p.configSection.empty() && equalsIgnoreCase(d.section, p.configSection))
        return &p;
      if (d.section.empty() && !p.consoleVariablePrefix.empty() &&
          startsWithIgnoreCase(d.key, p.consoleVariablePrefix))
        return &p;
    }
    return nullptr;
  };
  std::vector<std::string> knownSections{"SystemSettings", "Plugins"};
  for (const CVar* c : cvars_.list())
    if (!c->ini().empty()) knownSections.push_back(c->ini().section);
  // A file of thousands of unknown settings is one mistake, not thousands: the first
  // few are reported one by one, the rest in one line (a line each buried the terminal).
  constexpr size_t kReportedOneByOne = 20;
  size_t reported = 0, unreported = 0;
  std::string firstUnreported;
  bool unreportedFromCommandLine = false, unreportedFromIniOption = false;
  for (const CVarRegistry::Deferred& d : cvars_.deferred()) {
    if (const PluginDescriptor* p = ownedByAbsentPlugin(d)) {
      log::debug("{}: '{}' is for plugin {}, which is not loaded", d.source, d.key, p->name);
      continue;
    }
    if (reported == kReportedOneByOne) {
      if (unreported++ == 0) firstUnreported = d.source;
      unreportedFromCommandLine = unreportedFromCommandLine || d.by == SetBy::CommandLine;
      unreportedFromIniOption =
          unreportedFromIniOption || (d.by == SetBy::UserIni && fromIniOption(d.source));
      continue;
    }
    ++reported;
    std::string message;
    if (d.section.empty()) {
      message = fmt::format("unknown console variable '{}'{}", abbreviated(d.key),
                            didYouMean(d.key, cvars_.names()));
    } else if (cvars_.hasSection(d.section)) {
      message = fmt::format("unknown key '{}' in [{}]{}", abbreviated(d.key), abbreviated(d.section),
                            didYouMean(d.key, cvars_.keysInSection(d.section)));
    } else {
      message =
          fmt::format("unknown section [{}]{}", abbreviated(d.section), didYouMean(d.section, knownSections));
    }
    if (d.by == SetBy::CommandLine) {
      commandLineErrors_.push_back(message);
    } else if (d.by == SetBy::UserIni && fromIniOption(d.source)) {
      log::error("{}: {}", d.source, message);
      requestFailed(fmt::format("{}: {}", d.source, message));
    } else {
      log::warn("{}: {}", d.source, message);
    }
  }
  if (unreported > 0) {
    const std::string summary =
        fmt::format("{}: and {} more unknown settings, not listed one by one", firstUnreported, unreported);
    if (unreportedFromCommandLine) {
      commandLineErrors_.push_back(summary);
    } else if (unreportedFromIniOption) {
      log::error("{}", summary);
      requestFailed(summary);
    } else {
      log::warn("{}", summary);
    }
  }
}

bool Engine::saveSettings(std::string* error) {
  if (userIni_.empty()) {
    if (error) *error = "no user ini is in use";
    return false;
  }
  return ConfigStack::saveChangedSettings(cvars_, userIni_.string(), error);
}

SceneExtrasSchema Engine::extrasSchema() const {
  SceneExtrasSchema schema;
  schema.materialKeys = parameters_.names(ObjectKind::Material);
  schema.lightKeys = parameters_.names(ObjectKind::Light);
  for (const CVar* c : cvars_.list())
    if (!c->postProcessName().empty()) schema.postProcessSettings.push_back(c->postProcessName());
  for (const SceneVolumeKinds::Kind& k : volumeKinds_.all()) schema.volumeKinds.push_back(k.desc);
  return schema;
}

GltfLoadResult Engine::loadScene(const fs::path& path) {
  SceneExtrasSchema schema = extrasSchema();
  GltfLoadResult result = loadGltf(fromWorkingDirectoryOrRoot(path, root_).string(), &schema);
  if (result.scene) {
    scene_ = std::move(result.scene);
    events_.sceneLoaded.emit({*scene_, path.string()});
  }
  return result;
}

void Engine::setScene(std::unique_ptr<Scene> scene) {
  scene_ = std::move(scene);
  if (scene_) events_.sceneLoaded.emit({*scene_, std::string()});
}

std::string Engine::technique() const {
  const std::string& selected = technique_.cvar().getString();
  if (equalsIgnoreCase(selected, "none")) return "none";
  const PluginDescriptor* d = plugins_->descriptor(selected);
  if (d && plugins_->isLoaded(d->name)) return d->name;
  return "none";
}

std::vector<Engine::HookTiming> Engine::buildFrame(RenderGraph& graph, const FrameContext& frame,
                                                   const EngineStages& stages) {
  std::vector<HookTiming> timings;
  graph.setViewExtent(frame.view.width, frame.view.height);
  auto engineStage = [&](const std::function<void(RenderGraph&, const FrameContext&)>& stage) {
    graph.setOrigin(std::nullopt, "engine");
    if (stage) stage(graph, frame);
  };
  auto hooksAt = [&](ExtensionPoint point) {
    for (const PassHookRegistry::Hook* hook : hooks_.at(point, frame.technique)) {
      graph.setOrigin(point, hook->origin);
      const auto start = std::chrono::steady_clock::now();
      std::string error;
      bool outOfDeviceMemory = false;
      try {
        hook->desc.setup(graph, frame);
      } catch (const std::exception& e) {
        // The frame goes on without what the hook set up, and says it failed.
        error = fmt::format("pass hook '{}' ({}) failed: {}", hook->desc.name, hook->origin, e.what());
        outOfDeviceMemory = dynamic_cast<const gpu::OutOfDeviceMemory*>(&e) != nullptr;
        log::error("{}", error);
      }
      const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
      timings.push_back(
          {hook->desc.name, hook->origin, elapsed.count(), std::move(error), outOfDeviceMemory});
    }
  };
  engineStage(stages.sceneSetup);
  hooksAt(ExtensionPoint::FrameBegin);
  engineStage(stages.geometry);
  hooksAt(ExtensionPoint::AfterGBuffer);
  hooksAt(ExtensionPoint::IndirectDiffuse);
  hooksAt(ExtensionPoint::IndirectSpecular);
  hooksAt(ExtensionPoint::AmbientOcclusion);
  engineStage(stages.lighting);
  hooksAt(ExtensionPoint::BeforePostProcess);
  engineStage(stages.postProcess);
  hooksAt(ExtensionPoint::DebugView);
  engineStage(stages.output);
  return timings;
}

}  // namespace bounce
