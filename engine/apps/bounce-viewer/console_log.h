#pragma once
// What the viewer's console shows: typed lines, their output, and every warning and
// error the engine logs (a bad cvar, a shader that does not compile, a plugin that
// failed). Errors also become toasts, short-lived notes in the window's corner, so they
// are seen with the console closed. Thread-safe: plugins may log from worker threads.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace bounce::viewer {

enum class LineKind { Input, Output, Warning, Error };

struct ConsoleLine {
  LineKind kind = LineKind::Output;
  std::string text;
};

struct Toast {
  std::string text;
  std::chrono::steady_clock::time_point shownAt;
};

class ConsoleLog {
 public:
  /// Adds a line; warnings and errors are toasted too.
  void add(LineKind kind, std::string text);
  /// Adds a line unless the same text came during `frame` or the frame before: some
  /// engine errors repeat every frame (a pass whose shader does not compile), and the
  /// console says each once until it stops.
  void addUnlessRepeated(LineKind kind, std::string text, uint64_t frame);
  std::vector<ConsoleLine> lines() const;
  size_t errorCount() const;
  void clear();

  /// Toasts younger than `lifetime`; older ones are dropped.
  std::vector<Toast> liveToasts(std::chrono::steady_clock::duration lifetime);

 private:
  static constexpr size_t kMaxLines = 2000;  // oldest lines go first
  mutable std::mutex mutex_;
  std::deque<ConsoleLine> lines_;
  std::deque<Toast> toasts_;
  size_t errors_ = 0;
  std::map<std::string, uint64_t> lastFrameSeen_;
};

}  // namespace bounce::viewer
