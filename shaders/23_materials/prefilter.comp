#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23's prefiltered specular cube: one mip level per roughness step,
// each texel the sky seen through GGX's lobe of that roughness around it.
layout(local_size_x = 8, local_size_y = 8) in;
#include "pbr.glsl"
#include "cube.glsl"

layout(set = 0, binding = 0) uniform samplerCube source;  // the sky, every mip level
layout(set = 0, binding = 1, rgba16f) uniform writeonly imageCube target;  // one level

// [prefilter]
// The split sum's first factor: the sky averaged over the directions l that
// GGX's half vectors reflect the view into, weighted by n.l, with the
// assumption that n = v = r (the lobe seen head on). A half vector drawn
// with density D (n.h) gives l the density D (n.h) / (4 v.h) = D / 4 here.
void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    int size = imageSize(target).x;
    if (p.x >= size || p.y >= size) return;
    vec3 n = cube_direction(p.xy, p.z, size);
    // [prefilter-loop]
    mat3 frame = frame_towards(n, n);
    float alpha = max(params.roughness * params.roughness, 1e-3);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (uint i = 0u; i < params.samples; ++i) {
        vec2 u = hammersley(i, params.samples);
        float phi = 2.0 * PI * u.y;
        float cos_h = sqrt((1.0 - u.x) / (1.0 + (alpha * alpha - 1.0) * u.x));
        float sin_h = sqrt(max(0.0, 1.0 - cos_h * cos_h));
        vec3 h = frame * vec3(sin_h * cos(phi), sin_h * sin(phi), cos_h);
        vec3 l = 2.0 * cos_h * h - n;
        float n_dot_l = dot(n, l);
        if (n_dot_l <= 0.0) continue;
        float pdf = distribution_ggx(cos_h, alpha) / 4.0;
        sum += textureLod(source, l, source_lod(pdf, params.samples)).rgb * n_dot_l;
        weight += n_dot_l;
    }
    // [/prefilter-loop]
    imageStore(target, p, vec4(sum / weight, 1.0));
}
// [/prefilter]
