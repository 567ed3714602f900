// TraceCone: the cone-tracing primitive other shaders may call (seed 001, slide 26).
//
//   #include "vxgi/trace_cone.glsl"
//   ConeTracingArguments args = DefaultConeTracingArguments();
//   args.direction = R;  args.coneFactor = 0.2;  args.firstSamplePosition = P + N * 0.05;
//   args.surfaceNormal = N;  args.surfaceDistance = 0.05;  // optional: keeps the filter off P's surface
//   ConeTracingResults cone = TraceCone(args);
//   // cone.irradiance, cone.ambient, cone.finalOpacity
//
// The cone marches front to back through the clip-map, one sample per step whose
// footprint matches the cone's diameter there. Each step's opacity comes from the
// density it crosses (α_i = 1 − exp(−τ_i)) and its radiance L_i is the density-weighted
// mean radiance there (emittance / density); they composite under the opacity
// accumulated so far:
//   radiance += (1 − opacity) · α_i · L_i ;  opacity += (1 − opacity) · α_i
#ifndef VXGI_TRACE_CONE_GLSL
#define VXGI_TRACE_CONE_GLSL

#include "clip_map.glsl"

struct ConeTracingArguments {
  vec3 direction;            // unit direction the cone marches along
  float coneFactor;          // cone diameter per metre of distance: 2·tan(half-angle)
  vec3 firstSamplePosition;  // where marching starts (already offset from the surface): the
                             // cone's apex, behind which no sample reads (clip_map.glsl)
  float firstSampleDistance; // distance the first sample is taken at, in finest voxels
  float maxDistance;         // metres; the cone stops there
  float stepFactor;          // step length as a fraction of the footprint (≤ 1)
  float ambientRange;        // metres: occlusion beyond this does not count for `ambient`
  vec3 surfaceNormal;        // unit normal of the surface the cone leaves (zero: none)
  float surfaceDistance;     // height of firstSamplePosition above that surface, metres
};

struct ConeTracingResults {
  // π × the radiance the cone gathered: the irradiance a surface facing the cone would
  // receive if its whole hemisphere looked like this cone. Diffuse tracing averages
  // it over cones of equal projected solid angle.
  vec3 irradiance;
  float ambient;       // 1 − occlusion within ambientRange (1: unoccluded)
  float finalOpacity;  // opacity accumulated along the whole cone
};

ConeTracingArguments DefaultConeTracingArguments() {
  ConeTracingArguments a;
  a.direction = vec3(0.0, 0.0, 1.0);
  a.coneFactor = 1.0;
  a.firstSamplePosition = vec3(0.0);
  a.firstSampleDistance = 1.0;
  a.maxDistance = 1e30;
  a.stepFactor = 0.5;
  a.ambientRange = 1e30;
  a.surfaceNormal = vec3(0.0);
  a.surfaceDistance = 0.0;
  return a;
}

// Opacity at which a cone has ended on a surface: it stops, and what it gathered is
// renormalised to the whole cone (below). One opaque voxel is α = 0.99 (clip_map.glsl,
// VXGI_OPAQUE_VOXEL_ALPHA), and a wall filtered over two texels, or covering part of a
// footprint, gives a cone crossing it less; with this at 0.99 such cones marched on through
// the wall into what lies behind it (in a closed white furnace nothing: one bounce 1.6% low,
// three 3.8%). Lower values brighten partial occluders (the Cornell box's error against the
// path tracer grows again below 0.8). 0.8 is the highest at which no furnace figure falls
// below α = 0.999's, and it still reads every scene measured closer: the scan of this
// threshold is in the vxgi README (stop 41).
const float VXGI_OPAQUE = 0.8;
// Bounds the loop on any input (a NaN distance, a zero cone factor): 512 samples reach
// 2^9 footprints even with step factor 0.1, past the coarsest mip of any clip-map.
const int VXGI_MAX_STEPS = 512;
// How far (in footprints, along the surface normal) a sample must be from the surface a
// cone leaves before its filter may reach it. A trilinear sample of voxels of edge V
// weighs voxel centres up to V away along each axis, i.e. up to V·|n|₁ along the normal
// n; the voxels the surface passes through have centres up to V·|n|₁/2 above it. So the
// footprint at height h may be at most h / (1.5·|n|₁). Without this, the filter of a
// wide cone (its footprint is as wide as it is far) reaches behind the surface, and
// there a closed mesh's back faces (a 5 cm wall's far side shares its coarse voxels)
// stop the cone at once: walls of the Cornell box read 4–15% of a path tracer's one
// bounce. Limiting only the footprint of the finer of the two blended levels (a strict
// bound for both would be 3) keeps footprints wide, which tiny bright sources need.
const float VXGI_SURFACE_CLEARANCE = 1.5;
// Edge of the voxels a sample reads, per metre of cone diameter. A trilinear sample of
// voxels of edge V spreads what it reads over a tent of half-width V (variance V²/6 per
// axis) and each voxel's content over the voxel (V²/12): variance V²/4. vxgiChooseLevels blends
// the level of voxel V = d·2^−f with the next, 2V, by f = fract(log2(d / v0)): variance
// d²·2^−2f·(1 + 3f)/4, whose mean over f (a cone widens through every f) is 0.293 d². The
// cone's cross-section, a disk of diameter D, has variance D²/16 along each axis in its
// plane; equal when d = D / (4·√0.293) = 0.46 D. With d = D (what this was) every sample
// spread over twice the cone's width, into the dark back faces and neighbouring surfaces
// around it: the Cornell box's one bounce read 0.77 of the path tracer, 0.95 with 0.46
// (0.91 with 0.5, 1.09 with 0.35, 1.20 with 0.25: narrower filters over-light).
const float VXGI_VOXELS_PER_DIAMETER = 0.46;

ConeTracingResults TraceCone(ConeTracingArguments args) {
  ConeTracingResults res;
  res.irradiance = vec3(0.0);
  res.ambient = 1.0;
  res.finalOpacity = 0.0;
  vec3 r = safeNormalize(args.direction, vec3(0.0, 0.0, 1.0));
  float coneFactor = max(args.coneFactor, 1e-3);
  float stepFactor = clamp(args.stepFactor, 0.05, 1.0);
  float v0 = clipMap.voxelSize0;
  float t = max(args.firstSampleDistance, 0.0) * v0;
  float maxDistance = min(args.maxDistance, 1e30);
  vec3 radiance = vec3(0.0);
  float opacity = 0.0, ambientOpacity = 0.0;
  // The surface the cone leaves, if the caller named one: a sample at distance t is
  // surfaceDistance + t·rise above it, and its footprint is kept below that / clearance.
  vec3 n = safeNormalize(args.surfaceNormal, vec3(0.0));
  bool leavesSurface = dot(n, n) > 0.5;
  float rise = max(dot(r, n), 0.0);
  float clearance = VXGI_SURFACE_CLEARANCE * max(abs(n.x) + abs(n.y) + abs(n.z), 1.0);
  float surfaceDistance = max(args.surfaceDistance, 0.0);
#if !VXGI_AO_MODE
  // The apex and the surface the cone leaves (n = 0: none), which no sample reads behind.
  VxgiConeStart start = vxgiConeStart(r, args.firstSamplePosition, n, surfaceDistance);
#endif
  for (int i = 0; i < VXGI_MAX_STEPS && t < maxDistance && opacity < VXGI_OPAQUE; ++i) {
    float cone = coneFactor * t;  // the cone's diameter here
    float diameter = VXGI_VOXELS_PER_DIAMETER * cone;  // the voxels its sample reads
    if (leavesSurface) diameter = min(diameter, (surfaceDistance + t * rise) / clearance);
    // The footprint never shrinks below a finest voxel: finer detail is not stored.
    diameter = max(diameter, v0);
    vec3 p = args.firstSamplePosition + r * t;
    bool valid;
    // The sample may widen `diameter` to the voxels of the finest level holding p.
#if VXGI_AO_MODE
    VxgiSample s = vxgiSample(p, diameter, r, valid);
#else
    // Each facing direction reads only what lies in front of the apex (clip_map.glsl).
    VxgiSample s = vxgiSampleAhead(p, diameter, start, valid);
#endif
    if (!valid) break;  // left the clip-map: nothing more to gather
    // Steps follow the cone's width even where the footprint is held narrower near the
    // surface, so that costs no extra samples; the optical depth below counts the whole
    // step (step / diameter footprints), so occlusion stays right in thick media.
    float step = stepFactor * max(diameter, cone);
    // Beer–Lambert over this step: the sample's density is optical depth per footprint.
    float footprints = step / diameter;
    float alpha = 1.0 - exp(-max(s.density, 0.0) * VXGI_MAX_OPTICAL_DEPTH * footprints);
    // What the step emits towards the cone apex: mean radiance L = emittance / density
    // times α. Written as emittance × α/density, it needs no division by a density that
    // 8-bit storage may have rounded to zero: a bright source much smaller than a voxel
    // keeps its power at every level, where its opacity alone rounds away (one step of
    // stored density is 3.5% opacity).
    // (The same α: lavapipe's compiler would not share the exponential.)
    radiance += (1.0 - opacity) * vxgiAlphaPerDensity(s.density, footprints, alpha) * max(s.emittance, vec3(0.0));
    if (t <= args.ambientRange) ambientOpacity += (1.0 - ambientOpacity) * alpha;
    opacity += (1.0 - opacity) * alpha;
    t += step;
  }
  // Stopped on an opaque surface: the rest (up to 1 − VXGI_OPAQUE) is more of the same
  // surface, so renormalise instead of leaving the cone that much too dark (this is what
  // makes a closed furnace come out exact rather than low). Occlusion likewise: a surface
  // reached within the ambient range (all of the opacity counted there too) occludes the
  // whole cone, not VXGI_OPAQUE of it.
  if (opacity >= VXGI_OPAQUE) {
    radiance /= opacity;
    if (ambientOpacity >= opacity) ambientOpacity = 1.0;
  }
  res.irradiance = PI * radiance;
  res.ambient = 1.0 - ambientOpacity;
  res.finalOpacity = opacity;
  return res;
}

#endif
