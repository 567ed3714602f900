#pragma once

namespace bounce::gpu {

/// In AddressSanitizer builds, marks every shared library loaded so far as never to be
/// unloaded (RTLD_NODELETE); does nothing otherwise. Called once the Vulkan device exists,
/// so the driver (lavapipe's libvulkan_lvp.so) and the layers are among them. When the
/// loader unloads the driver at exit, memory that only the driver's globals pointed at
/// looks leaked (LeakSanitizer reported 112 bytes in 2 blocks, with or without the
/// validation layer) and its frames have no module name, so no suppression could name
/// them exactly. Kept loaded, that memory stays reachable and real leaks keep their names.
void keepLoadedLibrariesForLeakChecks();

}  // namespace bounce::gpu
