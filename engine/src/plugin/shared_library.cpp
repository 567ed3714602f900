#include "plugin/shared_library.h"

#include <dlfcn.h>

namespace bounce {

std::unique_ptr<SharedLibrary> SharedLibrary::open(const std::filesystem::path& path, std::string* error) {
  // RTLD_LOCAL keeps plugins' symbols apart; they resolve the engine's through their
  // own link to libbounce_engine.so, which is already loaded. RTLD_NODELETE keeps the
  // code mapped after dlclose: plugins link libraries with worker threads (TBB, Embree)
  // that outlive the plugin object, and unmapping their code under them crashes.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (!handle) {
    if (error) {
      const char* e = dlerror();
      *error = e ? e : "dlopen failed";
    }
    return nullptr;
  }
  return std::make_unique<SharedLibrary>(handle);
}

SharedLibrary::~SharedLibrary() { dlclose(handle_); }

void* SharedLibrary::symbol(const char* name) const {
  dlerror();
  return dlsym(handle_, name);
}

}  // namespace bounce
