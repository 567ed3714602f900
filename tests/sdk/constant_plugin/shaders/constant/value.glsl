#ifndef SDK_CONSTANT_VALUE_GLSL
#define SDK_CONSTANT_VALUE_GLSL
// Found beside the including file; its own include comes from the engine's GLSL library.
#include "bounce/common.glsl"

vec4 constantIrradiance(vec4 value) { return vec4(sanitize(value.rgb, HALF_MAX), 1.0); }

#endif
