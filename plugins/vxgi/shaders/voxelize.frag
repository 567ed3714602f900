#version 460
// Voxelization, step 3: each fragment is a voxel column the triangle touches. It adds
// the surface's projected coverage, and (unless in ambient-occlusion mode) the radiance
// it sends out × that coverage, to every voxel of the column the surface passes
// through, per facing direction, with float atomics into the scratch volume. The
// resolve pass turns the sums into opacity and premultiplied emittance.
#extension GL_EXT_shader_atomic_float : require
// VXGI_MULTI_BOUNCE (set by the plugin while r.VXGI.Bounces > 1, never in ambient-occlusion
// mode): each surface also sends out the indirect light the clip-map as it stands gathers
// at it; the bounce passes (vxgi/bounce_requests.glsl) trace the cones and add that light.
#ifndef VXGI_MULTI_BOUNCE
#define VXGI_MULTI_BOUNCE 0
#endif
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "bounce/scene.glsl"
#include "bounce/lights.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"
#define WORK_COUNTERS_BINDING 40
#include "bounce/work_counters.glsl"  // before shadows.glsl: its taps count themselves

// bounce: x cones of the multi-bounce gather (0: none this voxelization); y..w (their step
// factor, range and normal offset) are the bounce passes'.
SCENE_DRAW_PUSH_CONSTANTS(ivec4 regionMin; ivec4 regionMax; ivec4 innerMin; ivec4 innerMax; ivec4 scratchLayout;
                          vec4 ambient; vec4 bounce;)

SCENE_MATERIALS(27)
LIGHTS(24)
SHADOW_MATRICES(25)
#include "bounce/shadows.glsl"
layout(binding = 26) uniform sampler2DArrayShadow shadowMaps;
layout(binding = 28) uniform sampler2D baseColorTexture;
layout(binding = 29) uniform sampler2D emissiveTexture;

layout(binding = 21, r32f) uniform coherent image3D scratch;
// Bricks that received sums this frame (vxgi/scratch.glsl): the resolve skips the others.
layout(std430, binding = 60) buffer VxgiBrickOccupancy { uint brickOccupancy[]; };
#include "vxgi/voxel_column.glsl"
#if VXGI_MULTI_BOUNCE
#include "vxgi/bounce_requests.glsl"
// The gathers this level's fragments list: x the workgroups of the passes that take one
// request a lane, w the requests made (more than fit when the list overflowed).
layout(std430, binding = 61) buffer VxgiBounceRequests {
  uvec4 bounceHeader;
  VxgiBounceRequest bounceRequests[];
};
#endif
// Per material: x thickness (voxels), y proportional emittance, z omni-directional.
layout(std430, binding = 22) readonly buffer VxgiMaterialParams { vec4 materialParams[]; };
// Per light: 1 when it is flagged "VXGI indirect lighting".
layout(std430, binding = 23) readonly buffer VxgiLightFlags { uint lightFlags[]; };

layout(location = 0) in vec3 gWorld;
layout(location = 1) in vec2 gUv;
layout(location = 2) flat in vec3 gNormal;
layout(location = 3) flat in int gAxis;
layout(location = 4) flat in vec4 gPixelBox;
layout(location = 5) flat in vec4 gTriangle01;
layout(location = 6) flat in vec2 gTriangle2;

layout(location = 0) out vec4 unusedColor;

// The area of the triangle (pixel units) inside the unit pixel whose lower corner is
// `pixel`. This is coverage supersampling taken to the limit: the pieces of a mesh's
// triangles in one pixel add up to the area they cover, so a surface smaller than a voxel
// blocks and emits in proportion to its size, while the dilated rasterization still
// guarantees it a fragment.
//
// Computed edge by edge, as font rasterizers accumulate coverage: the winding number of
// a point is the signed count of edges crossing the ray to its right, so the area inside
// the pixel S = [0,1]² is Σ_edges ∫ clamp(x_e(y), 0, 1) dy over the edge's y-range
// clipped to [0, 1] (oriented, so edges going down subtract). Each term is closed-form.
// No polygon clipping: its dynamically indexed vertex arrays live in memory on a CPU
// device (lavapipe), one gather per lane per access, and cost more than the rest of the
// fragment shader.
float edgeCoverage(vec2 a, vec2 b) {
  float dy = b.y - a.y;
  // A horizontal edge crosses no horizontal line; 1e-12 px² is far below any coverage
  // that matters and keeps the divisions below finite.
  if (abs(dy) < 1e-12) return 0.0;
  float y0 = clamp(a.y, 0.0, 1.0), y1 = clamp(b.y, 0.0, 1.0);
  float x0 = mix(a.x, b.x, clamp((y0 - a.y) / dy, 0.0, 1.0));
  float x1 = mix(a.x, b.x, clamp((y1 - a.y) / dy, 0.0, 1.0));
  // Mean of clamp(x, 0, 1) along the clipped piece: (F(x1) − F(x0)) / (x1 − x0) with F
  // the antiderivative c²/2 + max(x − 1, 0), c = clamp(x, 0, 1). Below 1e-3 px of x
  // change the difference quotient loses its digits (x reaches ±map size) and the
  // midpoint is within 1e-3 of it.
  float dx = x1 - x0;
  float c0 = clamp(x0, 0.0, 1.0), c1 = clamp(x1, 0.0, 1.0);
  float F0 = 0.5 * c0 * c0 + max(x0 - 1.0, 0.0), F1 = 0.5 * c1 * c1 + max(x1 - 1.0, 0.0);
  float mean = abs(dx) > 1e-3 ? (F1 - F0) / dx : clamp(0.5 * (x0 + x1), 0.0, 1.0);
  return mean * (y1 - y0);
}

float pixelCoverage(vec2 pixel, vec2 p0, vec2 p1, vec2 p2) {
  vec2 a = p0 - pixel, b = p1 - pixel, c = p2 - pixel;
  float area = edgeCoverage(a, b) + edgeCoverage(b, c) + edgeCoverage(c, a);
  return clamp(abs(area), 0.0, 1.0);
}

bool inBox(ivec3 c, ivec4 lo, ivec4 hi) { return all(greaterThanEqual(c, lo.xyz)) && all(lessThan(c, hi.xyz)); }

// Diffuse radiance the two sides of a surface with normal n send out (`back` only when
// double-sided, else 0): emission plus the flagged lights' light each side reflects (with
// their shadow maps) plus the optional constant ambient (the seed's remedy for
// single-bounce specular). One loop serves both sides, since a light reaches at most one
// of them: on a CPU device a second call for the back side runs in full whether or not it
// is needed (both sides of a branch run under a mask), and lighting was 40% of the pass.
// halfA, halfB: the half-extents of this fragment's piece of surface (a voxel column's),
// over which the shadow maps are averaged.
void outgoingRadiance(vec3 n, bool doubleSided, vec3 albedo, vec3 emission, vec3 halfA, vec3 halfB, out vec3 front,
                      out vec3 back) {
  vec3 reflectedFront = albedo * draw.ambient.rgb;
  vec3 reflectedBack = doubleSided ? reflectedFront : vec3(0.0);
  uint lightCount = uint(draw.ambient.w);
  for (uint i = 0u; i < lightCount; ++i) {
    if (lightFlags[i] == 0u) continue;
    Light light = lights[i];
    vec3 L, E;
    float dist;
    lightIncidence(light, gWorld, L, E, dist);
    float cosine = dot(n, L);
    bool lit = cosine > 0.0 || (doubleSided && cosine < 0.0);
    if (!lit || all(equal(E, vec3(0.0)))) continue;
    vec3 N = cosine > 0.0 ? n : -n;  // the side the light reaches
    vec3 reflected = albedo * E * abs(cosine) * shadowFactorOverPatch(light, gWorld, N, L, halfA, halfB, shadowMaps);
    if (cosine > 0.0)
      reflectedFront += reflected;
    else
      reflectedBack += reflected;
  }
  front = emission + reflectedFront * INV_PI;
  back = doubleSided ? emission + reflectedBack * INV_PI : vec3(0.0);
}

void main() {
  unusedColor = vec4(0.0);
  // The pixel in this axis's N×N region of the target (voxelize.geom). A dilated triangle
  // reaching past its region's side lands in the next region: that is outside the level.
  vec2 pixel = gl_FragCoord.xy - vec2(float(gAxis * clipMap.mapSize), 0.0);
  if (pixel.x < 0.0 || pixel.x > float(clipMap.mapSize)) discard;
  if (any(lessThan(pixel, gPixelBox.xy)) || any(greaterThan(pixel, gPixelBox.zw))) discard;
  int level = draw.regionMin.w;
  float v = vxgiVoxelSize(level);
  vec3 u = gWorld / v;
  ivec3 c = ivec3(floor(u));
  // The voxels along the projection axis that this pixel's piece of the surface passes
  // through: its depth ± half the depth change across the pixel, extended behind the
  // surface by the material's thickness (in voxels; 1 = the surface alone). On the plane,
  // depth changes by |n_a| / |n_axis| voxels per pixel along in-plane axis a, so half a
  // pixel each way spans (|n_a| + |n_b|) / (2 |n_axis|), at most 1 (n_axis is the largest
  // component). It comes from the flat normal, not dFdx/dFdy: after the discard above the
  // derivatives are undefined wherever a quad neighbour was discarded, and on lavapipe
  // some read up to the old 2-voxel clamp on flat faces of constant depth (measured).
  // A 10 cm wall's sunlit outer face so put 7% of its density and emittance into the two
  // voxels in front of its inner face, where the room's cones read it (issue 16).
  float depth = u[gAxis];
  // gNormal is unit (the geometry shader drops degenerate triangles), so its dominant
  // component is at least 1/√3: the 1e-6 never binds, and the min is only the bound above.
  vec3 an = abs(gNormal);
  float span = min(0.5 * (an.x + an.y + an.z - an[gAxis]) / max(an[gAxis], 1e-6), 1.0);
  vec4 params = materialParams[draw.material];
  float behind = max(params.x - 1.0, 0.0) * -sign(gNormal[gAxis]);
  float first = floor(min(depth - span, depth - span + behind)), last = floor(max(depth + span, depth + span + behind));

  Material m = materials[draw.material];
  vec3 albedo = m.baseColor.rgb * texture(baseColorTexture, gUv).rgb * (1.0 - saturate(m.metallic));
  vec3 emission = m.emission.rgb * texture(emissiveTexture, gUv).rgb;
  bool doubleSided = (m.textures1.w & 1) != 0;
  vec3 n = gNormal;
  vec3 a = abs(n);
  float dominant = max(a[gAxis], 1e-6);
  // Projected coverage of this piece along each axis, relative to one voxel face: the
  // part of the pixel it covers, seen along the dominant axis, and tilted to the others.
  float covered = pixelCoverage(floor(pixel), gTriangle01.xy, gTriangle01.zw, gTriangle2);
  if (!(covered > 0.0)) discard;  // the dilation's extra reach: the triangle misses this column
  vec3 coverage = covered * a / dominant;
  bool proportional = params.y > 0.5, omni = params.z > 0.5;

#if !VXGI_AO_MODE
  vec3 front, back;
  // The voxel face this fragment covers, carried onto the surface's plane: half a voxel
  // along each of the projection plane's axes, and the depth change that goes with it
  // (|n_axis| ≥ 1/√3, so the division is safe). The emittance of a voxel that a shadow
  // edge crosses is then its lit fraction, not whether its centre is lit.
  int axisA = (gAxis + 1) % 3, axisB = (gAxis + 2) % 3;
  vec3 halfA = vec3(0.0), halfB = vec3(0.0);
  halfA[axisA] = 0.5 * v;
  halfA[gAxis] = -0.5 * v * n[axisA] / n[gAxis];
  halfB[axisB] = 0.5 * v;
  halfB[gAxis] = -0.5 * v * n[axisB] / n[gAxis];
  outgoingRadiance(n, doubleSided, albedo, emission, halfA, halfB, front, back);
#endif
  // Integer bounds: a float counter stops advancing at large magnitudes, and a corner
  // extrapolated far out for a sliver triangle could make the span huge.
  if (!(abs(depth) < 1e6)) discard;
  int k0 = int(first), k1 = min(int(last), k0 + 8);
  // The column's voxels this level writes: inside the plan's box, outside the inner box (a
  // coarser level's inner box is the finer level's downsampled).
  VxgiVoxelColumn column;
  column.first = c;
  column.first[gAxis] = k0;
  column.axis = gAxis;
  column.mask = 0u;
  for (int k = k0; k <= k1; ++k) {
    ivec3 voxel = c;
    voxel[gAxis] = k;
    if (inBox(voxel, draw.regionMin, draw.regionMax) && !inBox(voxel, draw.innerMin, draw.innerMax))
      column.mask |= 1u << uint(k - k0);
  }
  if (column.mask == 0u) discard;
  VxgiSurfacePiece piece;
  piece.normal = n;
  piece.coverage = coverage;
  piece.doubleSided = doubleSided;
  piece.proportional = proportional;
  piece.omni = omni;
#if VXGI_MULTI_BOUNCE
  // Multi-bounce: the surface also reflects the indirect light that reaches it, gathered by
  // diffuse cones from the clip-map as the last voxelization left it (which held the
  // bounces before, so each voxelization adds one; the plugin re-voxelizes until
  // r.VXGI.Bounces are in). The bounce passes (vxgi/bounce_requests.glsl) trace the cones and
  // add the light to this column's sums after the draw: a CPU device runs a fragment shader
  // on the threads of the target's 64×64 tiles, as many as the target has. Traced here, the
  // cones cost 56 ns a texture sample; there 12 (lavapipe, 2 cores; VXGI README). A request
  // that does not fit in the list is dropped and counted: the plugin voxelizes again with a
  // longer one (tracing it here instead costs every fragment the untaken branch, since a
  // CPU device runs both sides of a branch under a mask: 11 → 28 ms a voxelization).
  if (draw.bounce.x > 0.0 && any(greaterThan(albedo, vec3(0.0)))) {
    uint slot = atomicAdd(bounceHeader.w, 1u);
    if (slot < uint(bounceRequests.length())) {
      bounceRequests[slot] = vxgiPackBounceRequest(gWorld, albedo, column, piece);
      if (slot % VXGI_BOUNCE_GROUP == 0u) atomicAdd(bounceHeader.x, 1u);
      countWork(WORK_BUFFER_BYTES, 64u + 8u);  // the request, and the count's atomic
    }
  }
#endif
#if !VXGI_AO_MODE
  front = sanitize(front, HALF_MAX);
  back = sanitize(back, HALF_MAX);
#else
  vec3 front = vec3(0.0), back = vec3(0.0);
#endif
  // countWork expands to nothing in frames that do not count: the call stays outside it.
  uint atomics = vxgiAddColumnSums(column, piece, front, back, draw.scratchLayout);
  countWork(WORK_IMAGE_BYTES, 8u * atomics);  // float atomic adds: 4 bytes read, 4 written
}
