#include "gpu/library_pin.h"

#include <dlfcn.h>
#include <link.h>

#if defined(__SANITIZE_ADDRESS__)
#define BOUNCE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BOUNCE_ASAN 1
#endif
#endif

namespace bounce::gpu {

void keepLoadedLibrariesForLeakChecks() {
#ifdef BOUNCE_ASAN
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void*) {
        // RTLD_NOLOAD: only libraries already loaded; the handle's reference is kept for good.
        if (info->dlpi_name && info->dlpi_name[0])
          (void)dlopen(info->dlpi_name, RTLD_NOLOAD | RTLD_NOW | RTLD_NODELETE);
        return 0;
      },
      nullptr);
#endif
}

}  // namespace bounce::gpu
