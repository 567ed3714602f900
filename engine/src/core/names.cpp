#include "bounce/core/names.h"

#include <algorithm>
#include <cctype>
#include <numeric>

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
