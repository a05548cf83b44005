#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23: a glTF metallic-roughness material, lit by two directional
// lights and a uniform sky, written as linear radiance into the HDR target.
#include "blocks.glsl"
#include "pbr.glsl"
#include "surface.glsl"

layout(location = 0) out vec4 radiance;

void main() {
    float occlusion;
    vec3 emitted;
    Material m = surface_material(occlusion, emitted);

    // [shade]
    vec3 n = shading_normal(), v = normalize(frame.eye.xyz - world);
    if (!gl_FrontFacing) n = -n;  // a double-sided glTF surface seen from behind
    vec3 colour = occlusion * environment(n, v, m, frame.sky.rgb, uint(frame.sky.w));
    for (int i = 0; i < 2; ++i)
        colour += frame.light_radiance[i].rgb * brdf_cos(n, v, frame.light_direction[i].xyz, m);
    radiance = vec4(colour + emitted, 1.0);
    // [/shade]
}
