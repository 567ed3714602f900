#version 460
// Debug modes 1, 4 and 5: one GI channel alone (indirect diffuse irradiance, indirect
// specular radiance, ambient occlusion), exposed, Reinhard tone-mapped and sRGB-encoded.
#include "bounce/common.glsl"
#include "bounce/color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant) uniform Push {
  ivec4 params;  // x, y: view size; z: 1 = grey from the red channel (AO)
  vec4 display;  // x: exposure (multiplier)
} pc;
layout(binding = 0) uniform sampler2D channel;
layout(binding = 1, rgba8) uniform writeonly image2D outView;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, pc.params.xy))) return;
  vec4 v = texelFetch(channel, pixel, 0);
  vec3 c = pc.params.z == 1 ? vec3(saturate(v.r)) : sanitize(v.rgb * pc.display.x, HALF_MAX);
  if (pc.params.z != 1) c = c / (1.0 + c);
  imageStore(outView, pixel, vec4(linearToSrgb(c), 1.0));
}
