// Chapter 24's uniform block (set 0, binding 0), as chapters/24_ray_queries/
// main.cpp's FrameBlock lays it out (std140: every member 16-byte aligned).
layout(set = 0, binding = 0) uniform Frame {
    mat4 clip_from_world;
    mat4 light_from_world;  // the shadow map's light clip space
    vec4 light;             // xyz: the direction the light travels
    uvec4 settings;         // x: 0 shadow map, 1 ray query, 2 both compared
} frame;

layout(push_constant) uniform Draw {
    mat4 world_from_object;
    vec4 colour;
} draw;
