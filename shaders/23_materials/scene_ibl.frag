#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23 under the environment (--sky environment): the same surface as
// scene.frag, lit by two directional lights and by image-based light, the
// split sum's three images (set 2) read in place of the sampled sky.
#include "blocks.glsl"
#include "pbr.glsl"
#include "surface.glsl"

layout(set = 2, binding = 1) uniform samplerCube irradiance_map;  // cosine-weighted mean radiance
layout(set = 2, binding = 2) uniform samplerCube specular_map;    // one level per roughness step
layout(set = 2, binding = 3) uniform sampler2D brdf_lut;          // (A, B) at (n.v, roughness)

layout(location = 0) out vec4 radiance;

// [image-based-light]
// The split sum: the lobe's light, the prefiltered sky in the mirror
// direction at this roughness's level, times the lobe's share of it,
// F0 A + B. The diffuse part gets what the specular lobe did not reflect.
vec3 image_based_light(vec3 n, vec3 v, Material m) {
    float n_dot_v = max(dot(n, v), 1e-4);
    vec2 ab = texture(brdf_lut, vec2(n_dot_v, m.roughness)).rg;
    vec3 specular_share = f0_of(m) * ab.x + ab.y;
    vec3 diffuse = texture(irradiance_map, n).rgb * diffuse_of(m) * (1.0 - specular_share);
    float level = m.roughness * float(textureQueryLevels(specular_map) - 1);
    vec3 specular = textureLod(specular_map, reflect(-v, n), level).rgb * specular_share;
    return diffuse + specular;
}
// [/image-based-light]

void main() {
    float occlusion;
    vec3 emitted;
    Material m = surface_material(occlusion, emitted);

    // [shade-ibl]
    vec3 n = shading_normal(), v = normalize(frame.eye.xyz - world);
    if (!gl_FrontFacing) n = -n;
    vec3 colour = occlusion * frame.sky.rgb * image_based_light(n, v, m);
    for (int i = 0; i < 2; ++i)
        colour += frame.light_radiance[i].rgb * brdf_cos(n, v, frame.light_direction[i].xyz, m);
    radiance = vec4(colour + emitted, 1.0);
    // [/shade-ibl]
}
