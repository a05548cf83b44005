// Chapter 17: lighting one pixel from its tile's list. The includer defines
// TILE_LIGHT(i), the i-th light of the tile's list: a storage buffer for the
// fragment pass, shared memory for the compute pass. Otherwise this is
// chapter 16's lighting.frag, with shade_all's loop over the list.

const vec3 background = vec3(0.02, 0.02, 0.04);

// Blue (no lights) through cyan, green and yellow to red (1,024 and more),
// on a log scale: 1, 31 and 1023 lights lie at 0.1, 0.5 and 1.
vec3 heat_ramp(uint count) {
    float t = min(log2(1.0 + float(count)) / log2(1.0 + 1024.0), 1.0);
    return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0),
                      1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}

// [shade-tile]
// `pixel` of a `size` screen; its tile's list holds `count` lights of the
// `found` that touch the tile (count = min(found, MAX_TILE_LIGHTS)).
vec3 shade_tile(ivec2 pixel, uvec2 size, uint count, uint found, int view) {
    float depth = texelFetch(gbuffer_depth, pixel, 0).r;
    vec3 albedo = texelFetch(gbuffer_base_colour, pixel, 0).rgb;
    if (view == VIEW_HEAT) {
        // Overflowing tiles are white; tile borders are darker, so the grid shows.
        vec3 heat = found > MAX_TILE_LIGHTS ? vec3(1.0) : heat_ramp(found);
        vec3 colour = 0.25 * albedo + 0.75 * heat;
        bool border = any(equal(uvec2(pixel) % TILE_SIZE, uvec2(0)));
        return border ? 0.5 * colour : colour;
    }
    if (depth == 1.0) return background;
    vec3 normal = oct_decode(texelFetch(gbuffer_normal, pixel, 0).rg);
    vec4 params = texelFetch(gbuffer_params, pixel, 0);
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec4 world = frame.inverse_view_proj * vec4(ndc, depth, 1.0);
    vec3 position = world.xyz / world.w;
    Material m = Material(albedo, params.r, round(params.g * 255.0));

    vec3 n = normalize(normal);
    vec3 v = normalize(frame.camera_position - position);
    vec3 colour = frame.ambient * m.albedo;
    for (uint i = 0; i < count; ++i) {  // the tile's lights only
        // Most of the list does not reach this pixel: read a light's position
        // and radius first, and the rest only for the few that do.
        uint j = TILE_LIGHT(i);
        if (distance(lights[j].position, position) >= lights[j].radius) continue;
        colour += shade_point_light(position, n, v, m.albedo, lights[j], FALLOFF_WINDOWED,
                                    vec3(1.0, 0.0, 0.0), m.specular, m.shininess);
    }
    return colour;
}
// [/shade-tile]
