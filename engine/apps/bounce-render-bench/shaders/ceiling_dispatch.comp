#version 460
// The fixed cost of a dispatch: one workgroup of one invocation that stores one word, so
// what a run of them takes is the device's cost of starting a dispatch and of the barrier
// after it, not of any computing.
layout(local_size_x = 1) in;
layout(binding = 0, std430) writeonly buffer Result { uint result[]; };
layout(push_constant) uniform Push { uint value; } pc;

void main() { result[0] = pc.value; }
