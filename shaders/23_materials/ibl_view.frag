#version 450
// Chapter 23's views of the image-based light, into the HDR image: the sky
// or the irradiance cube unfolded into a cross (+Y above, then -X, +Z, +X,
// -Z, then -Y below, each face seen from inside the cube), the prefiltered
// cube's six levels as panoramas (roughness 0 to 1, left to right, top row
// first), or the BRDF table (n.v along x, roughness down y; red its scale,
// green its bias).
layout(set = 0, binding = 0) uniform samplerCube sky_map;
layout(set = 0, binding = 1) uniform samplerCube irradiance_map;
layout(set = 0, binding = 2) uniform samplerCube specular_map;
layout(set = 0, binding = 3) uniform sampler2D brdf_table;
layout(push_constant) uniform View {
    uvec4 settings;  // x, y: the extent; z: 1 sky, 2 irradiance, 3 prefiltered, 4 brdf; w: levels
} view;
layout(location = 0) out vec4 radiance;

const vec3 background = vec3(0.02);

// [cross]
// Where a face's texel (s, t in -1..1, t down the page) looks, as Vulkan's
// cube map table picks a face by the largest component of the direction.
vec3 face_direction(int face, vec2 st) {
    if (face == 0) return vec3(1.0, -st.y, -st.x);   // +X
    if (face == 1) return vec3(-1.0, -st.y, st.x);   // -X
    if (face == 2) return vec3(st.x, 1.0, st.y);     // +Y
    if (face == 3) return vec3(st.x, -1.0, -st.y);   // -Y
    if (face == 4) return vec3(st.x, -st.y, 1.0);    // +Z
    return vec3(-st.x, -st.y, -1.0);                 // -Z
}

// The cross is four faces wide and three high; a cell with no face is -1.
int cross_face(ivec2 cell) {
    if (cell.y == 0) return cell.x == 1 ? 2 : -1;
    if (cell.y == 2) return cell.x == 1 ? 3 : -1;
    const int middle[4] = int[](1, 4, 0, 5);
    return middle[cell.x];
}
// [/cross]

void main() {
    const vec2 extent = vec2(view.settings.xy);
    const vec2 p = gl_FragCoord.xy;
    radiance = vec4(background, 1.0);
    if (view.settings.z == 1u || view.settings.z == 2u) {
        const float side = floor(min(extent.x / 4.0, extent.y / 3.0));
        const vec2 q = p - floor((extent - vec2(4.0, 3.0) * side) * 0.5);
        if (any(lessThan(q, vec2(0.0))) || q.x >= 4.0 * side || q.y >= 3.0 * side) return;
        const ivec2 cell = ivec2(q / side);
        const int face = cross_face(cell);
        if (face < 0) return;
        const vec3 direction = face_direction(face, (q - vec2(cell) * side) / side * 2.0 - 1.0);
        radiance.rgb = view.settings.z == 1u ? textureLod(sky_map, direction, 0.0).rgb
                                             : textureLod(irradiance_map, direction, 0.0).rgb;
    } else if (view.settings.z == 3u) {
        // Three panoramas across, two down, each twice as wide as high, with
        // a gap of one part in forty between them.
        const float width = floor(min(extent.x / 3.0, extent.y));
        const vec2 panel = vec2(width, width * 0.5);
        const vec2 q = p - floor((extent - panel * vec2(3.0, 2.0)) * 0.5);
        if (any(lessThan(q, vec2(0.0))) || q.x >= 3.0 * panel.x || q.y >= 2.0 * panel.y) return;
        const ivec2 cell = ivec2(q / panel);
        const vec2 uv = (q - vec2(cell) * panel) / panel;
        const vec2 gap = vec2(1.0 / 40.0, 1.0 / 20.0);
        if (any(lessThan(uv, gap)) || any(greaterThan(uv, 1.0 - gap))) return;
        const float level = float(cell.y * 3 + cell.x);
        if (level >= float(view.settings.w)) return;
        // Longitude across (the middle looks along -z), latitude up.
        const float longitude = (uv.x * 2.0 - 1.0) * 3.14159265;
        const float latitude = (0.5 - uv.y) * 3.14159265;
        const vec3 direction = vec3(cos(latitude) * sin(longitude), sin(latitude),
                                    -cos(latitude) * cos(longitude));
        radiance.rgb = textureLod(specular_map, direction, level).rgb;
    } else {
        const float side = floor(min(extent.x, extent.y));
        const vec2 q = p - floor((extent - vec2(side)) * 0.5);
        if (any(lessThan(q, vec2(0.0))) || any(greaterThanEqual(q, vec2(side)))) return;
        radiance.rgb = vec3(textureLod(brdf_table, q / side, 0.0).rg, 0.0);
    }
}
