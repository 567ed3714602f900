#pragma once
// RAII wrapper around dlopen/dlclose.

#include <filesystem>
#include <memory>
#include <string>

namespace bounce {

class SharedLibrary {
 public:
  /// Opens a library (RTLD_NOW: unresolved symbols fail here, not mid-frame).
  static std::unique_ptr<SharedLibrary> open(const std::filesystem::path& path, std::string* error);
  ~SharedLibrary();
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  void* symbol(const char* name) const;

  /// Takes ownership of a dlopen handle; use open().
  explicit SharedLibrary(void* handle) : handle_(handle) {}

 private:
  void* handle_;
};

}  // namespace bounce
