#include "bounce/config/ini_document.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <system_error>

namespace bounce {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

bool isBlank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view text) {
  while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
  while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
  return text;
}

bool endsWithCarriageReturn(std::string_view line) { return !line.empty() && line.back() == '\r'; }

/// What one stored line means. parse() and set() both classify lines through this, so
/// an edit finds sections and values exactly where parsing saw them.
struct LineMeaning {
  enum class Kind { Blank, Comment, Section, BadSection, Entry, Error };
  Kind kind = Kind::Blank;
  std::string section;  // Section
  IniEntry::Op op = IniEntry::Op::Set;
  std::string key;
  std::string value;       // unquoted, unescaped
  size_t valueOffset = 0;  // where the value's text starts in the raw line (Entry)
  std::string error;       // Error, BadSection
};

LineMeaning fail(LineMeaning::Kind kind, std::string message) {
  LineMeaning m;
  m.kind = kind;
  m.error = std::move(message);
  return m;
}

/// Reads a value that starts with '"'. Only \" and \\ are escapes; any other backslash
/// is kept, so Windows paths survive being quoted by hand.
LineMeaning readQuoted(std::string_view text, LineMeaning m) {
  std::string out;
  size_t i = 1;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\\' && i + 1 < text.size() && (text[i + 1] == '"' || text[i + 1] == '\\')) {
      out += text[++i];
      continue;
    }
    if (c == '"') break;
    out += c;
  }
  if (i >= text.size()) return fail(LineMeaning::Kind::Error, "unterminated quoted value");
  std::string_view rest = trim(text.substr(i + 1));
  if (!rest.empty())
    return fail(LineMeaning::Kind::Error, fmt::format("unexpected '{}' after the closing quote", rest));
  m.value = std::move(out);
  return m;
}

LineMeaning interpret(std::string_view raw, bool firstLine) {
  std::string_view body = raw;
  // A BOM only means something at the very start of the file; elsewhere it is text.
  if (firstLine && body.starts_with(kUtf8Bom)) body.remove_prefix(kUtf8Bom.size());
  if (endsWithCarriageReturn(body)) body.remove_suffix(1);

  const std::string_view line = trim(body);
  LineMeaning m;
  if (line.empty()) return m;
  if (line.front() == ';' || line.front() == '#') {
    m.kind = LineMeaning::Kind::Comment;
    return m;
  }

  if (line.front() == '[') {
    const size_t close = line.find(']');
    if (close == std::string_view::npos)
      return fail(LineMeaning::Kind::BadSection,
                  "missing ']' in section header (keys up to the next [Section] are ignored)");
    const std::string_view rest = trim(line.substr(close + 1));
    if (!rest.empty())
      return fail(LineMeaning::Kind::BadSection,
                  fmt::format("unexpected '{}' after ']' in section header (keys up to the next "
                              "[Section] are ignored)",
                              rest));
    const std::string_view name = trim(line.substr(1, close - 1));
    if (name.empty())
      return fail(LineMeaning::Kind::BadSection,
                  "empty section name (keys up to the next [Section] are ignored)");
    m.kind = LineMeaning::Kind::Section;
    m.section = std::string(name);
    return m;
  }

  std::string_view statement = line;
  switch (statement.front()) {
    case '+':
      m.op = IniEntry::Op::Append;
      break;
    case '.':
      m.op = IniEntry::Op::AppendDuplicate;
      break;
    case '-':
      m.op = IniEntry::Op::Remove;
      break;
    case '!':
      m.op = IniEntry::Op::Clear;
      break;
    default:
      break;
  }
  if (m.op != IniEntry::Op::Set) statement.remove_prefix(1);

  const size_t equals = statement.find('=');
  if (equals == std::string_view::npos)
    return fail(LineMeaning::Kind::Error, fmt::format("expected 'Key=Value' or '[Section]', got '{}'", line));
  const std::string_view key = trim(statement.substr(0, equals));
  if (key.empty()) return fail(LineMeaning::Kind::Error, "empty key");
  m.kind = LineMeaning::Kind::Entry;
  m.key = std::string(key);

  // Whitespace after '=' belongs to the line's layout, not to the value; set() keeps it.
  std::string_view valueText = statement.substr(equals + 1);
  while (!valueText.empty() && isBlank(valueText.front())) valueText.remove_prefix(1);
  m.valueOffset = size_t(valueText.data() - raw.data());
  valueText = trim(valueText);
  if (!valueText.empty() && valueText.front() == '"') return readQuoted(valueText, std::move(m));
  m.value = std::string(valueText);
  return m;
}

}  // namespace

std::string IniDiagnostic::where() const { return line > 0 ? fmt::format("{}:{}", file, line) : file; }

IniDocument IniDocument::parse(std::string_view text, std::string path,
                               std::vector<IniDiagnostic>& diagnostics) {
  IniDocument doc;
  doc.path_ = std::move(path);

  // Lines are stored raw ('\r' and BOM included) so that text() gives back the input.
  size_t start = 0;
  while (start < text.size()) {
    const size_t newline = text.find('\n', start);
    if (newline == std::string_view::npos) {
      doc.lines_.emplace_back(text.substr(start));
      doc.trailingNewline_ = false;
      break;
    }
    doc.lines_.emplace_back(text.substr(start, newline - start));
    start = newline + 1;
  }

  std::optional<std::string> section;
  // Keys under a broken header would otherwise land in the previous section and
  // silently change settings nobody meant to touch, so they are dropped (the header's
  // diagnostic says so) while other errors there are still reported.
  bool underBrokenHeader = false;
  for (size_t i = 0; i < doc.lines_.size(); ++i) {
    const int lineNumber = int(i) + 1;
    LineMeaning m = interpret(doc.lines_[i], i == 0);
    switch (m.kind) {
      case LineMeaning::Kind::Blank:
      case LineMeaning::Kind::Comment:
        break;
      case LineMeaning::Kind::Section:
        section = std::move(m.section);
        underBrokenHeader = false;
        break;
      case LineMeaning::Kind::BadSection:
        section.reset();
        underBrokenHeader = true;
        diagnostics.push_back({doc.path_, lineNumber, std::move(m.error)});
        break;
      case LineMeaning::Kind::Error:
        diagnostics.push_back({doc.path_, lineNumber, std::move(m.error)});
        break;
      case LineMeaning::Kind::Entry:
        if (underBrokenHeader) break;
        if (!section) {
          diagnostics.push_back({doc.path_, lineNumber, "key outside of any [Section]"});
          break;
        }
        doc.entries_.push_back({m.op, *section, std::move(m.key), std::move(m.value), lineNumber});
        break;
    }
  }
  return doc;
}

std::optional<IniDocument> IniDocument::load(const std::string& path,
                                             std::vector<IniDiagnostic>& diagnostics) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) {
    diagnostics.push_back({path, 0, "file not found"});
    return std::nullopt;
  }
  if (fs::is_directory(status)) {
    diagnostics.push_back({path, 0, "is a folder, not an ini file"});
    return std::nullopt;
  }
  // Devices (/dev/zero never ends), FIFOs (block until a writer comes) and sockets are
  // not settings files: only a regular file has a size to check before reading.
  if (!fs::is_regular_file(status)) {
    diagnostics.push_back({path, 0, "is not a regular file (a device, pipe or socket); not read"});
    return std::nullopt;
  }
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) {
    diagnostics.push_back({path, 0, fmt::format("cannot read file: {}", ec.message())});
    return std::nullopt;
  }
  if (size > kMaxFileBytes) {
    diagnostics.push_back(
        {path, 0,
         fmt::format("is {} bytes; ini files larger than {} MiB are refused", size, kMaxFileBytes >> 20)});
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diagnostics.push_back({path, 0, fmt::format("cannot open file: {}", std::strerror(errno))});
    return std::nullopt;
  }
  // Read at most the cap even if the file grew since it was measured.
  std::string content(size_t(size), '\0');
  in.read(content.data(), std::streamsize(size));
  if (in.bad()) {
    diagnostics.push_back({path, 0, "cannot read file"});
    return std::nullopt;
  }
  content.resize(size_t(in.gcount()));
  return parse(content, path, diagnostics);
}

void IniDocument::set(std::string_view section, std::string_view key, std::string_view value) {
  const std::string written = quoteIfNeeded(value);

  // An existing plain assignment is rewritten in place: only the value text changes,
  // the indentation, key spelling, spacing around '=' and line ending stay.
  for (auto entry = entries_.rbegin(); entry != entries_.rend(); ++entry) {
    if (entry->op != IniEntry::Op::Set || !equalsIgnoreCase(entry->section, section) ||
        !equalsIgnoreCase(entry->key, key))
      continue;
    std::string& raw = lines_[size_t(entry->line - 1)];
    const LineMeaning m = interpret(raw, entry->line == 1);
    const bool carriageReturn = endsWithCarriageReturn(raw);
    raw = raw.substr(0, m.valueOffset) + written + (carriageReturn ? "\r" : "");
    entry->value = std::string(value);
    return;
  }

  const std::string lineEnd = !lines_.empty() && endsWithCarriageReturn(lines_.front()) ? "\r" : "";
  auto insertLine = [&](size_t index, std::string text) {
    // Appending after a last line that had no newline: give it the file's line ending.
    if (index == lines_.size() && !trailingNewline_ && !lines_.empty() && !lineEnd.empty() &&
        !endsWithCarriageReturn(lines_.back()))
      lines_.back() += lineEnd;
    if (index == lines_.size()) trailingNewline_ = true;
    lines_.insert(lines_.begin() + std::ptrdiff_t(index), text + lineEnd);
    for (IniEntry& e : entries_)
      if (e.line > int(index)) ++e.line;
  };
  auto addEntry = [&](size_t index) {
    insertLine(index, std::string(key) + "=" + written);
    IniEntry entry{IniEntry::Op::Set, std::string(section), std::string(key), std::string(value),
                   int(index) + 1};
    auto position = std::upper_bound(entries_.begin(), entries_.end(), entry.line,
                                     [](int line, const IniEntry& e) { return line < e.line; });
    entries_.insert(position, std::move(entry));
  };

  // The last header of the section wins (a section may appear more than once); the new
  // key goes after the block's last statement, before comments that lead into the next.
  std::optional<size_t> header;
  for (size_t i = 0; i < lines_.size(); ++i) {
    const LineMeaning m = interpret(lines_[i], i == 0);
    if (m.kind == LineMeaning::Kind::Section && equalsIgnoreCase(m.section, section)) header = i;
  }
  if (header) {
    size_t insertAt = *header + 1;
    for (size_t i = *header + 1; i < lines_.size(); ++i) {
      const LineMeaning::Kind kind = interpret(lines_[i], false).kind;
      if (kind == LineMeaning::Kind::Section || kind == LineMeaning::Kind::BadSection) break;
      if (kind != LineMeaning::Kind::Blank && kind != LineMeaning::Kind::Comment) insertAt = i + 1;
    }
    addEntry(insertAt);
    return;
  }

  if (!lines_.empty() && interpret(lines_.back(), lines_.size() == 1).kind != LineMeaning::Kind::Blank)
    insertLine(lines_.size(), "");
  insertLine(lines_.size(), "[" + std::string(section) + "]");
  addEntry(lines_.size());
}

std::string IniDocument::text() const {
  std::string out;
  for (size_t i = 0; i < lines_.size(); ++i) {
    out += lines_[i];
    if (i + 1 < lines_.size() || trailingNewline_) out += '\n';
  }
  return out;
}

bool IniDocument::save(const std::string& path, std::string* error) const {
  auto failWith = [&](std::string reason) {
    if (error) *error = std::move(reason);
    return false;
  };
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec)
      return failWith(
          fmt::format("cannot create folder '{}': {}", target.parent_path().string(), ec.message()));
  }

  // The temporary file sits beside the target so the rename stays on one file system
  // and is atomic: readers see the old file or the new one, never half of either.
  fs::path temp = target;
  temp += fmt::format(".{:08x}.tmp", std::random_device{}());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) return failWith(fmt::format("cannot write '{}': {}", temp.string(), std::strerror(errno)));
    const std::string content = text();
    out.write(content.data(), std::streamsize(content.size()));
    out.close();
    if (!out) {
      fs::remove(temp, ec);
      return failWith(fmt::format("cannot write '{}': {}", temp.string(), std::strerror(errno)));
    }
  }
  if (fs::exists(target, ec)) {
    // Keep the permissions someone gave the file; failure here is not worth refusing.
    const fs::perms perms = fs::status(target, ec).permissions();
    if (!ec) fs::permissions(temp, perms, ec);
  }
  fs::rename(temp, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    return failWith(fmt::format("cannot replace '{}': {}", path, ec.message()));
  }
  return true;
}

std::string IniDocument::quoteIfNeeded(std::string_view value) {
  const bool needsQuotes = value.empty() || isBlank(value.front()) || isBlank(value.back()) ||
                           value.find_first_of("\"\\") != std::string_view::npos;
  if (!needsQuotes) return std::string(value);
  std::string out = "\"";
  for (char c : value) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace bounce
