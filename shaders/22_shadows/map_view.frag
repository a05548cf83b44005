#version 450
// Chapter 22's --view map: each cascade's layer of the shadow map as a
// square, side by side, nearest cascade on the left. The grey is the depth
// the light reached there, from the slice's nearest depth (black) to 1
// (white): the light looks down from above, so the floor is pale, the tops
// of the pillars darker. Texels no caster covered keep the clear value 1.0,
// drawn pale blue: the light passes them unblocked.
layout(set = 0, binding = 0) uniform sampler2DArray shadow_depth;
layout(push_constant) uniform View {
    uvec4 size;       // x, y: the target's extent; z: the cascades
    vec4 near_depth;  // each cascade's: drawn black
} view;
layout(location = 0) out vec4 frag_colour;

const vec3 cascade_colours[4] =
    vec3[](vec3(1.0, 0.3, 0.3), vec3(0.3, 1.0, 0.3), vec3(0.3, 0.5, 1.0), vec3(1.0, 1.0, 0.3));
const float frame_width = 3.0;  // pixels of the coloured frame round each square

void main() {
    const float cascades = float(view.size.z);
    const vec2 extent = vec2(view.size.xy);
    const float side = floor(min(extent.y, extent.x / cascades));
    const vec2 origin = floor((extent - vec2(side * cascades, side)) * 0.5);
    const vec2 p = gl_FragCoord.xy - origin;
    if (p.x < 0.0 || p.y < 0.0 || p.x >= side * cascades || p.y >= side) {
        frag_colour = vec4(0.1, 0.1, 0.12, 1.0);
        return;
    }
    const uint layer = min(uint(p.x / side), view.size.z - 1);
    const vec2 in_square = vec2(p.x - float(layer) * side, p.y);
    if (any(lessThan(in_square, vec2(frame_width))) ||
        any(greaterThanEqual(in_square, vec2(side - frame_width)))) {
        frag_colour = vec4(cascade_colours[layer], 1.0);
        return;
    }
    // The map's v runs down the screen, as the light's clip-space y does
    // (Vulkan's y points down): the square shows what the light sees.
    const float depth = textureLod(shadow_depth, vec3(in_square / side, float(layer)), 0.0).r;
    if (depth >= 1.0) {
        frag_colour = vec4(0.6, 0.75, 1.0, 1.0);
        return;
    }
    const float near = view.near_depth[layer];
    frag_colour = vec4(vec3(clamp((depth - near) / (1.0 - near), 0.0, 1.0)), 1.0);
}
