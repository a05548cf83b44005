#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23's environment: level 0 of the sky's cube map, made at start-up
// from a formula (no file): a blue gradient above the horizon, a bright sun
// where the key light is, and a darker ground. Radiance, as the scene pass
// writes it: the sun's disc is over a hundred times as bright as the sky.
layout(local_size_x = 8, local_size_y = 8) in;
#include "pbr.glsl"
#include "cube.glsl"

layout(set = 0, binding = 1, rgba16f) uniform writeonly imageCube target;

// [sky]
vec3 sky(vec3 d) {
    if (params.sun.w != 0.0) return vec3(1.0);  // the white furnace: 1 from everywhere
    const vec3 zenith = vec3(0.03, 0.08, 0.22), horizon = vec3(0.26, 0.28, 0.32);
    const vec3 ground = vec3(0.035, 0.03, 0.025);
    vec3 colour = d.y >= 0.0 ? mix(horizon, zenith, sqrt(d.y))
                             : mix(0.5 * horizon, ground, smoothstep(0.0, 0.15, -d.y));
    // The sun: a disc of angular radius 2.5 degrees, in the key light's direction.
    if (dot(d, params.sun.xyz) > cos(radians(2.5))) colour += vec3(40.0, 36.0, 30.0);
    return colour;
}
// [/sky]

void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);  // x, y, and z: the face
    int size = imageSize(target).x;
    if (p.x >= size || p.y >= size) return;
    imageStore(target, p, vec4(sky(cube_direction(p.xy, p.z, size)), 1.0));
}
