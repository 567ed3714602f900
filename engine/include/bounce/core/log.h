#pragma once
// One-line diagnostics for users and plugins. Everything the engine reports goes
// through here, so tests, the viewer console and the terminal all see the same lines.

#include <fmt/format.h>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::log {

enum class Level { Debug, Info, Warning, Error };

std::string_view levelName(Level level);

/// Writes one message. Messages are single lines by convention: callers name the
/// file:line, the value or the plugin at fault, and what happens next.
void write(Level level, std::string_view message);

template <class... Args>
void debug(fmt::format_string<Args...> f, Args&&... args) {
  write(Level::Debug, fmt::format(f, std::forward<Args>(args)...));
}
template <class... Args>
void info(fmt::format_string<Args...> f, Args&&... args) {
  write(Level::Info, fmt::format(f, std::forward<Args>(args)...));
}
template <class... Args>
void warn(fmt::format_string<Args...> f, Args&&... args) {
  write(Level::Warning, fmt::format(f, std::forward<Args>(args)...));
}
template <class... Args>
void error(fmt::format_string<Args...> f, Args&&... args) {
  write(Level::Error, fmt::format(f, std::forward<Args>(args)...));
}

/// Lowest level printed to the terminal (the default is Info; BOUNCE_LOG_LEVEL=debug
/// in the environment lowers it). Listeners receive every level.
void setTerminalLevel(Level level);

struct Record {
  Level level;
  std::string message;
};

/// Receives every message while alive (the viewer console, tests). RAII: the
/// listener is removed when this object is destroyed.
class Listener {
 public:
  explicit Listener(std::function<void(const Record&)> callback);
  ~Listener();
  Listener(const Listener&) = delete;
  Listener& operator=(const Listener&) = delete;

 private:
  std::function<void(const Record&)> callback_;
};

/// Collects messages while alive; handy for asserting that an error was reported.
class Capture {
 public:
  Capture();
  const std::vector<Record>& records() const { return records_; }
  /// Number of messages at `level` whose text contains `needle` (empty: all at level).
  size_t count(Level level, std::string_view needle = {}) const;
  bool contains(std::string_view needle) const;
  std::string joined() const;

 private:
  std::vector<Record> records_;
  Listener listener_;
};

}  // namespace bounce::log
