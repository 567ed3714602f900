#version 460
// DDGI.Reset: zeroes the probe atlases and probe data, so an update takes its values whole
// (a black texel has no history) and every probe starts active at its rest position.
// Without DDGI_SCROLL_CLEAR: everything, when the textures are new. With it: only the
// probes a camera-following volume's scroll just brought in (their texels held probes
// that left on the other side); one workgroup of T×T per probe, T the larger map.
#if DDGI_SCROLL_CLEAR
#define DDGI_VOLUME_BINDING 3
#include "ddgi/volume.glsl"
layout(local_size_x = DDGI_TEXELS, local_size_y = DDGI_TEXELS) in;
layout(push_constant) uniform Push {
  ivec4 moved;  // xyz: this frame's scroll, in probes
};
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif
layout(binding = 0, DDGI_IRRADIANCE_FORMAT) uniform writeonly image2DArray irradianceAtlas;
layout(binding = 1, DDGI_DISTANCE_FORMAT) uniform writeonly image2DArray distanceAtlas;
layout(binding = 2, rgba16f) uniform writeonly image2DArray probeData;

void main() {
#if DDGI_SCROLL_CLEAR
  ivec3 c = ddgiProbeCoords(gl_WorkGroupID.x);
  // New: within |moved| planes of the side the grid moved towards.
  bvec3 entered = bvec3(moved.x > 0 ? c.x >= ddgiCounts.x - moved.x : c.x < -moved.x,
                        moved.y > 0 ? c.y >= ddgiCounts.y - moved.y : c.y < -moved.y,
                        moved.z > 0 ? c.z >= ddgiCounts.z - moved.z : c.z < -moved.z);
  if (!any(entered)) return;  // uniform per workgroup: one probe
  ivec2 t = ivec2(gl_LocalInvocationID.xy);
  if (all(lessThan(t, ivec2(ddgiTexels.x)))) imageStore(irradianceAtlas, ddgiProbeBlock(c, ddgiTexels.x) + ivec3(t, 0), vec4(0.0));
  if (all(lessThan(t, ivec2(ddgiTexels.y)))) imageStore(distanceAtlas, ddgiProbeBlock(c, ddgiTexels.y) + ivec3(t, 0), vec4(0.0));
  if (t == ivec2(0)) imageStore(probeData, ddgiProbeDataTexel(c), vec4(0.0));
#else
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (all(lessThan(p, imageSize(irradianceAtlas)))) imageStore(irradianceAtlas, p, vec4(0.0));
  if (all(lessThan(p, imageSize(distanceAtlas)))) imageStore(distanceAtlas, p, vec4(0.0));
  if (all(lessThan(p, imageSize(probeData)))) imageStore(probeData, p, vec4(0.0));
#endif
}
