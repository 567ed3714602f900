#version 460
// Voxelization, step 2: project each triangle along its dominant axis onto the level's
// voxel grid (one pixel = one voxel column) and dilate it by half a pixel diagonal, so
// every voxel column the triangle touches gets a fragment (conservative coverage in
// the shader: lavapipe has no VK_EXT_conservative_rasterization). The fragment shader
// then weighs each fragment by how much of its pixel the undilated triangle covers.
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "bounce/scene.glsl"
#include "vxgi/clip_map.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

SCENE_DRAW_PUSH_CONSTANTS(ivec4 regionMin; ivec4 regionMax; ivec4 innerMin; ivec4 innerMax;)

layout(location = 0) in vec3 vWorld[];
layout(location = 1) in vec2 vUv[];
layout(location = 0) out vec3 gWorld;
layout(location = 1) out vec2 gUv;
layout(location = 2) flat out vec3 gNormal;   // geometric normal (unit), counter-clockwise front
layout(location = 3) flat out int gAxis;      // dominant axis: 0 x, 1 y, 2 z
layout(location = 4) flat out vec4 gPixelBox; // the triangle's pixel bounds, dilated
layout(location = 5) flat out vec4 gTriangle01; // the undilated triangle in pixels: p0, p1
layout(location = 6) flat out vec2 gTriangle2;  // … p2 (counter-clockwise)

// The two in-plane axes for a dominant axis.
ivec2 planeAxes(int axis) { return axis == 0 ? ivec2(1, 2) : (axis == 1 ? ivec2(2, 0) : ivec2(0, 1)); }

void main() {
  vec3 e1 = vWorld[1] - vWorld[0], e2 = vWorld[2] - vWorld[0];
  vec3 n = cross(e1, e2);
  float len2 = dot(n, n);
  // Degenerate (zero-area or non-finite) triangles cover nothing: drop them here rather
  // than divide by their zero normal.
  if (!(len2 > 1e-24) || isinf(len2)) return;
  n *= inversesqrt(len2);
  vec3 a = abs(n);
  int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
  ivec2 pa = planeAxes(axis);

  int level = draw.regionMin.w;
  float v = vxgiVoxelSize(level);
  vec2 origin = vec2(clipMap.levelOrigin[level][pa.x], clipMap.levelOrigin[level][pa.y]);
  float size = float(clipMap.mapSize);
  // Pixel coordinates (one pixel per voxel of the level).
  vec2 p[3];
  for (int i = 0; i < 3; ++i) p[i] = vec2(vWorld[i][pa.x], vWorld[i][pa.y]) / v - origin;

  // Dilation (Hasselgren et al., GPU Gems 2 ch. 42): push each edge out by half a
  // pixel in the L∞ sense and intersect neighbouring edges. Orientation first, so
  // "out" is the same side for every triangle.
  float area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
  if (area < 0.0) { vec2 t = p[1]; p[1] = p[2]; p[2] = t; }
  vec3 edge[3];
  for (int i = 0; i < 3; ++i) {
    vec3 a3 = vec3(p[i], 1.0), b3 = vec3(p[(i + 1) % 3], 1.0);
    edge[i] = cross(a3, b3);
    // Counter-clockwise, the inside is where dot(edge, (x, y, 1)) > 0: growing the
    // constant moves the edge outwards by half a pixel along both axes.
    edge[i].z += 0.5 * (abs(edge[i].x) + abs(edge[i].y));
  }
  vec2 q[3];
  for (int i = 0; i < 3; ++i) {
    vec3 c = cross(edge[(i + 2) % 3], edge[i]);
    // Nearly parallel edges (a sliver) put the corner far away; the pixel box below
    // discards what lies outside the triangle's own bounds.
    q[i] = abs(c.z) > 1e-12 ? c.xy / c.z : p[i];
  }
  vec2 lo = min(min(p[0], p[1]), p[2]) - 0.5, hi = max(max(p[0], p[1]), p[2]) + 0.5;
  int order[3] = int[3](0, area < 0.0 ? 2 : 1, area < 0.0 ? 1 : 2);  // world vertex of each p
  // World position at each dilated corner, extrapolated on the triangle's plane.
  for (int i = 0; i < 3; ++i) {
    // Barycentrics of q[i] in the (reordered) triangle p.
    vec2 d0 = p[1] - p[0], d1 = p[2] - p[0], d2 = q[i] - p[0];
    float den = d0.x * d1.y - d1.x * d0.y;
    float b1 = (d2.x * d1.y - d1.x * d2.y) / den, b2 = (d0.x * d2.y - d2.x * d0.y) / den;
    float b0 = 1.0 - b1 - b2;
    gWorld = b0 * vWorld[order[0]] + b1 * vWorld[order[1]] + b2 * vWorld[order[2]];
    gUv = b0 * vUv[order[0]] + b1 * vUv[order[1]] + b2 * vUv[order[2]];
    gNormal = n;
    gAxis = axis;
    gPixelBox = vec4(lo, hi);
    gTriangle01 = vec4(p[0], p[1]);
    gTriangle2 = p[2];
    // Each projection axis has its own N×N region of the 3N×N target, side by side along X: a
    // CPU device (lavapipe) rasterizes each 64×64 tile of a target on one thread, so a
    // single N×N target of 64² ran all of a level's fragments on one core.
    gl_Position = vec4((q[i].x + float(axis) * size) / (3.0 * size) * 2.0 - 1.0, q[i].y / size * 2.0 - 1.0, 0.5,
                       1.0);
    EmitVertex();
  }
  EndPrimitive();
}
