#pragma once
#include <cstdint>

namespace bounce {

/// Who registered something (a console variable, a flag, a pass hook...). The engine
/// registers as `kEngineOwner`; every plugin gets its own id, so unloading a plugin
/// removes exactly what it registered.
using OwnerId = uint32_t;
inline constexpr OwnerId kEngineOwner = 0;

}  // namespace bounce
