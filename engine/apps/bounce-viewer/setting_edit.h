#pragma once
// A value a Settings-panel widget produced, written the way every other setting write is:
// through the registry at console priority, so the variable's own validator refuses or
// clamps it exactly as the console, scripts, ini files and -set would.

#include "bounce/config/cvar_registry.h"
#include "console_log.h"

#include <string>

namespace bounce::viewer {

/// Writes `text` to `cvar`; the outcome (the line as typed, a refusal, a clamp or a
/// pending restart) goes to `log`. False when refused (the variable keeps its value).
bool applySettingEdit(CVarRegistry& cvars, ConsoleLog& log, CVar& cvar, const std::string& text);

}  // namespace bounce::viewer
