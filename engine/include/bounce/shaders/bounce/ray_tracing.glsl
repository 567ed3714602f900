// Ray tracing into the scene from any shader stage: the engine's two-level BVH
// (bounce/raytracing/ray_tracing_layout.h), traversed in software, so it runs on
// lavapipe and on every GPU.
//
//   #define RAY_TRACING_BINDING 2      // six storage buffers from this binding on
//   #include "bounce/ray_tracing.glsl"
//   RayHit h = traceClosestHit(origin, direction, 0.0, 1e30);
//   if (h.hit) { RtSurface s = surfaceAt(h, direction); ... }
//   bool blocked = traceAnyHit(origin, direction, 0.0, distance);
//
// On the C++ side the pass declares the reads with readRayTracingScene() and binds them
// with bindRayTracingScene() (bounce/raytracing/ray_tracing.h).
//
// Rays: `direction` need not be unit length (t is in its units); a NaN/Inf/zero
// direction, a NaN origin or tMin > tMax is a miss. Hits are accepted for tMin < t < tMax.
// Alpha-masked materials (glTF alphaMode MASK) are cut out where their base-colour alpha
// is below the cutoff, as the rasterizer discards: rays pass through leaves and fences.
// Define RAY_TRACING_DEBUG_COUNTERS_BINDING to count stack overflows and step-limit
// hits (RtDebugCounters { uint stackOverflows; uint stepLimits; }).
#ifndef BOUNCE_RAY_TRACING_GLSL
#define BOUNCE_RAY_TRACING_GLSL

#ifndef RAY_TRACING_BINDING
#error "define RAY_TRACING_BINDING (the first of six bindings) before including bounce/ray_tracing.glsl"
#endif

#include "bounce/common.glsl"

struct RtNode {
  vec4 lmin;  // xyz: left child's box; w: left child reference (uint bits)
  vec4 lmax;  // w: right child reference
  vec4 rmin;
  vec4 rmax;
};
struct RtTriangle {
  vec4 v0;  // object space; w: triangle within its mesh (uint bits)
  vec4 v1;  // w: material index
  vec4 v2;  // w: flags (1: double-sided)
};
struct RtTriangleAttributes {
  uvec4 normals;  // xyz: octahedral snorm16x2 vertex normals; w: primitive within the mesh
  vec4 uv01;
  vec4 uv2;
};
struct RtInstance {
  vec4 worldToObject[3];  // rows of a 3x4 affine matrix
  vec4 objectToWorld[3];
  uint nodeOffset;
  uint triangleOffset;
  uint sceneInstance;
  uint mesh;
};
struct RtMaterial {
  vec4 baseColor;  // rgb: albedo (factor x mean texture colour), a: alpha (masked: the factor)
  vec4 emission;   // rgb: radiance W/(m2 sr), w: first word of the alpha mask (uint bits, 0: none)
  vec4 params;     // x: roughness, y: metallic, z: alpha cutoff (< 0 opaque), w: 1 double-sided
};

layout(std430, binding = RAY_TRACING_BINDING) readonly buffer RtNodeBuffer { RtNode rtNodes[]; };
layout(std430, binding = RAY_TRACING_BINDING + 1) readonly buffer RtTriangleBuffer { RtTriangle rtTriangles[]; };
layout(std430, binding = RAY_TRACING_BINDING + 2) readonly buffer RtAttributeBuffer {
  RtTriangleAttributes rtAttributes[];
};
layout(std430, binding = RAY_TRACING_BINDING + 3) readonly buffer RtInstanceBuffer {
  uvec4 rtCounts;  // x: instances (0: every ray misses), y: top level's first node, z: triangles, w: materials
  RtInstance rtInstances[];
};
layout(std430, binding = RAY_TRACING_BINDING + 4) readonly buffer RtMaterialBuffer { RtMaterial rtMaterials[]; };
// Alpha masks: per texture [width, height, alpha bytes four to a word] (ray_tracing_layout.h).
layout(std430, binding = RAY_TRACING_BINDING + 5) readonly buffer RtAlphaMaskBuffer { uint rtAlphaMasks[]; };

#ifdef RAY_TRACING_DEBUG_COUNTERS_BINDING
layout(std430, binding = RAY_TRACING_DEBUG_COUNTERS_BINDING) buffer RtDebugCounters {
  uint rtStackOverflows;
  uint rtStepLimits;
};
#endif

const uint RT_LEAF = 0x80000000u;
// Bottom levels are built at most 40 inner levels deep and the top level 23
// (RayTracingScene), so with the instance marker the stack never holds more than 64.
const uint RT_STACK_SIZE = 64u;
// Node visits per ray before giving up (a corrupt BVH must not hang the device).
const uint RT_MAX_STEPS = 65536u;
const uint RT_EXIT_INSTANCE = 0xFFFFFFFFu;  // stack marker: back to the top level

struct RayHit {
  bool hit;
  float t;             // origin + t * direction is the hit point
  uint instance;       // index in Scene::instances()
  uint triangle;       // triangle within its mesh (primitives in order)
  vec2 barycentrics;   // (u, v): P = (1 - u - v) v0 + u v1 + v v2
  bool frontFace;      // geometric: the ray meets the side cross(v1 - v0, v2 - v0) points to
  uint rtTriangle;     // index into rtTriangles / rtAttributes
  uint rtInstance;     // index into rtInstances
};

// A ray prepared for slab tests and the watertight triangle test (Woop, Benthin, Wald,
// JCGT 2013): the axis where the direction is largest, the other two, and the shear.
struct RtRay {
  vec3 origin;
  vec3 direction;
  vec3 invDirection;
  vec3 scaledOrigin;  // -origin * invDirection, so a slab is one fma per axis
  // Rows of the watertight test's permute-and-shear: (A[kx] - Sx A[kz], A[ky] - Sy A[kz],
  // Sz A[kz]) = (dot(shearX, A), dot(shearY, A), dot(shearZ, A)); one of each row's
  // entries is 0 and another 1, so each is the same arithmetic as indexing, without
  // per-lane dynamic indexing (which llvmpipe turns into selects).
  vec3 shearX;
  vec3 shearY;
  vec3 shearZ;
};

RtRay rtPrepareRay(vec3 o, vec3 d) {
  RtRay r;
  r.origin = o;
  r.direction = d;
  // A zero component becomes 1e-20 (keeping its sign): 1/0 = inf times a zero box
  // extent would make NaN in the slab test.
  vec3 safeD = mix(d, mix(vec3(1e-20), vec3(-1e-20), lessThan(d, vec3(0.0))), lessThan(abs(d), vec3(1e-20)));
  r.invDirection = 1.0 / safeD;
  r.scaledOrigin = -o * r.invDirection;
  vec3 a = abs(d);
  int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
  int kx = (kz + 1) % 3;
  int ky = (kx + 1) % 3;
  if (d[kz] < 0.0) {  // keeps the winding, so the sign test below stays the same
    int tmp = kx;
    kx = ky;
    ky = tmp;
  }
  float sz = 1.0 / d[kz];
  vec3 ex = vec3(equal(ivec3(0, 1, 2), ivec3(kx)));
  vec3 ey = vec3(equal(ivec3(0, 1, 2), ivec3(ky)));
  vec3 ez = vec3(equal(ivec3(0, 1, 2), ivec3(kz)));
  r.shearX = ex - (d[kx] * sz) * ez;
  r.shearY = ey - (d[ky] * sz) * ez;
  r.shearZ = sz * ez;
  return r;
}

// Entry and exit distances of a box, clipped to [tMin, tMax]; entry > exit: missed.
vec2 rtSlab(RtRay r, vec3 lo, vec3 hi, float tMin, float tMax) {
  vec3 t1 = fma(lo, r.invDirection, r.scaledOrigin);
  vec3 t2 = fma(hi, r.invDirection, r.scaledOrigin);
  vec3 tNear = min(t1, t2);
  vec3 tFar = max(t1, t2);
  float enter = max(max(tNear.x, tNear.y), max(tNear.z, tMin));
  // 1 + 2*gamma(3), gamma(n) = n u / (1 - n u), u = 2^-24: the conservative slab factor
  // of pbrt's Bounds3::IntersectP, so a box entered exactly at tMax is not lost to rounding.
  float exit = min(min(tFar.x, tFar.y), min(tFar.z, tMax)) * 1.0000004;
  return vec2(enter, exit);
}

// The 2D edge function p.x q.y - p.y q.x, evaluated with the two points in a canonical
// order and negated when swapped: the two triangles sharing an edge then compute the very
// same expression and get exact negations of each other, whether or not the compiler
// fuses it into an FMA (fma(p.x, q.y, -p.y q.x) is not antisymmetric by itself, and
// `precise` to forbid fusing cost a third of the traversal speed on llvmpipe).
float rtEdge(vec2 p, vec2 q) {
  bool swap = p.x < q.x || (p.x == q.x && p.y < q.y);
  vec2 a = swap ? q : p;
  vec2 b = swap ? p : q;
  float e = a.x * b.y - a.y * b.x;
  return swap ? -e : e;
}

// Watertight ray/triangle test: edge functions in the ray's sheared frame. A ray
// through a shared edge or vertex gets zeros there, which pass the sign test, so it hits
// both neighbours and never slips between them. Degenerate triangles (det = 0) never hit.
bool rtIntersectTriangle(RtRay r, RtTriangle tri, float tMin, float tMax, out float t, out vec2 bary) {
  vec3 A = tri.v0.xyz - r.origin;
  vec3 B = tri.v1.xyz - r.origin;
  vec3 C = tri.v2.xyz - r.origin;
  float ax = dot(r.shearX, A), ay = dot(r.shearY, A);
  float bx = dot(r.shearX, B), by = dot(r.shearY, B);
  float cx = dot(r.shearX, C), cy = dot(r.shearY, C);
  float U = rtEdge(vec2(cx, cy), vec2(bx, by));
  float V = rtEdge(vec2(ax, ay), vec2(cx, cy));
  float W = rtEdge(vec2(bx, by), vec2(ax, ay));
  t = 0.0;
  bary = vec2(0.0);
  if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) return false;
  float det = U + V + W;
  if (det == 0.0) return false;
  float T = U * dot(r.shearZ, A) + V * dot(r.shearZ, B) + W * dot(r.shearZ, C);
  t = T / det;
  if (!(t > tMin && t < tMax)) return false;  // also refuses NaN
  bary = vec2(V, W) / det;
  return true;
}

// Alpha of mask texel (x, y), both already wrapped into range.
float rtMaskTexel(uint first, uint width, uint x, uint y) {
  uint i = y * width + x;
  return float((rtAlphaMasks[first + 2u + (i >> 2u)] >> (8u * (i & 3u))) & 255u) * (1.0 / 255.0);
}

// Repeat wrapping of texel coordinate c (integral, possibly negative or huge) into [0, size).
uint rtWrapTexel(float c, uint size) {
  float s = float(size);
  // Rounding can land c - s floor(c / s) on s itself (or, beyond 2^24, anywhere): clamp.
  return uint(clamp(c - s * floor(c / s), 0.0, s - 1.0));
}

// Whether a candidate hit on rtTriangles[p] at `bary` is cut out: its material is alpha
// masked and alpha (factor x the texture's, bilinear on mip 0 with repeat wrapping, as
// the rasterizer's sampler and the reference path tracer read it) is below the cutoff.
// Opaque materials cost one load of the cutoff.
bool rtCutOut(uint p, vec2 bary) {
  uint material = min(floatBitsToUint(rtTriangles[p].v1.w), max(rtCounts.w, 1u) - 1u);
  float cutoff = rtMaterials[material].params.z;
  if (cutoff < 0.0) return false;
  float alpha = rtMaterials[material].baseColor.a;
  uint first = floatBitsToUint(rtMaterials[material].emission.w);
  if (first != 0u) {
    RtTriangleAttributes attr = rtAttributes[p];
    vec2 uv = (1.0 - bary.x - bary.y) * attr.uv01.xy + bary.x * attr.uv01.zw + bary.y * attr.uv2.xy;
    // A non-finite coordinate reads texel 0.
    uv.x = isnan(uv.x) || isinf(uv.x) ? 0.0 : uv.x;
    uv.y = isnan(uv.y) || isinf(uv.y) ? 0.0 : uv.y;
    uint w = rtAlphaMasks[first], h = rtAlphaMasks[first + 1u];
    // Texel centres at (i + 0.5) / size.
    vec2 x = uv * vec2(w, h) - 0.5;
    vec2 x0 = floor(x);
    vec2 f = x - x0;
    uint ax = rtWrapTexel(x0.x, w), bx = rtWrapTexel(x0.x + 1.0, w);
    uint ay = rtWrapTexel(x0.y, h), by = rtWrapTexel(x0.y + 1.0, h);
    float top = mix(rtMaskTexel(first, w, ax, ay), rtMaskTexel(first, w, bx, ay), f.x);
    float bottom = mix(rtMaskTexel(first, w, ax, by), rtMaskTexel(first, w, bx, by), f.x);
    alpha *= mix(top, bottom, f.y);
  }
  return alpha < cutoff;
}

vec3 rtTransformPoint(vec4 rows[3], vec3 p) {
  vec4 h = vec4(p, 1.0);
  return vec3(dot(rows[0], h), dot(rows[1], h), dot(rows[2], h));
}
vec3 rtTransformVector(vec4 rows[3], vec3 v) {
  return vec3(dot(rows[0].xyz, v), dot(rows[1].xyz, v), dot(rows[2].xyz, v));
}
// A normal from object to world space: the inverse transpose of objectToWorld, i.e. the
// transpose of worldToObject's 3x3.
vec3 rtTransformNormal(vec4 worldToObject[3], vec3 n) {
  return worldToObject[0].xyz * n.x + worldToObject[1].xyz * n.y + worldToObject[2].xyz * n.z;
}

bool rtFinite(vec3 v) { return !any(isnan(v)) && !any(isinf(v)); }

RayHit rtTrace(vec3 origin, vec3 direction, float tMin, float tMax, bool anyHit) {
  RayHit h;
  h.hit = false;
  h.t = tMax;
  h.instance = 0u;
  h.triangle = 0u;
  h.barycentrics = vec2(0.0);
  h.frontFace = true;
  h.rtTriangle = 0u;
  h.rtInstance = 0u;
  if (!rtFinite(origin) || !rtFinite(direction) || dot(direction, direction) == 0.0 || isnan(tMin) ||
      isnan(tMax) || tMin > tMax || tMax <= 0.0 || rtCounts.x == 0u)
    return h;
  tMin = max(tMin, 0.0);

  // Two loops in one ("while-while", Aila and Laine 2009): the inner one walks inner
  // nodes until the ray reaches a leaf, the outer one handles that leaf. SIMD lanes
  // (llvmpipe runs 8 invocations per vector) then do the same kind of work together.
  RtRay ray = rtPrepareRay(origin, direction);
  uint stack[RT_STACK_SIZE];
  uint sp = 0u;
  uint base = rtCounts.y;  // the level's first node
  uint node = 0u;          // reference: inner node 0 of the top level
  uint triangleBase = 0u;
  int instance = -1;  // -1: in the top level
  float tBest = tMax;
  uint step = 0u;
  bool done = false;
  while (!done) {
    while ((node & RT_LEAF) == 0u) {
      if (++step > RT_MAX_STEPS) {
        done = true;
        break;
      }
      RtNode n = rtNodes[base + node];
      vec2 a = rtSlab(ray, n.lmin.xyz, n.lmax.xyz, tMin, tBest);
      vec2 b = rtSlab(ray, n.rmin.xyz, n.rmax.xyz, tMin, tBest);
      bool hitA = a.x <= a.y;
      bool hitB = b.x <= b.y;
      uint left = floatBitsToUint(n.lmin.w);
      uint right = floatBitsToUint(n.lmax.w);
      if (hitA && hitB) {
        // Nearer child first: a close hit shrinks tBest and culls the far one.
        bool rightFirst = b.x < a.x;
        node = rightFirst ? right : left;
        if (sp < RT_STACK_SIZE) {
          stack[sp++] = rightFirst ? left : right;
        } else {
#ifdef RAY_TRACING_DEBUG_COUNTERS_BINDING
          atomicAdd(rtStackOverflows, 1u);
#endif
        }
      } else if (hitA || hitB) {
        node = hitA ? left : right;
      } else {
        if (sp == 0u) {
          done = true;
          break;
        }
        node = stack[--sp];
        if (node == RT_EXIT_INSTANCE) {
          // Back to the top level; the entry below a marker is never another marker.
          instance = -1;
          ray = rtPrepareRay(origin, direction);
          base = rtCounts.y;
          if (sp == 0u) {
            done = true;
            break;
          }
          node = stack[--sp];
        }
      }
    }
    if (done) break;
    uint count = (node >> 24) & 127u;
    uint first = node & 0xFFFFFFu;
    if (instance < 0) {
      // A top-level leaf holds one instance (or none: the wrapper of a lone root).
      if (count != 0u && sp < RT_STACK_SIZE) {
        stack[sp++] = RT_EXIT_INSTANCE;
        instance = int(first);
        RtInstance ri = rtInstances[first];
        ray = rtPrepareRay(rtTransformPoint(ri.worldToObject, origin), rtTransformVector(ri.worldToObject, direction));
        base = ri.nodeOffset;
        triangleBase = ri.triangleOffset;
        node = 0u;
        continue;
      }
#ifdef RAY_TRACING_DEBUG_COUNTERS_BINDING
      if (count != 0u) atomicAdd(rtStackOverflows, 1u);
#endif
    } else {
      for (uint i = 0u; i < count; ++i) {
        uint p = triangleBase + first + i;
        float t;
        vec2 bary;
        if (rtIntersectTriangle(ray, rtTriangles[p], tMin, tBest, t, bary) && !rtCutOut(p, bary)) {
          tBest = t;
          h.hit = true;
          h.t = t;
          h.barycentrics = bary;
          h.rtTriangle = p;
          h.rtInstance = uint(instance);
        }
      }
      if (anyHit && h.hit) break;
    }
    if (sp == 0u) break;
    node = stack[--sp];
    if (node == RT_EXIT_INSTANCE) {
      instance = -1;
      ray = rtPrepareRay(origin, direction);
      base = rtCounts.y;
      if (sp == 0u) break;
      node = stack[--sp];
    }
  }
#ifdef RAY_TRACING_DEBUG_COUNTERS_BINDING
  if (step > RT_MAX_STEPS) atomicAdd(rtStepLimits, 1u);
#endif
  if (h.hit) {
    RtInstance ri = rtInstances[h.rtInstance];
    RtTriangle tri = rtTriangles[h.rtTriangle];
    h.instance = ri.sceneInstance;
    h.triangle = floatBitsToUint(tri.v0.w);
    vec3 ng = cross(tri.v1.xyz - tri.v0.xyz, tri.v2.xyz - tri.v0.xyz);
    // Object space: dot(M^-1 D, Ng) = dot(D, M^-T Ng), the world-space normal test.
    h.frontFace = dot(rtTransformVector(ri.worldToObject, direction), ng) < 0.0;
  }
  return h;
}

RayHit traceClosestHit(vec3 origin, vec3 direction, float tMin, float tMax) {
  return rtTrace(origin, direction, tMin, tMax, false);
}

// Visibility: true when anything lies between tMin and tMax (stops at the first hit).
bool traceAnyHit(vec3 origin, vec3 direction, float tMin, float tMax) {
  return rtTrace(origin, direction, tMin, tMax, true).hit;
}

// What a hit point looks like to shading. Normals are world space and unit length.
struct RtSurface {
  vec3 position;
  vec3 geometricNormal;  // faces the incoming ray
  vec3 normal;           // interpolated vertex normal, on the same side as geometricNormal
  vec2 uv;               // TEXCOORD_0
  uint material;
  vec3 baseColor;  // factor x the texture's mean colour (textures are not sampled per hit)
  vec3 emission;   // radiance W/(m2 sr); 0 seen from behind a single-sided surface
  float roughness;
  float metallic;
  bool frontFace;    // the hit's front face, or any face of a double-sided material
  bool doubleSided;
  float rayOffset;  // how far to move off the surface before tracing again (float rounding)
};

vec3 rtDecodeNormal(uint packed) {
  vec2 e = unpackSnorm2x16(packed);
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * mix(vec2(-1.0), vec2(1.0), greaterThanEqual(n.xy, vec2(0.0)));
  return n;
}

RtSurface surfaceAt(RayHit h) {
  RtSurface s;
  RtInstance ri = rtInstances[h.rtInstance];
  RtTriangle tri = rtTriangles[h.rtTriangle];
  RtTriangleAttributes attr = rtAttributes[h.rtTriangle];
  float u = h.barycentrics.x, v = h.barycentrics.y, w = 1.0 - u - v;
  // Interpolating the vertices (not origin + t * direction) keeps the point on the
  // triangle to within rounding of its coordinates, whatever the ray's length.
  s.position = rtTransformPoint(ri.objectToWorld, w * tri.v0.xyz + u * tri.v1.xyz + v * tri.v2.xyz);
  vec3 face = safeNormalize(
      rtTransformNormal(ri.worldToObject, cross(tri.v1.xyz - tri.v0.xyz, tri.v2.xyz - tri.v0.xyz)),
      vec3(0.0, 1.0, 0.0));
  s.material = floatBitsToUint(tri.v1.w);
  s.doubleSided = (floatBitsToUint(tri.v2.w) & 1u) != 0u;
  s.frontFace = h.frontFace || s.doubleSided;
  s.geometricNormal = h.frontFace ? face : -face;
  vec3 n = w * rtDecodeNormal(attr.normals.x) + u * rtDecodeNormal(attr.normals.y) + v * rtDecodeNormal(attr.normals.z);
  n = safeNormalize(rtTransformNormal(ri.worldToObject, n), face);
  // A single-sided back face is shaded like an opaque surface facing the ray (as the
  // reference path tracer does); a double-sided one with its normal flipped.
  s.normal = h.frontFace ? n : (s.doubleSided ? -n : s.geometricNormal);
  s.uv = w * attr.uv01.xy + u * attr.uv01.zw + v * attr.uv2.xy;
  RtMaterial m = rtMaterials[min(s.material, max(rtCounts.w, 1u) - 1u)];
  s.baseColor = m.baseColor.rgb;
  s.emission = s.frontFace ? m.emission.rgb : vec3(0.0);
  s.roughness = m.params.x;
  s.metallic = m.params.y;
  vec3 a = abs(s.position);
  // 2^-16 of the coordinates' magnitude: far above float rounding of a transformed,
  // interpolated point (2^-23 relative, a few roundings), far below any real wall.
  s.rayOffset = max(max(a.x, max(a.y, a.z)) * 1.52587890625e-05, 1e-7);
  return s;
}

// Where to start a ray leaving surface `s` in direction `d`: off the side `d` goes to.
vec3 offsetRayOrigin(RtSurface s, vec3 d) {
  return s.position + s.geometricNormal * (dot(d, s.geometricNormal) >= 0.0 ? s.rayOffset : -s.rayOffset);
}

#endif
