// Chapter 20: one line's walk, shared by both compute rasterisers
// (raster.comp, one line at a time over the whole image, and tiles.comp, one
// tile at a time). Both compute every pixel and every colour word with these
// functions, the same operations in the same order, so the two pictures agree
// to the bit. Needs ndim.glsl's push constants and a palette[] buffer.

// [walk]
// Clip space to pixels, then one step per pixel along the major axis: at each
// pixel centre c on that axis, the line's other coordinate picks the pixel.
// The last pixel is left to the next line (half-open, like the hardware's
// lines), and the walk is clamped to the image.
struct Walk {
    vec2 p0, d;           // the first end in pixels; the second minus the first
    int major, minor;     // 0: x, 1: y
    int first, last;      // the steps along the major axis, inclusive
    float per_pixel;      // t's step from one pixel to the next
    float depth0, depth1; // the ends' depths, -1..1
};

// False where there is nothing to walk: an end behind the eye, or a line of
// length 0 along its major axis (it covers no pixel centre).
bool start_walk(Projected a, Projected b, out Walk w) {
    if ((a.colour >> 24) == 0u || (b.colour >> 24) == 0u) return false;
    const vec2 size = vec2(push.size);
    w.p0 = (a.xy * 0.5 + 0.5) * size;
    const vec2 p1 = (b.xy * 0.5 + 0.5) * size;
    w.d = p1 - w.p0;
    w.major = abs(w.d.x) >= abs(w.d.y) ? 0 : 1;
    w.minor = 1 - w.major;
    if (w.d[w.major] == 0.0) return false;
    const bool forward = w.d[w.major] > 0.0;
    const float start = forward ? w.p0[w.major] : p1[w.major];
    const float end = forward ? p1[w.major] : w.p0[w.major];
    w.first = max(int(ceil(start - 0.5)), 0);
    w.last = min(int(ceil(end - 0.5)), int(push.size[w.major])) - 1;
    w.per_pixel = 1.0 / w.d[w.major];
    w.depth0 = a.depth;
    w.depth1 = b.depth;
    return true;
}

// Step i (a pixel column, or row, along the major axis): the pixel along the
// minor axis, which may lie outside the image, and t, 0 at a and 1 at b.
int walk_minor(Walk w, int i, out float t) {
    t = (float(i) + 0.5 - w.p0[w.major]) * w.per_pixel;
    return int(floor(w.p0[w.minor] + t * w.d[w.minor]));
}

// The word at t: the depth t = -1..1 as level 1..255 (0 is the background),
// looked up in the palette.
uint walk_word(Walk w, float t) {
    const float depth = clamp(0.5 + 0.5 * mix(w.depth0, w.depth1, t), 0.0, 1.0);
    return palette[1u + uint(depth * 254.0 + 0.5)];
}
// [/walk]
