#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23's diffuse irradiance cube: for every normal n, the sky's
// radiance averaged over the hemisphere around n, weighted by the cosine.
layout(local_size_x = 8, local_size_y = 8) in;
#include "pbr.glsl"
#include "cube.glsl"

layout(set = 0, binding = 0) uniform samplerCube source;  // the sky, every mip level
layout(set = 0, binding = 1, rgba16f) uniform writeonly imageCube target;

// [irradiance]
// (1 / pi) * integral of L(l) (n.l) dl, the irradiance divided by pi (the
// map is usually just called the irradiance): drawn with density n.l / pi (a
// cosine-distributed direction), each sample weighs exactly L(l), and the
// sum is a plain mean. A Lambertian surface of colour c under this sky sends
// back c times it.
void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    int size = imageSize(target).x;
    if (p.x >= size || p.y >= size) return;
    vec3 n = cube_direction(p.xy, p.z, size);
    mat3 frame = frame_towards(n, n);
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < params.samples; ++i) {
        vec2 u = hammersley(i, params.samples);
        float phi = 2.0 * PI * u.y, r = sqrt(u.x), n_dot_l = sqrt(1.0 - u.x);
        vec3 l = frame * vec3(r * cos(phi), r * sin(phi), n_dot_l);
        sum += textureLod(source, l, source_lod(n_dot_l / PI, params.samples)).rgb;
    }
    imageStore(target, p, vec4(sum / float(params.samples), 1.0));
}
// [/irradiance]
