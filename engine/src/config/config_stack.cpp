#include "bounce/config/config_stack.h"

#include "bounce/core/log.h"
#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace bounce {
namespace {

constexpr std::string_view kSystemSettings = "SystemSettings";

/// Logs the diagnostics added since `first`, so a bad line reaches the terminal and the
/// viewer console even when nobody inspects diagnostics().
void logFrom(const std::vector<IniDiagnostic>& diagnostics, size_t first) {
  for (size_t i = first; i < diagnostics.size(); ++i)
    log::error("{}: {}", diagnostics[i].where(), diagnostics[i].message);
}

bool contains(const std::vector<std::string>& names, std::string_view name) {
  return std::any_of(names.begin(), names.end(),
                     [&](const std::string& n) { return equalsIgnoreCase(n, name); });
}

struct IniKey {
  std::string section, key;
};

/// Where a console change to `cvar` is written. If the file already sets the variable
/// (under [SystemSettings] by name or alias, or under its binding) those lines are
/// updated: writing elsewhere would leave a stale line that could win at the next start.
/// Otherwise its binding, or [SystemSettings] by name.
std::vector<IniKey> linesFor(const CVar& cvar, const IniDocument& doc) {
  std::vector<IniKey> found;
  for (const IniEntry& e : doc.entries()) {
    if (e.op != IniEntry::Op::Set) continue;
    const bool byName = equalsIgnoreCase(e.section, kSystemSettings) &&
                        (equalsIgnoreCase(e.key, cvar.name()) || contains(cvar.aliases(), e.key));
    const bool byBinding = !cvar.ini().empty() && equalsIgnoreCase(e.section, cvar.ini().section) &&
                           equalsIgnoreCase(e.key, cvar.ini().key);
    const bool seen = std::any_of(found.begin(), found.end(), [&](const IniKey& k) {
      return equalsIgnoreCase(k.section, e.section) && equalsIgnoreCase(k.key, e.key);
    });
    if ((byName || byBinding) && !seen) found.push_back({e.section, e.key});
  }
  if (found.empty()) {
    if (cvar.ini().empty()) return {{std::string(kSystemSettings), cvar.name()}};
    return {{cvar.ini().section, cvar.ini().key}};
  }
  return found;
}

}  // namespace

bool ConfigStack::addFile(const std::string& path, SetBy level, bool required) {
  std::error_code ec;
  // A user ini that was never written is normal, not worth a message.
  if (!required && !std::filesystem::exists(path, ec)) return false;
  const size_t first = diagnostics_.size();
  std::optional<IniDocument> doc = IniDocument::load(path, diagnostics_);
  if (doc) merge(*doc, level);
  logFrom(diagnostics_, first);
  return doc.has_value() && diagnostics_.size() == first;
}

bool ConfigStack::addText(std::string_view text, const std::string& name, SetBy level) {
  const size_t first = diagnostics_.size();
  merge(IniDocument::parse(text, name, diagnostics_), level);
  logFrom(diagnostics_, first);
  return diagnostics_.size() == first;
}

void ConfigStack::merge(const IniDocument& doc, SetBy level) {
  for (const IniEntry& entry : doc.entries()) {
    Section* s = section(entry.section, true);
    auto [it, inserted] = s->values.try_emplace(toLower(entry.key));
    if (inserted) s->keyOrder.push_back(entry.key);
    Value& v = it->second;
    // Layers normally arrive lowest first, but a plugin's defaults may be read after
    // the user's ini: a lower layer never overrides what a higher one wrote.
    if (!inserted && level < v.level) continue;
    std::vector<std::string>& items = v.array;
    std::vector<std::string>& sources = v.arraySources;
    const std::string source = fmt::format("{}:{}", doc.path(), entry.line);
    switch (entry.op) {
      case IniEntry::Op::Set:
        // As in Unreal, a plain assignment replaces the whole array too.
        v.text = entry.value;
        v.assigned = true;
        items.assign(1, entry.value);
        sources.assign(1, source);
        break;
      case IniEntry::Op::Append:
        if (std::find(items.begin(), items.end(), entry.value) == items.end()) {
          items.push_back(entry.value);
          sources.push_back(source);
        }
        break;
      case IniEntry::Op::AppendDuplicate:
        items.push_back(entry.value);
        sources.push_back(source);
        break;
      case IniEntry::Op::Remove:
        for (size_t i = items.size(); i-- > 0;)
          if (items[i] == entry.value) {
            items.erase(items.begin() + std::ptrdiff_t(i));
            sources.erase(sources.begin() + std::ptrdiff_t(i));
          }
        break;
      case IniEntry::Op::Clear:
        // `!Key=` removes the key: a higher layer can take back a lower layer's value.
        items.clear();
        sources.clear();
        v.text.clear();
        v.assigned = false;
        break;
    }
    v.level = level;
    v.source = source;
    v.sequence = ++writes_;
  }
}

ConfigStack::Section* ConfigStack::section(std::string_view name, bool create) {
  std::string key = toLower(name);
  if (auto it = sectionIndex_.find(key); it != sectionIndex_.end()) return &sections_[it->second];
  if (!create) return nullptr;
  sectionIndex_.emplace(std::move(key), sections_.size());
  sections_.push_back({std::string(name), {}, {}});
  return &sections_.back();
}

const ConfigStack::Section* ConfigStack::section(std::string_view name) const {
  auto it = sectionIndex_.find(toLower(name));
  return it == sectionIndex_.end() ? nullptr : &sections_[it->second];
}

const ConfigStack::Value* ConfigStack::find(std::string_view sectionName, std::string_view key) const {
  const Section* s = section(sectionName);
  if (!s) return nullptr;
  auto it = s->values.find(toLower(key));
  return it == s->values.end() ? nullptr : &it->second;
}

std::optional<std::string> ConfigStack::get(std::string_view sectionName, std::string_view key) const {
  const Value* v = find(sectionName, key);
  if (!v || !v->assigned) return std::nullopt;
  return v->text;
}

std::vector<std::string> ConfigStack::array(std::string_view sectionName, std::string_view key) const {
  const Value* v = find(sectionName, key);
  return v ? v->array : std::vector<std::string>{};
}

std::vector<std::string> ConfigStack::sections() const {
  std::vector<std::string> names;
  for (const Section& s : sections_) names.push_back(s.name);
  return names;
}

std::vector<std::string> ConfigStack::keys(std::string_view sectionName) const {
  const Section* s = section(sectionName);
  return s ? s->keyOrder : std::vector<std::string>{};
}

std::vector<CVarRegistry::Refused> ConfigStack::applyTo(CVarRegistry& cvars,
                                                        const std::vector<std::string>& reserved) const {
  struct Write {
    const Section* section;
    const std::string* key;
    const Value* value;
  };
  std::vector<Write> writes;
  for (const Section& s : sections_) {
    const bool systemSettings = equalsIgnoreCase(s.name, kSystemSettings);
    if (!systemSettings && contains(reserved, s.name)) continue;
    for (const std::string& key : s.keyOrder) {
      const Value& v = s.values.at(toLower(key));
      // Variables are scalars: a key only ever touched by array operators has no value for one.
      if (v.assigned) writes.push_back({&s, &key, &v});
    }
  }
  // Lowest priority first and in load order within a priority: two keys reaching the
  // same variable (a name and an alias, or [SystemSettings] and a plugin section) end
  // as they would had each line been applied as it was read.
  std::sort(writes.begin(), writes.end(), [](const Write& a, const Write& b) {
    if (a.value->level != b.value->level) return a.value->level < b.value->level;
    return a.value->sequence < b.value->sequence;
  });
  // The registry logs rejected and clamped values with their source, and holds values
  // for variables that are not registered yet.
  std::vector<CVarRegistry::Refused> refused;
  for (const Write& w : writes) {
    const bool system = equalsIgnoreCase(w.section->name, kSystemSettings);
    const SetResult r =
        system ? cvars.set(*w.key, w.value->text, w.value->level, w.value->source)
               : cvars.setIni(w.section->name, *w.key, w.value->text, w.value->level, w.value->source);
    if (r.status == SetResult::Status::Rejected)
      refused.push_back(
          {{system ? std::string() : w.section->name, *w.key, w.value->text, w.value->level, w.value->source},
           r.message});
  }
  return refused;
}

bool ConfigStack::saveChangedSettings(const CVarRegistry& cvars, const std::string& path,
                                      std::string* error) {
  std::vector<IniDiagnostic> diagnostics;
  std::optional<IniDocument> doc;
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    doc = IniDocument::load(path, diagnostics);
    if (!doc) {
      if (error)
        *error = diagnostics.empty() ? "cannot read " + path
                                     : diagnostics.back().where() + ": " + diagnostics.back().message;
      return false;
    }
  } else {
    doc = IniDocument::parse({}, path, diagnostics);
  }
  const std::string before = doc->text();

  bool anyChanged = false;
  for (const CVar* cvar : cvars.list()) {
    if (cvar->setBy() != SetBy::Console) continue;
    anyChanged = true;
    const std::string text = cvar->format(cvar->pendingValue() ? *cvar->pendingValue() : cvar->value());
    for (const IniKey& where : linesFor(*cvar, *doc)) doc->set(where.section, where.key, text);
  }

  // Nothing to write: leave the file (or its absence) alone rather than touch it.
  if (!anyChanged || (doc->text() == before && std::filesystem::exists(path, ec))) return true;
  return doc->save(path, error);
}

}  // namespace bounce
