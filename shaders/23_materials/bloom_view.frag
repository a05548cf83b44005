#version 450
// Chapter 23's view of the bloom's chain (--view bloom), drawn into the HDR
// image in place of the scene: twelve panels, three across and four down.
// The top two rows are the way down, levels 0 to 5 as the halvings left them
// (a copy made before the way up adds to them); the bottom two rows are the
// same levels after the way up. Each level fills a panel of level 0's shape,
// one texel to a block of pixels, so that the coarse levels show their texels.
layout(set = 0, binding = 0) uniform sampler2D down_levels;  // the copy of the way down
layout(set = 0, binding = 1) uniform sampler2D up_levels;    // the chain itself, after the way up
layout(push_constant) uniform View {
    uvec4 settings;  // x, y: the extent; z: the chain's levels
} view;
layout(location = 0) out vec4 radiance;

const vec3 background = vec3(0.02);
const float gap = 0.025;  // of a panel's width and height, on each side

void main() {
    const vec2 extent = vec2(view.settings.xy);
    const int levels = int(view.settings.z);
    radiance = vec4(background, 1.0);
    // Panels of level 0's shape, as large as three across and four down allow.
    const vec2 size0 = vec2(textureSize(up_levels, 0));
    const vec2 panel = floor(size0 * min(extent.x / (3.0 * size0.x), extent.y / (4.0 * size0.y)));
    const vec2 q = gl_FragCoord.xy - floor((extent - panel * vec2(3.0, 4.0)) * 0.5);
    if (any(lessThan(q, vec2(0.0))) || any(greaterThanEqual(q, panel * vec2(3.0, 4.0)))) return;
    const ivec2 cell = ivec2(q / panel);
    const vec2 uv = ((q - vec2(cell) * panel) / panel - gap) / (1.0 - 2.0 * gap);
    const int level = (cell.y % 2) * 3 + cell.x;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))) || level >= levels)
        return;
    const ivec2 texel = ivec2(uv * vec2(textureSize(up_levels, level)));
    if (cell.y < 2) {
        radiance.rgb = texelFetch(down_levels, texel, level).rgb;
    } else {
        // The way up leaves in level k the sum of levels k to 5, each blurred:
        // divided by their number, it is their mean, as bright as the scene
        // (the tone-mapping pass divides level 0 by all six the same way).
        radiance.rgb = texelFetch(up_levels, texel, level).rgb / float(levels - level);
    }
}
