#version 460
// Depth of scene geometry as seen from one shadow-map layer.
#include "bounce/scene.glsl"

SCENE_VERTEX_INPUTS
SCENE_INSTANCES(0)
SCENE_DRAW_PUSH_CONSTANTS(mat4 viewProjection;)

void main() { gl_Position = draw.viewProjection * (instances[draw.instance].world * vec4(inPosition, 1.0)); }
