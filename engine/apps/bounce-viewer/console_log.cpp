#include "console_log.h"

namespace bounce::viewer {

void ConsoleLog::add(LineKind kind, std::string text) {
  std::lock_guard lock(mutex_);
  if (kind == LineKind::Error || kind == LineKind::Warning) {
    if (kind == LineKind::Error) ++errors_;
    toasts_.push_back({text, std::chrono::steady_clock::now()});
    if (toasts_.size() > 5) toasts_.pop_front();  // a burst of errors must not fill the window
  }
  lines_.push_back({kind, std::move(text)});
  if (lines_.size() > kMaxLines) lines_.pop_front();
}

void ConsoleLog::addUnlessRepeated(LineKind kind, std::string text, uint64_t frame) {
  {
    std::lock_guard lock(mutex_);
    if (lastFrameSeen_.size() > 1000) lastFrameSeen_.clear();  // bounded: old texts may be said again
    auto [it, inserted] = lastFrameSeen_.try_emplace(text, frame);
    const bool repeated = !inserted && it->second + 1 >= frame;
    it->second = frame;
    if (repeated) return;
  }
  add(kind, std::move(text));
}

std::vector<ConsoleLine> ConsoleLog::lines() const {
  std::lock_guard lock(mutex_);
  return {lines_.begin(), lines_.end()};
}

size_t ConsoleLog::errorCount() const {
  std::lock_guard lock(mutex_);
  return errors_;
}

void ConsoleLog::clear() {
  std::lock_guard lock(mutex_);
  lines_.clear();
}

std::vector<Toast> ConsoleLog::liveToasts(std::chrono::steady_clock::duration lifetime) {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  while (!toasts_.empty() && now - toasts_.front().shownAt > lifetime) toasts_.pop_front();
  return {toasts_.begin(), toasts_.end()};
}

}  // namespace bounce::viewer
