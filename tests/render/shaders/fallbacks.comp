#version 460
// Samples one of each fallback kind and writes what it read: the plugin-API tests check
// the values, and the validation layer that each binding's view type is the declared one.
layout(local_size_x = 1) in;
layout(binding = 0) uniform sampler2D white2D;
layout(binding = 1) uniform sampler2D black2D;
layout(binding = 2) uniform sampler2DArray black2DArray;
layout(binding = 3) uniform sampler3D black3D;
layout(binding = 4) uniform sampler3D white3D;
layout(binding = 5) uniform samplerCube blackCube;
layout(binding = 6) uniform sampler2DArrayShadow farDepth;
layout(binding = 7, std430) readonly buffer Zero { uint zero[]; };
layout(binding = 8, std430) writeonly buffer Result { float result[]; };

void main() {
  result[0] = texture(white2D, vec2(0.5)).r;
  result[1] = texture(black2D, vec2(0.5)).r;
  result[2] = texture(black2DArray, vec3(0.5, 0.5, 0.0)).r;
  result[3] = texture(black3D, vec3(0.5)).r;
  result[4] = texture(white3D, vec3(0.5)).r;
  result[5] = texture(blackCube, vec3(0.0, 0.0, 1.0)).r;
  result[6] = texture(farDepth, vec4(0.5, 0.5, 0.0, 0.5));  // 0.5 <= 1: lit
  result[7] = float(zero[0] + zero[16383]);
}
