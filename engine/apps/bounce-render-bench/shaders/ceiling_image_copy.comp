#version 460
// Storage-image bandwidth: imageLoad + imageStore of one RGBA16F texel of a 3D image per
// invocation (8 bytes read, 8 written), in 4×4×4 blocks.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0, rgba16f) readonly uniform image3D source;
layout(binding = 1, rgba16f) writeonly uniform image3D destination;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, imageSize(source)))) return;
  imageStore(destination, p, imageLoad(source, p));
}
