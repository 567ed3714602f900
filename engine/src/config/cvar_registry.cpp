#include "bounce/config/cvar_registry.h"
#include "config/cvar_range_text.h"

#include "bounce/core/log.h"
#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bounce {

struct CVarRegistry::Observers {
  uint64_t nextId = 1;
  std::vector<std::pair<uint64_t, std::function<void(const CVar&)>>> list;
};

namespace {

std::string iniKey(std::string_view section, std::string_view key) {
  return toLower(section) + '\n' + toLower(key);
}

double numeric(const CVarValue& v) {
  if (auto* i = std::get_if<int32_t>(&v)) return *i;
  if (auto* f = std::get_if<float>(&v)) return *f;
  return 0.0;
}

bool isNumeric(CVarType t) { return t == CVarType::Int || t == CVarType::Float; }

}  // namespace

CVarRegistry::CVarRegistry() : observers_(std::make_shared<Observers>()) {}
CVarRegistry::~CVarRegistry() = default;

CVar& CVarRegistry::declare(CVarType type, std::string name, std::vector<std::string> aliases,
                            std::string help, CVarValue defaultValue, std::optional<double> min,
                            std::optional<double> max, RangePolicy policy, std::vector<CVarValue> allowed,
                            std::vector<std::string> enumNames, CVarFlags flags, IniBinding ini,
                            std::string postProcess, std::string category,
                            std::function<std::string(const CVarValue&)> validate, OwnerId owner) {
  if (name.empty()) throw std::invalid_argument("console variable declared without a name");
  for (const std::string& n : [&] {
         std::vector<std::string> all{name};
         all.insert(all.end(), aliases.begin(), aliases.end());
         return all;
       }())
    if (byName_.count(toLower(n)))
      throw std::invalid_argument(fmt::format("console variable '{}' is already declared", n));
  if (!ini.empty() && byIni_.count(iniKey(ini.section, ini.key)))
    throw std::invalid_argument(
        fmt::format("ini key [{}] {} is already bound to another variable", ini.section, ini.key));

  auto cvar = std::make_unique<CVar>(CVar::RegistryKey{});
  CVar& c = *cvar;
  c.name_ = std::move(name);
  c.aliases_ = std::move(aliases);
  c.type_ = type;
  c.help_ = std::move(help);
  c.flags_ = flags;
  c.ini_ = std::move(ini);
  c.postProcess_ = std::move(postProcess);
  c.category_ = std::move(category);
  c.owner_ = owner;
  c.min_ = min;
  c.max_ = max;
  c.rangePolicy_ = policy;
  c.enumNames_ = std::move(enumNames);
  c.allowed_ = std::move(allowed);
  for (const CVarValue& v : c.allowed_) c.allowedText_.push_back(c.format(v));
  if (c.type_ == CVarType::Enum) c.allowedText_ = c.enumNames_;
  c.validate_ = std::move(validate);
  c.value_ = defaultValue;
  c.default_ = std::move(defaultValue);

  // A default that its own declaration would reject is a programming error.
  if (isNumeric(type)) {
    double v = numeric(c.default_);
    if ((min && v < *min) || (max && v > *max))
      throw std::invalid_argument(fmt::format("default of '{}' is outside {}", c.name_, rangeText(c)));
  }
  if (type == CVarType::Enum && size_t(std::get<int32_t>(c.default_)) >= c.enumNames_.size())
    throw std::invalid_argument(fmt::format("default of enum '{}' is not a valid index", c.name_));
  if (!c.allowed_.empty() && std::find(c.allowed_.begin(), c.allowed_.end(), c.default_) == c.allowed_.end())
    throw std::invalid_argument(fmt::format("default of '{}' is not an allowed value", c.name_));
  if (c.validate_) {
    if (std::string e = c.validate_(c.default_); !e.empty())
      throw std::invalid_argument(fmt::format("default of '{}' is invalid: {}", c.name_, e));
  }

  CVar& inserted = insert(std::move(cvar));
  applyDeferred(inserted);
  return inserted;
}

CVar& CVarRegistry::insert(std::unique_ptr<CVar> cvar) {
  CVar& c = *cvar;
  byName_[toLower(c.name_)] = &c;
  for (const std::string& a : c.aliases_) byName_[toLower(a)] = &c;
  if (!c.ini_.empty()) byIni_[iniKey(c.ini_.section, c.ini_.key)] = &c;
  cvars_.push_back(std::move(cvar));
  return c;
}

void CVarRegistry::applyDeferred(CVar& cvar) {
  std::vector<Deferred> mine;
  auto matches = [&](const Deferred& d) {
    if (d.section.empty()) {
      if (equalsIgnoreCase(d.key, cvar.name_)) return true;
      return std::any_of(cvar.aliases_.begin(), cvar.aliases_.end(),
                         [&](const std::string& a) { return equalsIgnoreCase(d.key, a); });
    }
    return !cvar.ini_.empty() && equalsIgnoreCase(d.section, cvar.ini_.section) &&
           equalsIgnoreCase(d.key, cvar.ini_.key);
  };
  for (auto it = deferred_.begin(); it != deferred_.end();) {
    if (matches(*it)) {
      mine.push_back(std::move(*it));
      it = deferred_.erase(it);
    } else {
      ++it;
    }
  }
  // Lowest priority first, keeping load order within a priority, so the outcome is the
  // same as if the variable had existed when the values were read.
  std::stable_sort(mine.begin(), mine.end(),
                   [](const Deferred& a, const Deferred& b) { return a.by < b.by; });
  for (const Deferred& d : mine) {
    SetResult r = set(cvar, d.text, d.by, d.source);
    if (r.status == SetResult::Status::Rejected) refused_.push_back({d, r.message});
  }
}

CVar* CVarRegistry::find(std::string_view nameOrAlias) const {
  auto it = byName_.find(toLower(nameOrAlias));
  return it == byName_.end() ? nullptr : it->second;
}

CVar* CVarRegistry::findByIni(std::string_view section, std::string_view key) const {
  auto it = byIni_.find(iniKey(section, key));
  return it == byIni_.end() ? nullptr : it->second;
}

bool CVarRegistry::hasSection(std::string_view section) const {
  return std::any_of(cvars_.begin(), cvars_.end(), [&](const auto& c) {
    return !c->ini_.empty() && equalsIgnoreCase(c->ini_.section, section);
  });
}

std::vector<std::string> CVarRegistry::keysInSection(std::string_view section) const {
  std::vector<std::string> keys;
  for (const auto& c : cvars_)
    if (!c->ini_.empty() && equalsIgnoreCase(c->ini_.section, section)) keys.push_back(c->ini_.key);
  return keys;
}

std::vector<CVar*> CVarRegistry::list(std::string_view prefix) const {
  std::vector<CVar*> out;
  for (const auto& c : cvars_)
    if (startsWithIgnoreCase(c->name_, prefix)) out.push_back(c.get());
  std::sort(out.begin(), out.end(),
            [](const CVar* a, const CVar* b) { return toLower(a->name()) < toLower(b->name()); });
  return out;
}

std::vector<std::string> CVarRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& c : cvars_) {
    out.push_back(c->name_);
    out.insert(out.end(), c->aliases_.begin(), c->aliases_.end());
  }
  return out;
}

bool CVarRegistry::cheatsAllowed() const {
  // Without the engine's con.AllowCheats (a bare registry in a tool) nothing is guarded.
  const CVar* allow = find("con.AllowCheats");
  return !allow || allow->type() != CVarType::Bool || allow->getBool();
}

SetResult CVarRegistry::set(std::string_view name, std::string_view text, SetBy by, std::string_view source) {
  if (CVar* c = find(name)) return set(*c, text, by, source);
  if (by == SetBy::Console) {
    return {SetResult::Status::Rejected,
            fmt::format("unknown console variable '{}'{}", name, didYouMean(name, names()))};
  }
  // Unreal holds ini and command-line values for variables a plugin registers later.
  deferred_.push_back({{}, std::string(name), std::string(text), by, std::string(source)});
  return {SetResult::Status::Deferred, {}};
}

SetResult CVarRegistry::setIni(std::string_view section, std::string_view key, std::string_view text,
                               SetBy by, std::string_view source) {
  if (CVar* c = findByIni(section, key)) return set(*c, text, by, source);
  deferred_.push_back({std::string(section), std::string(key), std::string(text), by, std::string(source)});
  return {SetResult::Status::Deferred, {}};
}

SetResult CVarRegistry::set(CVar& cvar, std::string_view text, SetBy by, std::string_view source) {
  std::string error;
  std::optional<CVarValue> value = cvar.parse(text, &error);
  if (!value) {
    // "3e9" for an int is a number out of its range, not text: it is checked as the same
    // number in a post-process volume would be (clamped or refused by the declaration).
    if (std::optional<double> number = CVar::wideNumber(cvar.type(), text))
      return write(
          cvar, [&] { return cvar.checkNumber(*number); }, by, source);
    SetResult r{SetResult::Status::Rejected,
                fmt::format("{}: {}; keeps {}", cvar.name(), error, cvar.valueText())};
    if (by != SetBy::Console) log::error("{}: {}", source.empty() ? setByName(by) : source, r.message);
    return r;
  }
  return setValue(cvar, std::move(*value), by, source);
}

SetResult CVarRegistry::setValue(CVar& c, CVarValue value, SetBy by, std::string_view source) {
  return write(
      c, [&] { return c.check(std::move(value)); }, by, source);
}

SetResult CVarRegistry::write(CVar& c, const std::function<CheckedValue()>& check, SetBy by,
                              std::string_view source) {
  using Status = SetResult::Status;
  std::string where = source.empty() ? std::string(setByName(by)) : std::string(source);
  // Writes that nobody sees the result of (ini files, the command line) are logged
  // here; console writes return their message to the console, which prints it.
  auto finish = [&](SetResult r) {
    if (by != SetBy::Console && !r.message.empty()) {
      if (r.status == Status::Rejected)
        log::error("{}: {}", where, r.message);
      else if (r.status == Status::Clamped)
        log::warn("{}: {}", where, r.message);
      else
        log::debug("{}: {}", where, r.message);
    }
    return r;
  };

  if (hasFlag(c.flags_, CVarFlags::ReadOnly) && by >= SetBy::CommandLine)
    return finish({Status::Rejected, fmt::format("{} is read-only (set it in an ini file)", c.name_)});
  if (hasFlag(c.flags_, CVarFlags::Cheat) && by >= SetBy::CommandLine && !cheatsAllowed())
    return finish(
        {Status::Rejected, fmt::format("{} is a cheat variable; set con.AllowCheats 1 first", c.name_)});
  if (by < c.setBy_)
    return finish(
        {Status::Ignored, fmt::format("{} keeps {} (set by {} at {}, which has priority over {})", c.name_,
                                      c.valueText(), setByName(c.setBy_), c.source_, setByName(by))});

  CheckedValue checked = check();
  if (!checked.ok())
    return finish({Status::Rejected, fmt::format("{}; keeps {}", checked.message, c.valueText())});
  CVarValue value = std::move(*checked.value);
  const Status status = checked.clamped ? Status::Clamped : Status::Changed;
  std::string message = std::move(checked.message);

  c.setBy_ = by;
  c.source_ = where;
  if (hasFlag(c.flags_, CVarFlags::RequiresRestart) && startupComplete_) {
    if (value == c.value_) {
      c.pending_.reset();
      return finish({Status::Unchanged, {}});
    }
    c.pending_ = value;
    return finish({Status::Pending, fmt::format("{} will be {} after a restart (now {})", c.name_,
                                                c.format(value), c.valueText())});
  }
  if (value == c.value_) return finish({status == Status::Clamped ? status : Status::Unchanged, message});
  c.value_ = std::move(value);
  c.pending_.reset();
  notify(c);
  return finish({status, message});
}

std::vector<CVarRegistry::Deferred> CVarRegistry::deferred() const { return deferred_; }
void CVarRegistry::clearDeferred() { deferred_.clear(); }

void CVarRegistry::removeOwnedBy(OwnerId owner) {
  for (auto it = byName_.begin(); it != byName_.end();)
    it = it->second->owner_ == owner ? byName_.erase(it) : std::next(it);
  for (auto it = byIni_.begin(); it != byIni_.end();)
    it = it->second->owner_ == owner ? byIni_.erase(it) : std::next(it);
  std::erase_if(cvars_, [owner](const auto& c) { return c->owner_ == owner; });
}

Subscription CVarRegistry::onAnyChanged(std::function<void(const CVar&)> callback) {
  uint64_t id = observers_->nextId++;
  observers_->list.emplace_back(id, std::move(callback));
  return Subscription([weak = std::weak_ptr<Observers>(observers_), id] {
    if (auto obs = weak.lock()) std::erase_if(obs->list, [id](const auto& e) { return e.first == id; });
  });
}

void CVarRegistry::notify(CVar& cvar) {
  cvar.fireChanged();
  auto list = observers_->list;
  for (const auto& [id, callback] : list) callback(cvar);
}

}  // namespace bounce
