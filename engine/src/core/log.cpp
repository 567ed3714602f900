#include "bounce/core/log.h"

#include "bounce/core/names.h"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>

namespace bounce::log {
namespace {

struct Hub {
  std::mutex mutex;
  std::vector<Listener*> listeners;
  std::vector<std::function<void(const Record&)>*> callbacks;
  std::shared_ptr<spdlog::logger> terminal;
  Level terminalLevel = Level::Info;

  Hub() {
    terminal = spdlog::stderr_color_mt("bounce");
    terminal->set_pattern("%^%l%$: %v");
    terminal->set_level(spdlog::level::trace);
    if (const char* env = std::getenv("BOUNCE_LOG_LEVEL")) {
      std::string v(env);
      if (v == "debug") terminalLevel = Level::Debug;
      if (v == "warning") terminalLevel = Level::Warning;
      if (v == "error") terminalLevel = Level::Error;
    }
  }
};

Hub& hub() {
  static Hub instance;
  return instance;
}

spdlog::level::level_enum toSpd(Level level) {
  switch (level) {
    case Level::Debug:
      return spdlog::level::debug;
    case Level::Info:
      return spdlog::level::info;
    case Level::Warning:
      return spdlog::level::warn;
    case Level::Error:
      return spdlog::level::err;
  }
  return spdlog::level::info;
}

}  // namespace

std::string_view levelName(Level level) {
  switch (level) {
    case Level::Debug:
      return "debug";
    case Level::Info:
      return "info";
    case Level::Warning:
      return "warning";
    case Level::Error:
      return "error";
  }
  return "?";
}

void write(Level level, std::string_view text) {
  // Messages quote user input (names, values, script lines): escaping control bytes here
  // keeps an ESC sequence in a bad value from reaching the terminal by any path.
  const std::string message = printable(text, true);
  Hub& h = hub();
  std::lock_guard lock(h.mutex);
  if (level >= h.terminalLevel) h.terminal->log(toSpd(level), "{}", message);
  if (!h.callbacks.empty()) {
    Record record{level, message};
    for (auto* cb : h.callbacks) (*cb)(record);
  }
}

void setTerminalLevel(Level level) {
  std::lock_guard lock(hub().mutex);
  hub().terminalLevel = level;
}

Listener::Listener(std::function<void(const Record&)> callback) : callback_(std::move(callback)) {
  std::lock_guard lock(hub().mutex);
  hub().callbacks.push_back(&callback_);
}

Listener::~Listener() {
  std::lock_guard lock(hub().mutex);
  auto& v = hub().callbacks;
  v.erase(std::remove(v.begin(), v.end(), &callback_), v.end());
}

Capture::Capture() : listener_([this](const Record& r) { records_.push_back(r); }) {}

size_t Capture::count(Level level, std::string_view needle) const {
  return size_t(std::count_if(records_.begin(), records_.end(), [&](const Record& r) {
    return r.level == level && (needle.empty() || r.message.find(needle) != std::string::npos);
  }));
}

bool Capture::contains(std::string_view needle) const {
  return std::any_of(records_.begin(), records_.end(),
                     [&](const Record& r) { return r.message.find(needle) != std::string::npos; });
}

std::string Capture::joined() const {
  std::string out;
  for (const Record& r : records_) out += fmt::format("{}: {}\n", levelName(r.level), r.message);
  return out;
}

}  // namespace bounce::log
