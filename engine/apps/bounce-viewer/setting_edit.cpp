#include "setting_edit.h"

#include <fmt/format.h>

namespace bounce::viewer {

bool applySettingEdit(CVarRegistry& cvars, ConsoleLog& log, CVar& cvar, const std::string& text) {
  const SetResult r = cvars.set(cvar, text, SetBy::Console, "viewer");
  if (r.status == SetResult::Status::Rejected) {
    log.add(LineKind::Error, r.message);
    return false;
  }
  log.add(LineKind::Input, fmt::format("{} {}", cvar.name(), text));
  if (!r.message.empty()) log.add(LineKind::Warning, r.message);  // clamped, pending
  return true;
}

}  // namespace bounce::viewer
