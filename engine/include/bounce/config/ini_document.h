#pragma once
// One .ini file in Unreal syntax, kept line by line so it can be edited and written
// back with its comments, blank lines and key order intact.
//
//   ; comment            (whole lines starting with ';' or '#')
//   [Section]
//   Key=Value            set (later lines win)
//   +Key=Value           append to the array Key unless already present
//   .Key=Value           append even if present
//   -Key=Value           remove that value from the array
//   !Key=                clear the array
//   Key="quoted value"   quotes keep spaces and ';'; \" and \\ escape
//
// Inline comments are not supported (as in Unreal): `Key=1 ; x` has value "1 ; x".

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

/// A problem found while reading an ini file, with its location.
struct IniDiagnostic {
  std::string file;
  int line = 0;  ///< 1-based; 0 when about the whole file
  std::string message;
  std::string where() const;  ///< "file:line"
};

struct IniEntry {
  enum class Op : char { Set = '=', Append = '+', AppendDuplicate = '.', Remove = '-', Clear = '!' };
  Op op = Op::Set;
  std::string section;
  std::string key;
  std::string value;  ///< unquoted, unescaped
  int line = 0;       ///< 1-based
};

class IniDocument {
 public:
  IniDocument() = default;

  /// Parses text. Bad lines are reported in `diagnostics` and skipped; the rest of the
  /// file still loads.
  static IniDocument parse(std::string_view text, std::string path, std::vector<IniDiagnostic>& diagnostics);
  /// Largest ini file read. Unreal's whole shipped config tree is under 2 MiB; the cap
  /// leaves room for generated files and stops a device or a runaway file eating memory.
  static constexpr uintmax_t kMaxFileBytes = uintmax_t(16) << 20;
  /// Reads and parses a regular file of at most kMaxFileBytes; nullopt (with a
  /// diagnostic) when it cannot be read.
  static std::optional<IniDocument> load(const std::string& path, std::vector<IniDiagnostic>& diagnostics);

  const std::string& path() const { return path_; }
  const std::vector<IniEntry>& entries() const { return entries_; }

  /// Sets `key` in `section`: rewrites the key's last plain assignment in place, or
  /// adds a line at the end of the section, or appends a new section. Untouched lines,
  /// comments and order are preserved.
  void set(std::string_view section, std::string_view key, std::string_view value);

  std::string text() const;
  /// Writes atomically (temporary file + rename); false with a reason on failure.
  bool save(const std::string& path, std::string* error) const;

  /// Quotes a value when writing it would otherwise change it (spaces at the ends,
  /// quotes, backslashes, empty).
  static std::string quoteIfNeeded(std::string_view value);

 private:
  std::string path_;
  std::vector<std::string> lines_;
  std::vector<IniEntry> entries_;
  bool trailingNewline_ = true;
};

}  // namespace bounce
