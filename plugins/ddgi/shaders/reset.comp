#version 460
// DDGI.Reset: zeroes the probe atlases and probe data when they are (re)created, so the
// first update takes its values whole (a black texel has no history) and every probe
// starts active at its rest position.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, DDGI_IRRADIANCE_FORMAT) uniform writeonly image2DArray irradianceAtlas;
layout(binding = 1, DDGI_DISTANCE_FORMAT) uniform writeonly image2DArray distanceAtlas;
layout(binding = 2, rgba16f) uniform writeonly image2DArray probeData;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (all(lessThan(p, imageSize(irradianceAtlas)))) imageStore(irradianceAtlas, p, vec4(0.0));
  if (all(lessThan(p, imageSize(distanceAtlas)))) imageStore(distanceAtlas, p, vec4(0.0));
  if (all(lessThan(p, imageSize(probeData)))) imageStore(probeData, p, vec4(0.0));
}
