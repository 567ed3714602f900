#include "bounce/config/console.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace bounce {

std::string ConsoleResult::text() const { return fmt::format("{}", fmt::join(lines, "\n")); }

Console::Console(CVarRegistry& cvars) : cvars_(cvars) {}

std::vector<std::string> Console::split(std::string_view line) {
  std::vector<std::string> words;
  std::string current;
  bool inQuotes = false, hasWord = false;
  for (size_t i = 0; i < line.size(); ++i) {
    char c = line[i];
    if (c == '\\' && i + 1 < line.size() && (line[i + 1] == '"' || line[i + 1] == '\\')) {
      current += line[++i];
      hasWord = true;
    } else if (c == '"') {
      inQuotes = !inQuotes;
      hasWord = true;
    } else if (!inQuotes && std::isspace(static_cast<unsigned char>(c))) {
      if (hasWord) words.push_back(std::move(current));
      current.clear();
      hasWord = false;
    } else {
      current += c;
      hasWord = true;
    }
  }
  if (hasWord) words.push_back(std::move(current));
  return words;
}

ConsoleResult Console::execute(std::string_view line, SetBy by) {
  std::vector<std::string> words = split(line);
  if (words.empty() || words[0].starts_with(';') || words[0].starts_with('#') || words[0].starts_with("//"))
    return {};
  // `name=value` is accepted as well as `name value`.
  if (size_t eq = words[0].find('='); eq != std::string::npos && eq > 0) {
    std::string value = words[0].substr(eq + 1);
    words[0].resize(eq);
    words.insert(words.begin() + 1, value);
    if (words[1].empty()) words.erase(words.begin() + 1);
  }
  const std::string& name = words[0];
  std::vector<std::string> args(words.begin() + 1, words.end());

  if (equalsIgnoreCase(name, "help")) return listPrefix(args.empty() ? std::string_view{} : args[0]);
  if (auto it = commands_.find(toLower(name)); it != commands_.end()) return it->second.desc.run(args);

  if (CVar* cvar = cvars_.find(name)) {
    if (args.empty()) return describe(*cvar, true);
    if (args.size() == 1 && args[0] == "?") return describe(*cvar, true);
    // Strings may contain spaces without quotes: everything after the name is the value.
    std::string value = args.size() == 1 ? args[0] : fmt::format("{}", fmt::join(args, " "));
    SetResult r = cvars_.set(*cvar, value, by, by == SetBy::Console ? "console" : "");
    using S = SetResult::Status;
    switch (r.status) {
      case S::Changed:
      case S::Unchanged:
        return {true, {fmt::format("{} = {}", cvar->name(), cvar->valueText())}};
      case S::Rejected:
        return {false, {r.message}};
      default:
        return {true, {r.message}};
    }
  }

  std::vector<CVar*> matches = cvars_.list(name);
  if (!matches.empty()) return listPrefix(name);
  std::vector<std::string> candidates = cvars_.names();
  for (const auto& [key, cmd] : commands_) candidates.push_back(cmd.desc.name);
  return {false,
          {fmt::format("unknown console variable or command '{}'{}", name, didYouMean(name, candidates))}};
}

ConsoleResult Console::describe(const CVar& c, bool withHelp) const {
  ConsoleResult r;
  r.lines.push_back(fmt::format("{} = {}    [{}, set by {}: {}]", c.name(), c.valueText(),
                                cvarTypeName(c.type()), setByName(c.setBy()), c.setBySource()));
  if (c.pendingValue()) r.lines.push_back(fmt::format("  after restart: {}", c.format(*c.pendingValue())));
  if (!withHelp) return r;
  if (!c.help().empty()) r.lines.push_back("  " + c.help());
  if (c.min() || c.max()) {
    auto num = [&](double v) {
      return c.type() == CVarType::Int ? fmt::format("{}", int64_t(v)) : fmt::format("{}", v);
    };
    r.lines.push_back(fmt::format("  range: {} .. {}{}", c.min() ? num(*c.min()) : "",
                                  c.max() ? num(*c.max()) : "",
                                  c.rangePolicy() == RangePolicy::Clamp ? " (clamped)" : ""));
  }
  if (!c.allowedValues().empty())
    r.lines.push_back(fmt::format("  values: {}", fmt::join(c.allowedValues(), ", ")));
  r.lines.push_back(fmt::format("  default: {}", c.format(c.defaultValue())));
  if (!c.aliases().empty()) r.lines.push_back(fmt::format("  aliases: {}", fmt::join(c.aliases(), ", ")));
  if (!c.ini().empty()) r.lines.push_back(fmt::format("  ini: [{}] {}", c.ini().section, c.ini().key));
  if (!c.postProcessName().empty())
    r.lines.push_back(fmt::format("  post-process setting: {}", c.postProcessName()));
  std::vector<std::string> flags;
  if (hasFlag(c.flags(), CVarFlags::ReadOnly)) flags.push_back("read-only");
  if (hasFlag(c.flags(), CVarFlags::Cheat)) flags.push_back("cheat");
  if (hasFlag(c.flags(), CVarFlags::RequiresRestart)) flags.push_back("requires restart");
  if (!flags.empty()) r.lines.push_back(fmt::format("  flags: {}", fmt::join(flags, ", ")));
  return r;
}

ConsoleResult Console::listPrefix(std::string_view prefix) const {
  ConsoleResult r;
  for (const CVar* c : cvars_.list(prefix)) {
    std::string help = c->help().substr(0, c->help().find('\n'));
    r.lines.push_back(fmt::format("{} = {}  {}", c->name(), c->valueText(), help));
  }
  for (const auto& [key, cmd] : commands_)
    if (startsWithIgnoreCase(cmd.desc.name, prefix))
      r.lines.push_back(fmt::format("{}  (command) {}", cmd.desc.name, cmd.desc.help));
  if (r.lines.empty()) {
    r.ok = false;
    r.lines.push_back(fmt::format("nothing starts with '{}'", prefix));
  }
  return r;
}

void Console::addCommand(ConsoleCommandDesc desc, OwnerId owner) {
  std::string key = toLower(desc.name);
  commands_[key] = Command{std::move(desc), owner};
}

void Console::removeOwnedBy(OwnerId owner) {
  std::erase_if(commands_, [owner](const auto& entry) { return entry.second.owner == owner; });
}

bool Console::hasCommand(std::string_view name) const { return commands_.count(toLower(name)) != 0; }

std::vector<std::string> Console::complete(std::string_view prefix) const {
  std::vector<std::string> out;
  for (const CVar* c : cvars_.list(prefix)) out.push_back(c->name());
  for (const auto& [key, cmd] : commands_)
    if (startsWithIgnoreCase(cmd.desc.name, prefix)) out.push_back(cmd.desc.name);
  if (startsWithIgnoreCase("help", prefix)) out.push_back("help");
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace bounce
