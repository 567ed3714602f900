// Multi-bounce gather requests (r.VXGI.Bounces > 1; never in ambient-occlusion mode): the
// voxelizer (voxelize.frag) lists each fragment's gather instead of tracing its cones, and
// compute passes per level finish it before the level's resolve:
//   bounce_cluster.comp  requests of one surface within a cell of N×N voxel columns
//                        (r.VXGI.BounceGatherCell) share one gather: the cell's leading column
//                        leads (step 0), and the others follow the nearest leader of their cell
//                        that serves them, or lead (step 1);
//   bounce_gather.comp   each leader's cones, into VxgiBounceIrradiance;
//   bounce_apply.comp    every request adds albedo / π × its leader's irradiance to its column.
// Who leads depends on where the requests are, never on the order they were listed in, so
// the same scene gives the same light.
// Needs clip_map.glsl and voxel_column.glsl.
#ifndef VXGI_BOUNCE_REQUESTS_GLSL
#define VXGI_BOUNCE_REQUESTS_GLSL

const uint VXGI_BOUNCE_GROUP = 64u;  // the local size of the passes that take one request a lane
const uint VXGI_NO_LEADER = 0xFFFFFFFFu;  // a cell without leaders, the end of its list (the plugin fills the cells with it)

// A fragment's listed gather (VxgiBounceRequests): its position, normal and diffuse albedo,
// and its column, packed into four vec4s (64 bytes).
struct VxgiBounceRequest {
  vec4 world;     // xyz: the fragment's world position; w: the packed column and flags (bits)
  vec4 normal;    // xyz: unit normal; w: first.x (bits)
  vec4 albedo;    // rgb: diffuse albedo; w: first.y (bits)
  vec4 coverage;  // xyz: coverage; w: first.z (bits)
};

// Packed word: axis (bits 0–1), mask (2–10), double-sided (11), proportional (12), omni (13).
VxgiBounceRequest vxgiPackBounceRequest(vec3 world, vec3 albedo, VxgiVoxelColumn column, VxgiSurfacePiece piece) {
  uint packed = uint(column.axis) | (column.mask << 2) | (piece.doubleSided ? 1u << 11 : 0u) |
                (piece.proportional ? 1u << 12 : 0u) | (piece.omni ? 1u << 13 : 0u);
  VxgiBounceRequest r;
  r.world = vec4(world, uintBitsToFloat(packed));
  r.normal = vec4(piece.normal, intBitsToFloat(column.first.x));
  r.albedo = vec4(albedo, intBitsToFloat(column.first.y));
  r.coverage = vec4(piece.coverage, intBitsToFloat(column.first.z));
  return r;
}

void vxgiUnpackBounceRequest(VxgiBounceRequest r, out vec3 world, out vec3 albedo, out VxgiVoxelColumn column,
                             out VxgiSurfacePiece piece) {
  uint packed = floatBitsToUint(r.world.w);
  world = r.world.xyz;
  albedo = r.albedo.rgb;
  column.first = ivec3(floatBitsToInt(r.normal.w), floatBitsToInt(r.albedo.w), floatBitsToInt(r.coverage.w));
  column.axis = int(packed & 3u);
  column.mask = (packed >> 2) & 0x1FFu;
  piece.normal = r.normal.xyz;
  piece.coverage = r.coverage.xyz;
  piece.doubleSided = (packed & (1u << 11)) != 0u;
  piece.proportional = (packed & (1u << 12)) != 0u;
  piece.omni = (packed & (1u << 13)) != 0u;
}

// The turn of a leading column's multi-bounce cone pattern about its normal (a fraction of a
// full turn), from where its cell lies in the projection plane (`edge`: the cell's columns
// per side, 1 without sharing). Each gather's four cones miss what lies between them, and
// the cones that later read this emittance average it over many cells: neighbouring cells
// turn their patterns apart, by the R2 sequence's two irrational steps (Roberts 2018, a
// low-discrepancy dither), so a footprint's cells together cover the turns evenly. Random
// turns (a hash of the column, before) left a room's light to chance: in a generated sunlit
// room with 20 cm walls, moving the 4×4 cells' leading column by one voxel moved the mean
// irradiance from 0.83 to 1.02 of the path tracer's (every column's own gather: 0.92); with
// these turns from 0.91 to 0.98 (own: 0.91).
// Only a turn: cones also moved outwards within their rings (up to grazing) lost 2.8% of the
// white furnace's light per bounce, against 1.3% with each at its ring's middle.
float vxgiColumnTurn(VxgiVoxelColumn column, int edge) {
  ivec3 t = vxgiWrap(column.first);
  int a = column.axis, shift = findLSB(max(edge, 1));
  vec2 cell = vec2(t[(a + 1) % 3] >> shift, t[(a + 2) % 3] >> shift);
  return fract(0.5 + dot(cell, vec2(0.7548776662, 0.5698402910)));
}

// The cell of a request in VxgiBounceCells: `edge` × `edge` voxel columns of the level (a
// power of two, 2..8) along its projection axis, per axis and facing sign (a floor and the
// ceiling above it face opposite ways, so they fall in different cells), toroidal like the
// level.
uint vxgiBounceCell(VxgiVoxelColumn column, vec3 normal, int edge) {
  ivec3 t = vxgiWrap(column.first);
  int a = column.axis, shift = findLSB(edge), cells = clipMap.mapSize >> shift;
  int u = t[(a + 1) % 3] >> shift, v = t[(a + 2) % 3] >> shift;
  int side = normal[a] > 0.0 ? 0 : 1;
  return uint(((a * 2 + side) * cells + v) * cells + u);
}

// Whether the column is its cell's leading one: at edge / 2 − 1 in both of the projection
// plane's axes (the first of a 2×2 cell, next to the middle of a larger one, so no column of
// the cell is more than edge / 2 columns from it along either axis).
bool vxgiLeadsCell(VxgiVoxelColumn column, int edge) {
  ivec3 t = vxgiWrap(column.first);
  int a = column.axis, lead = edge / 2 - 1;
  return (t[(a + 1) % 3] & (edge - 1)) == lead && (t[(a + 2) % 3] & (edge - 1)) == lead;
}

#endif
