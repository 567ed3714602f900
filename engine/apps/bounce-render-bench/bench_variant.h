#pragma once
// A benchmark variant: a labelled set of console-variable values measured as one column
// of bounce-render-bench's table, then restored, so several settings are compared in one
// run ("static: " against "dynamic: r.MyGI.ForceFullUpdate=1").

#include "bounce/config/cvar_registry.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace bounce {

struct BenchVariant {
  std::string label;
  std::vector<std::pair<std::string, std::string>> sets;  ///< cvar name, value text
  /// "r.X=1 r.Y=2", or "current settings" when it sets nothing.
  std::string describe() const;
};

/// Parses "LABEL: NAME=VALUE NAME=VALUE" (words split as console lines are, so a value
/// with spaces is quoted); nullopt and a one-line error when malformed.
std::optional<BenchVariant> parseBenchVariant(const std::string& text, std::string* error);

/// The values a variant replaced, to put back.
class AppliedVariant {
 public:
  void restore(CVarRegistry& cvars) const;

 private:
  friend std::optional<AppliedVariant> applyBenchVariant(CVarRegistry&, const BenchVariant&, std::string*);
  std::vector<std::pair<std::string, std::string>> previous_;
};

/// Writes the variant's values at console priority; on an unknown name or a refused value
/// restores what it wrote and returns nullopt with the reason.
std::optional<AppliedVariant> applyBenchVariant(CVarRegistry& cvars, const BenchVariant& variant,
                                                std::string* error);

/// "NAME.L*" for a pass named "NAME.L<digits>", else nullopt.
std::optional<std::string> levelGroup(const std::string& pass);

}  // namespace bounce
