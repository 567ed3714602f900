#pragma once
// tinyexr reports failures as strdup'ed strings the caller must release with
// FreeEXRErrorMessage; owning one here frees it on every return path.

#include <tinyexr.h>

#include <string>
#include <string_view>

namespace bounce::image {

class ExrErrorText {
 public:
  ExrErrorText() = default;
  ~ExrErrorText() {
    if (text_) FreeEXRErrorMessage(text_);
  }
  ExrErrorText(const ExrErrorText&) = delete;
  ExrErrorText& operator=(const ExrErrorText&) = delete;

  /// For tinyexr's `const char** err` parameter; pass it to one call only.
  const char** receive() { return &text_; }
  /// tinyexr's message, or `fallback` where it gave none (some paths return only a code).
  std::string reason(std::string_view fallback) const {
    return text_ && *text_ ? std::string(text_) : std::string(fallback);
  }

 private:
  const char* text_ = nullptr;
};

}  // namespace bounce::image
