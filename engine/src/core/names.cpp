#include "bounce/core/names.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <numeric>
#include <string>

namespace bounce {
namespace {
char lower(char c) { return char(std::tolower(static_cast<unsigned char>(c))); }
}  // namespace

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return lower(x) == lower(y); });
}

bool startsWithIgnoreCase(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() && equalsIgnoreCase(text.substr(0, prefix.size()), prefix);
}

std::string toLower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = lower(c);
  return out;
}

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), size_t(0));
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t above = row[j];
      size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> closestNames(std::string_view name, std::span<const std::string> candidates,
                                      size_t maxCount) {
  struct Scored {
    size_t score;
    const std::string* name;
  };
  std::vector<Scored> scored;
  // Nobody mistypes a name this long: it is data, not a typo, and comparing it would
  // cost its length times every candidate's.
  if (name.size() > kMaxSuggestedNameLength) return {};
  // A typo is plausible within about a third of the name's length (at least 2 edits);
  // candidates that start with what was typed are always offered first.
  const size_t limit = std::max<size_t>(2, name.size() / 3);
  for (const std::string& c : candidates) {
    if (equalsIgnoreCase(c, name)) continue;
    if (!name.empty() && startsWithIgnoreCase(c, name)) {
      scored.push_back({0, &c});
      continue;
    }
    // The edit distance is at least the difference in length: skip the quadratic work.
    const size_t lengthGap = c.size() > name.size() ? c.size() - name.size() : name.size() - c.size();
    if (lengthGap > limit) continue;
    size_t d = editDistance(name, c);
    if (d <= limit) scored.push_back({d, &c});
  }
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) {
    return a.score != b.score ? a.score < b.score : *a.name < *b.name;
  });
  std::vector<std::string> out;
  for (const Scored& s : scored) {
    if (out.size() == maxCount) break;
    if (std::find(out.begin(), out.end(), *s.name) == out.end()) out.push_back(*s.name);
  }
  return out;
}

std::string didYouMean(std::string_view name, std::span<const std::string> candidates) {
  std::vector<std::string> close = closestNames(name, candidates);
  if (close.empty()) return {};
  std::string out = " (did you mean ";
  for (size_t i = 0; i < close.size(); ++i) out += (i ? ", '" : "'") + close[i] + "'";
  return out + "?)";
}

}  // namespace bounce

namespace bounce {

namespace {

/// Length of the valid UTF-8 sequence starting at `s[i]` (2–4), or 0 when it is not one.
/// Overlong forms, surrogates and code points above U+10FFFF are invalid (RFC 3629).
size_t utf8SequenceLength(std::string_view s, size_t i, uint32_t* codePoint) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  size_t length = 0;
  uint32_t cp = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    cp = lead & 0x1Fu;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    cp = lead & 0x0Fu;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    cp = lead & 0x07u;
  } else {
    return 0;
  }
  if (i + length > s.size()) return 0;
  for (size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0u) != 0x80u) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3Fu);
  }
  if ((length == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) ||
      (length == 4 && (cp < 0x10000 || cp > 0x10FFFF)))
    return 0;
  *codePoint = cp;
  return length;
}

void appendHex(std::string& out, unsigned char byte) {
  constexpr char kDigits[] = "0123456789ABCDEF";
  out += "\\x";
  out += kDigits[byte >> 4];
  out += kDigits[byte & 0xF];
}

}  // namespace

std::string printable(std::string_view text, bool multiLine) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += char(c);
      ++i;
    } else if (c == '\n') {
      out += multiLine ? "\n" : "\\n";
      ++i;
    } else if (c == '\t') {
      out += multiLine ? "\t" : "\\t";
      ++i;
    } else if (c == '\r') {
      out += "\\r";
      ++i;
    } else if (c < 0x80) {
      appendHex(out, c);  // other C0 controls (ESC, NUL, BEL...) and DEL
      ++i;
    } else {
      uint32_t cp = 0;
      const size_t length = utf8SequenceLength(text, i, &cp);
      if (length == 0) {
        appendHex(out, c);  // not UTF-8: a lone 0x9B is CSI to an 8-bit terminal
        ++i;
      } else if (cp >= 0x80 && cp <= 0x9F) {
        for (size_t k = 0; k < length; ++k) appendHex(out, static_cast<unsigned char>(text[i + k]));
        i += length;
      } else {
        out.append(text.substr(i, length));
        i += length;
      }
    }
  }
  return out;
}

std::string abbreviated(std::string_view text, size_t maxLength) {
  if (text.size() <= maxLength) return printable(text);
  // Cut at a UTF-8 character boundary so the kept part stays valid text.
  size_t cut = maxLength;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0u) == 0x80u) --cut;
  return printable(text.substr(0, cut)) + "… (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace bounce
