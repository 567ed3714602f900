#pragma once
// The console panel: the log, and an input line that runs exactly what the engine
// console runs (plus the viewer's own commands), with history (Up/Down) and tab
// completion of variable and command names.

#include "bounce/config/console.h"
#include "console_log.h"
#include "dock_layout.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

struct ImGuiInputTextCallbackData;

namespace bounce::viewer {

class ConsolePanel {
 public:
  ConsolePanel(ConsoleLog& log, const Console& console, std::function<void(const std::string&)> run);
  void draw(const DockLayout& layout, bool* open);

  /// Completes the first word of `line` against variable and command names: the single
  /// match (followed by a space) or the longest common prefix of several; `candidates`
  /// receives the matches. Exposed for its own sake: it is what Tab does.
  std::string complete(const std::string& line, std::vector<std::string>* candidates) const;

 private:
  static int onInputEvent(ImGuiInputTextCallbackData* data);
  void submit();

  ConsoleLog& log_;
  const Console& console_;
  std::function<void(const std::string&)> run_;
  std::array<char, 512> input_{};
  std::vector<std::string> history_;
  int historyPos_ = -1;  // -1: editing a new line
  bool scrollToBottom_ = true;
  bool refocus_ = false;
};

}  // namespace bounce::viewer
