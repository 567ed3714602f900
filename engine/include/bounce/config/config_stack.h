#pragma once
// The layered configuration: BaseEngine.ini < DefaultEngine.ini < the user's ini <
// extra `-ini` files, merged key by key, applied to console variables at each layer's
// priority, and written back to the user ini.

#include "bounce/config/cvar_registry.h"
#include "bounce/config/ini_document.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace bounce {

class ConfigStack {
 public:
  /// Loads one layer. A missing optional file is skipped silently; a missing required
  /// file or a syntax error is reported (file:line) and the other layers still load.
  /// Returns false if the file could not be read or had errors.
  bool addFile(const std::string& path, SetBy level, bool required);
  /// Loads a layer from text (tests, generated configs).
  bool addText(std::string_view text, const std::string& name, SetBy level);

  /// Every diagnostic from every layer, in load order.
  const std::vector<IniDiagnostic>& diagnostics() const { return diagnostics_; }

  struct Value {
    std::string text;                       ///< scalar value (the last assignment)
    std::vector<std::string> array;         ///< the array after every +/-/./! across layers
    std::vector<std::string> arraySources;  ///< "file:line" of each element of `array`
    SetBy level = SetBy::BaseIni;           ///< layer of the last write
    std::string source;                     ///< "file:line" of the last write
    bool assigned = false;                  ///< a plain `Key=Value` set `text` (array-only keys have none)
    uint64_t sequence = 0;  ///< load order of the last write (same-priority writes apply in order)
  };
  const Value* find(std::string_view section, std::string_view key) const;
  std::optional<std::string> get(std::string_view section, std::string_view key) const;
  std::vector<std::string> array(std::string_view section, std::string_view key) const;
  std::vector<std::string> sections() const;
  /// Keys of a section in first-seen order.
  std::vector<std::string> keys(std::string_view section) const;

  /// Writes [SystemSettings] entries and every plugin-section key to `cvars` at the
  /// priority of the layer that set them. Keys nobody registered yet are held by the
  /// registry. Sections in `reserved` (e.g. "Plugins") are the engine's own and skipped.
  /// Returns the writes the registry refused (bad values, read-only...), which it has
  /// also logged; held values refused later are in CVarRegistry::refusedDeferred().
  std::vector<CVarRegistry::Refused> applyTo(CVarRegistry& cvars,
                                             const std::vector<std::string>& reserved) const;

  /// Saves every variable changed at console priority this session into the ini file
  /// at `path` (created if missing): variables with an ini binding under their section
  /// and key, others under [SystemSettings]. Comments and untouched lines survive.
  static bool saveChangedSettings(const CVarRegistry& cvars, const std::string& path, std::string* error);

 private:
  void merge(const IniDocument& doc, SetBy level);

  struct Section {
    std::string name;
    std::vector<std::string> keyOrder;
    std::map<std::string, Value> values;  // lower-case key
  };
  std::vector<Section> sections_;  // in first-seen order
  // Lower-case name → index in sections_: a file with many sections loads in linear time.
  std::unordered_map<std::string, size_t> sectionIndex_;
  std::vector<IniDiagnostic> diagnostics_;
  uint64_t writes_ = 0;  // entries merged so far; numbers Value::sequence
  Section* section(std::string_view name, bool create);
  const Section* section(std::string_view name) const;
};

}  // namespace bounce
