#version 450
// Chapter 22's lighting: one directional light, ambient plus Lambert, the
// Lambert part scaled by how much of the light reaches the point.
layout(set = 0, binding = 0) uniform Frame {
    mat4 clip_from_world;
    mat4 light_from_world[4];
    vec4 splits;
    vec4 eye;
    vec4 forward;
    vec4 light;
    uvec4 settings;
} frame;
layout(set = 0, binding = 1) uniform sampler2DArrayShadow shadow_map;

layout(push_constant) uniform Draw {
    mat4 world_from_object;
    vec4 colour;
} draw;

layout(location = 0) in vec3 world;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 frag_colour;

const vec3 cascade_colours[4] =
    vec3[](vec3(1.0, 0.3, 0.3), vec3(0.3, 1.0, 0.3), vec3(0.3, 0.5, 1.0), vec3(1.0, 1.0, 0.3));

void main() {
    // [cascade]
    // The cascade: the first whose far distance lies beyond this point.
    const float distance = dot(world - frame.eye.xyz, frame.forward.xyz);
    uint cascade = 0;
    for (uint i = 0; i + 1 < frame.settings.x; ++i)
        if (distance > frame.splits[i]) cascade = i + 1;
    // [/cascade]

    // [pcf]
    // Where the point lands in that cascade's map, and its depth from the
    // light. Each texture() call compares: 1 where the point's depth is at
    // most the map's (nothing nearer the light), else 0. Percentage-closer
    // filtering averages nine such answers around the point, a soft edge
    // three texels wide instead of a staircase.
    const vec4 light_clip = frame.light_from_world[cascade] * vec4(world, 1.0);
    const vec2 uv = light_clip.xy * 0.5 + 0.5;
    const vec2 texel = 1.0 / vec2(textureSize(shadow_map, 0).xy);
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            lit += texture(shadow_map, vec4(uv + vec2(x, y) * texel, float(cascade), light_clip.z));
    lit /= 9.0;
    // [/pcf]

    const vec3 n = normalize(world_normal);
    const float diffuse = max(dot(n, -frame.light.xyz), 0.0);
    vec3 colour = draw.colour.rgb * (0.2 + 0.8 * diffuse * lit);
    if (frame.settings.y != 0) colour = mix(colour, cascade_colours[cascade], 0.45);
    frag_colour = vec4(colour, 1.0);
}
