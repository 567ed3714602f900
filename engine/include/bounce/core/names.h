#pragma once
// Name comparison and "did you mean" suggestions, shared by the console, the ini
// loader, the scene loader and the plugin host.

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

/// ASCII case-insensitive equality (console variables, ini keys and plugin names are
/// case-insensitive, as in Unreal).
bool equalsIgnoreCase(std::string_view a, std::string_view b);
bool startsWithIgnoreCase(std::string_view text, std::string_view prefix);
std::string toLower(std::string_view text);

/// Edit distance, case-insensitive.
size_t editDistance(std::string_view a, std::string_view b);

/// Names longer than this get no suggestions (see closestNames).
inline constexpr size_t kMaxSuggestedNameLength = 256;

/// Up to `maxCount` candidates closest to `name`: prefix matches first, then by edit
/// distance, dropping candidates too far to be a plausible typo. Costs at most
/// O(|candidates| · kMaxSuggestedNameLength²), whatever `name` is.
std::vector<std::string> closestNames(std::string_view name, std::span<const std::string> candidates,
                                      size_t maxCount = 3);

/// " (did you mean 'a', 'b'?)" or "" when nothing is close.
std::string didYouMean(std::string_view name, std::span<const std::string> candidates);

/// User input made safe to print inside a one-line message: control characters (C0,
/// DEL, and U+0080–U+009F, which terminals obey as escape sequences) and bytes that are
/// not valid UTF-8 become `\n`, `\r`, `\t` or `\xHH`; everything else, UTF-8 text
/// included, is kept, so 'abc' and 'Grüße' read as written. The log sink applies it to
/// every message with `multiLine` (keeping line breaks and tabs, which multi-line reports
/// such as shader errors use); quote user input with it wherever a message bypasses the log.
std::string printable(std::string_view text, bool multiLine = false);

/// `text` for a one-line message: printable(), and past `maxLength` bytes cut with
/// "… (N bytes)", so a megabyte of input named in an error stays one readable line.
std::string abbreviated(std::string_view text, size_t maxLength = 120);

}  // namespace bounce
