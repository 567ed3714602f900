#pragma once
// A --script file: console lines and viewer actions run one per line, in order. The
// viewer takes lines until one asks for frames (`frames N`, `screenshot`), renders
// them, and goes on; blank lines and comments (#, //, ;) are skipped.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::viewer {

struct ScriptLine {
  size_t number = 0;  ///< 1-based, for messages
  std::string text;
};

class Script {
 public:
  /// Reads `path`; on failure returns nullopt with a one-line reason.
  static std::optional<Script> load(const std::string& path, std::string* error);
  /// The lines of a script's text; `path` names it in messages. (Separate from load so
  /// that tests/fuzz can feed it without a file or a window.)
  static Script parse(std::string_view text, const std::string& path);
  const std::string& path() const { return path_; }
  std::optional<ScriptLine> next();
  bool finished() const { return position_ >= lines_.size(); }

 private:
  std::string path_;
  std::vector<ScriptLine> lines_;
  size_t position_ = 0;
};

}  // namespace bounce::viewer
