// Chapter 23's image-based light, made in compute at start-up: what every
// step shares (chapters/23_materials/environment.hpp records them). Include
// after pbr.glsl.

// The push constants of every step (EnvironmentPush in environment.hpp).
layout(push_constant) uniform Step {
    vec4 sun;           // xyz: towards the sun; w: 1 for the white furnace's sky
    float roughness;    // the specular level being made
    uint samples;       // per texel
    float source_size;  // texels along a side of the sky's level 0
    float pad;
} params;

// [cube-direction]
// The direction through the centre of texel p of face `face` of a cube map
// whose faces are size x size texels: Vulkan's table of faces (+X, -X, +Y,
// -Y, +Z, -Z), each face's s and t running from -1 to 1. A compute shader
// writes a cube by texel and reads it by direction, so this table must be
// the one the sampler uses.
vec3 cube_direction(ivec2 p, int face, int size) {
    vec2 st = (vec2(p) + 0.5) / float(size) * 2.0 - 1.0;
    float s = st.x, t = st.y;
    vec3 d = face == 0 ? vec3(1.0, -t, -s)
           : face == 1 ? vec3(-1.0, -t, s)
           : face == 2 ? vec3(s, 1.0, t)
           : face == 3 ? vec3(s, -1.0, -t)
           : face == 4 ? vec3(s, -t, 1.0)
                       : vec3(-s, -t, -1.0);
    return normalize(d);
}
// [/cube-direction]

// [source-lod]
// Filtered importance sampling: a sample drawn with density `pdf` (per unit
// of solid angle), one of `count`, stands for about 1 / (count pdf) of the
// sphere. It reads the sky's mip level whose texels cover about that much
// (each level's texel covers four times the solid angle of the level above),
// so that it averages what lies between it and its neighbours instead of
// landing on a bright texel or missing it; + 1 blurs one level more, which
// hides the pattern of the fixed samples.
float source_lod(float pdf, uint count) {
    float sample_angle = 1.0 / (float(count) * pdf);
    float texel_angle = 4.0 * PI / (6.0 * params.source_size * params.source_size);
    return max(0.5 * log2(sample_angle / texel_angle) + 1.0, 0.0);
}
// [/source-lod]
