// Chapter 17, --cull binned: the bins that carry the lights from the light
// pass (bins.comp) through the prefix sum (bin_scan.comp) to the tile pass
// (tiles.comp), and each light's rectangle of tiles. The C++ twin of the
// rectangle is light_tile_rect in common/scene/include/vkt/scene/tiles.hpp.
// Include after tiles.glsl.

// [bin-buffers]
// Set 1, bindings 7..11 (bin_pass.hpp makes them).
layout(set = 1, binding = 7, std430) buffer LightSpheres {
    vec4 light_spheres[];  // [light]: view-space centre and radius (view_sphere)
};
layout(set = 1, binding = 8, std430) buffer LightRects {
    uvec2 light_rects[];  // [light]: its tiles, x0 | x1 << 16 and y0 | y1 << 16
};
layout(set = 1, binding = 9, std430) buffer BinCounts {
    uint bin_counts[];  // [tile]: how many candidates its bin holds
};
layout(set = 1, binding = 10, std430) buffer BinOffsets {
    uint bin_offsets[];  // [tile]: where its bin starts in bin_lights
};
layout(set = 1, binding = 11, std430) buffer BinLights {
    uint bin_lights[];  // every tile's candidates (light indices), bin after bin
};
// [/bin-buffers]

// [light-rect]
// The slopes u / t of the two lines through the eye that touch a circle of
// centre (u, t) and radius r (u: x or y; t: -z, in front of the eye), from
// (u - s t)^2 = r^2 (1 + s^2). False when the circle reaches the eye's
// plane (t <= r): lines of every slope meet it.
bool tangent_slopes(float u, float t, float r, out vec2 slopes) {
    float d = (t - r) * (t + r);  // t^2 - r^2, accurate when t is near r
    if (!(t > r) || !(d > 0.0)) return false;
    float s = r * sqrt(u * u + d);
    slopes = vec2(u * t - s, u * t + s) / d;
    return true;
}

// The tiles [first, last] of an axis `pixels` long that the slopes cover
// (NDC = scale * slope; scale < 0 flips y), a pixel of margin each side so
// that rounding never loses a tile. False when they miss the screen.
bool tile_span(vec2 slopes, float scale, uint pixels, out uvec2 span) {
    vec2 ndc = vec2(min(scale * slopes.x, scale * slopes.y), max(scale * slopes.x, scale * slopes.y));
    float size = float(pixels);
    vec2 p = (ndc * 0.5 + 0.5) * size + vec2(-1.0, 1.0);
    if (!(p.y >= 0.0 && p.x <= size)) return false;
    span = uvec2(uint(max(p.x, 0.0)) / TILE_SIZE,
                 min(uint(min(p.y, size)) / TILE_SIZE, (pixels + TILE_SIZE - 1) / TILE_SIZE - 1));
    return true;
}

// The tiles a light may touch, whatever their depth: (x0, y0, x1, y1),
// empty when x0 > x1. Every tile whose side planes sphere_touches_tile
// passes lies inside; one more near the edge costs a test, never a light.
uvec4 light_tile_rect(vec3 centre, float radius, uvec2 size) {
    const uvec4 none = uvec4(1, 1, 0, 0);
    float t = -centre.z;
    if (t + radius < 0.0) return none;  // behind the eye: every tile's near end culls it
    uvec4 rect = uvec4(0, 0, (size - 1) / TILE_SIZE);  // every tile, unless the slopes say less
    vec2 slopes;
    uvec2 span;
    if (tangent_slopes(centre.x, t, radius, slopes)) {
        if (!tile_span(slopes, frame.proj[0][0], size.x, span)) return none;
        rect.xz = span;
    }
    if (tangent_slopes(centre.y, t, radius, slopes)) {
        if (!tile_span(slopes, frame.proj[1][1], size.y, span)) return none;
        rect.yw = span;
    }
    return rect;
}
// [/light-rect]
