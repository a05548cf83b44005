#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23: a glTF metallic-roughness material, lit by two directional
// lights and a uniform sky, written as linear radiance into the HDR target.
#include "blocks.glsl"
#include "pbr.glsl"
#include "surface.glsl"

layout(location = 0) out vec4 radiance;

// [term]
// --term: 0 the whole shading (all); or one factor of the specular BRDF
// alone, written as a plain number, 1 white through --tone-map clamp.
// 1 (d): D for the key light. 2 (f): Schlick's F at v.h = n.v, the facets
// that face the eye (h = n), as a mirror shows the sky. 3 (v): the key
// light's G = 4 (n.l)(n.v) V, the share of facets both seen and lit.
// D and G are black where the key light does not reach.
layout(constant_id = 0) const int term = 0;

vec3 one_term(vec3 n, vec3 v, vec3 l, Material m) {
    float n_dot_l = dot(n, l), n_dot_v = max(dot(n, v), 1e-4);
    float alpha = max(m.roughness * m.roughness, 1e-3);
    if (term == 2) return fresnel_schlick(f0_of(m), n_dot_v);
    if (n_dot_l <= 0.0) return vec3(0.0);
    if (term == 1) return vec3(distribution_ggx(max(dot(n, normalize(v + l)), 0.0), alpha));
    return vec3(4.0 * n_dot_l * n_dot_v * visibility_smith(n_dot_l, n_dot_v, alpha));
}
// [/term]

void main() {
    float occlusion;
    vec3 emitted;
    Material m = surface_material(occlusion, emitted);

    // [shade]
    vec3 n = shading_normal(), v = normalize(frame.eye.xyz - world);
    if (!gl_FrontFacing) n = -n;  // a double-sided glTF surface seen from behind
    if (term != 0) {  // --term: one factor alone, in place of the shading
        radiance = vec4(one_term(n, v, frame.light_direction[0].xyz, m), 1.0);
        return;
    }
    vec3 colour = occlusion * environment(n, v, m, frame.sky.rgb, uint(frame.sky.w));
    // [lights]
    for (int i = 0; i < 2; ++i)
        colour += frame.light_radiance[i].rgb * brdf_cos(n, v, frame.light_direction[i].xyz, m);
    // [/lights]
    radiance = vec4(colour + emitted, 1.0);
    // [/shade]
}
