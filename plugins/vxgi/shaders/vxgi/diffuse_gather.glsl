// Diffuse irradiance at a surface point from the clip-map, shared by the G-buffer's diffuse
// tracing (diffuse.comp) and the voxelizer's multi-bounce gather (voxelize.frag).
//
// N cones of equal projected solid angle over the cosine-weighted hemisphere: their axes are
// a sunflower pattern on the unit disk lifted to the hemisphere (Malley's method: equal disk
// areas are equal cosine-weighted measure), each cone's solid angle is 2π/N (cos θ = 1 − 1/N),
// and each carries weight 1/N of the irradiance, so a uniform radiance field L gives exactly
// πL (the white furnace test).
#ifndef VXGI_DIFFUSE_GATHER_GLSL
#define VXGI_DIFFUSE_GATHER_GLSL

#include "trace_cone.glsl"

const float VXGI_GOLDEN_ANGLE = 2.39996322972865;

// Orthonormal basis around n (Duff et al. 2017: branchless, no singularity).
void vxgiTangentBasis(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// A cone leaving the surface at P (unit normal N): it starts `normalOffset` voxels of the
// finest level holding P off the surface along N, so it does not see the surface it leaves,
// and TraceCone keeps its filter off that surface.
ConeTracingArguments vxgiSurfaceCone(vec3 P, vec3 N, float normalOffset, float stepFactor, float maxDistance) {
  ConeTracingArguments args = DefaultConeTracingArguments();
  int level = max(vxgiFinestLevelAt(P, 0), 0);
  args.firstSamplePosition = P + N * (normalOffset * vxgiVoxelSize(level));
  args.surfaceNormal = N;
  args.surfaceDistance = dot(args.firstSamplePosition - P, N);
  args.firstSampleDistance = 1.0;
  args.stepFactor = stepFactor;
  args.maxDistance = maxDistance;
  return args;
}

struct VxgiDiffuseLight {
  vec3 irradiance;  // W/m² at the surface (before albedo)
  float ambient;    // the mean of the cones' ambient terms (1: unoccluded)
};

// `cones` cones (1..64) from `args` (vxgiSurfaceCone) over the hemisphere around N, the
// pattern turned about N by `turn` of a full turn (0: the fixed pattern; a turn keeps every
// cone's solid angle and weight, so the white furnace stays exact).
VxgiDiffuseLight vxgiGatherDiffuse(ConeTracingArguments args, vec3 N, int cones, float turn) {
  vec3 T, B;
  vxgiTangentBasis(N, T, B);
  cones = clamp(cones, 1, 64);
  float cosHalf = 1.0 - 1.0 / float(cones);
  args.coneFactor = 2.0 * sqrt(max(1.0 - cosHalf * cosHalf, 0.0)) / max(cosHalf, 1e-3);
  VxgiDiffuseLight light;
  light.irradiance = vec3(0.0);
  light.ambient = 0.0;
  for (int c = 0; c < cones; ++c) {
    float r = sqrt((float(c) + 0.5) / float(cones));
    float phi = float(c) * VXGI_GOLDEN_ANGLE + turn * (2.0 * PI);
    vec3 local = vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - r * r, 0.0)));
    args.direction = normalize(local.x * T + local.y * B + local.z * N);
    ConeTracingResults cone = TraceCone(args);
    light.irradiance += cone.irradiance;
    light.ambient += cone.ambient;
  }
  light.irradiance /= float(cones);
  light.ambient /= float(cones);
  return light;
}

#endif
