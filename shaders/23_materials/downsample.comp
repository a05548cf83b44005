#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23's environment: one mip level of the sky from the level above.
// The centre of a texel here is the corner where four texels of the level
// above meet, so one linear sample there is their average.
layout(local_size_x = 8, local_size_y = 8) in;
#include "pbr.glsl"
#include "cube.glsl"

layout(set = 0, binding = 0) uniform samplerCube source;  // the level above: a view of it alone
layout(set = 0, binding = 1, rgba16f) uniform writeonly imageCube target;  // this level

void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    int size = imageSize(target).x;
    if (p.x >= size || p.y >= size) return;
    imageStore(target, p, vec4(textureLod(source, cube_direction(p.xy, p.z, size), 0.0).rgb, 1.0));
}
