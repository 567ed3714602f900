#pragma once
// How a console variable's range reads in messages ("[1, 32]", "[0, ...]"), shared by
// the value checks (cvar.cpp) and the registry's check of declared defaults.

#include "bounce/config/cvar.h"

#include <string>

namespace bounce {

std::string rangeText(const CVar& c);

}  // namespace bounce
