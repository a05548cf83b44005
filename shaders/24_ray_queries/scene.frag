#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_query : require
// Chapter 24's lighting: chapter 22's ambient plus Lambert, the Lambert part
// scaled by whether the light reaches the point, answered either by the
// shadow map or by a ray query against the scene's acceleration structure.
#include "frame.glsl"

layout(set = 0, binding = 1) uniform sampler2DShadow shadow_map;
// [tlas-binding]
layout(set = 0, binding = 2) uniform accelerationStructureEXT scene;
// [/tlas-binding]

layout(location = 0) in vec3 world;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 frag_colour;

// The shadow map's answer, 0 (shadow) to 1 (lit): nine comparisons around
// the point averaged (chapter 22's percentage-closer filtering).
float map_visibility() {
    const vec4 light_clip = frame.light_from_world * vec4(world, 1.0);
    const vec2 uv = light_clip.xy * 0.5 + 0.5;
    const vec2 texel = 1.0 / vec2(textureSize(shadow_map, 0));
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            lit += texture(shadow_map, vec3(uv + vec2(x, y) * texel, light_clip.z));
    return lit / 9.0;
}

// [float-offset]
// Waechter and Binder's start for a ray leaving a surface (Ray Tracing Gems,
// chapter 6): each coordinate moved along the normal by a number of units in
// its last place, up to 256, so the step grows with the coordinate as its
// rounding error does; within 1/32 of zero, where floats are dense, by a
// small fixed distance instead. It covers the floating-point error only.
vec3 float_offset(vec3 p, vec3 n) {
    const ivec3 steps = ivec3(256.0 * n);
    vec3 moved;
    for (int i = 0; i < 3; ++i) {
        const int step = p[i] < 0.0 ? -steps[i] : steps[i];
        moved[i] = abs(p[i]) < 1.0 / 32.0 ? p[i] + n[i] / 65536.0
                                          : intBitsToFloat(floatBitsToInt(p[i]) + step);
    }
    return moved;
}
// [/float-offset]

// [ray-start]
// Where the ray starts: ray_offset along the normal, a hundredth by default
// (--ray-offset D sets it; --ray-offset ulp uses float_offset instead, page
// 24b's comparison), both specialization constants of the pipeline.
layout(constant_id = 0) const float ray_offset = 0.01;
layout(constant_id = 1) const bool use_float_offset = false;
// [/ray-start]

// [ray-query]
// The ray query's answer, exactly 0 or 1: a ray from the point towards the
// light, started a little off the surface so that it does not hit the
// triangle it leaves. Any hit at all means shadow, so the query stops at the
// first (TerminateOnFirstHit); the ray is opaque (and so is every
// geometry), so the loop that would let the shader judge candidate hits
// (alpha-tested leaves, say) finds none to judge.
float ray_visibility(vec3 n) {
    const vec3 origin = use_float_offset ? float_offset(world, n) : world + ray_offset * n;
    rayQueryEXT query;
    rayQueryInitializeEXT(query, scene, gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsOpaqueEXT,
                          0xFF, origin, 0.0, -frame.light.xyz, 1000.0);
    while (rayQueryProceedEXT(query)) {
    }
    return rayQueryGetIntersectionTypeEXT(query, true) == gl_RayQueryCommittedIntersectionNoneEXT
               ? 1.0
               : 0.0;
}
// [/ray-query]

void main() {
    const vec3 n = normalize(world_normal);
    const float diffuse = max(dot(n, -frame.light.xyz), 0.0);
    const uint mode = frame.settings.x;
    // A surface facing away from the light is unlit either way: no ray.
    const float map = diffuse > 0.0 && mode != 1 ? map_visibility() : 1.0;
    const float ray = diffuse > 0.0 && mode != 0 ? ray_visibility(n) : 1.0;
    vec3 colour = draw.colour.rgb * (0.2 + 0.8 * diffuse * (mode == 0 ? map : ray));
    if (mode == 2) {
        // [difference]
        // The comparison: the picture in grey, red where the map darkens a
        // point the ray finds lit, blue where it lights one the ray finds in
        // shadow; fully so where the two answers differ by a third or more
        // (three of the map's nine filtered comparisons).
        const float grey = dot(colour, vec3(0.3, 0.59, 0.11));
        colour = mix(vec3(grey), vec3(1.0, 0.1, 0.1), clamp(3.0 * (ray - map), 0.0, 1.0));
        colour = mix(colour, vec3(0.1, 0.3, 1.0), clamp(3.0 * (map - ray), 0.0, 1.0));
        // [/difference]
    }
    frag_colour = vec4(colour, 1.0);
}
