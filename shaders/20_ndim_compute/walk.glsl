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
    bool x_major;         // the major axis: x, or y
    float major0, minor0; // the first end, in pixels along each axis
    float minor_d;        // the second end's minor coordinate minus the first's
    float per_pixel;      // t's step from one pixel to the next along the major axis
    int first, last;      // the steps along the major axis, inclusive
    float depth0, depth1; // the ends' depths, -1..1
    float far;            // the largest coordinate of either end, in pixels
};

// False where there is nothing to walk: an end behind the eye, or a line of
// length 0 along its major axis (it covers no pixel centre).
bool start_walk(Projected a, Projected b, out Walk w) {
    if ((a.colour >> 24) == 0u || (b.colour >> 24) == 0u) return false;
    const vec2 size = vec2(push.size);
    const vec2 p0 = (a.xy * 0.5 + 0.5) * size, p1 = (b.xy * 0.5 + 0.5) * size, d = p1 - p0;
    w.x_major = abs(d.x) >= abs(d.y);
    // The ends with the major axis first.
    const vec2 q0 = w.x_major ? p0 : p0.yx, q1 = w.x_major ? p1 : p1.yx, e = q1 - q0;
    if (e.x == 0.0) return false;
    const float start = min(q0.x, q1.x), end = max(q0.x, q1.x);
    w.major0 = q0.x;
    w.minor0 = q0.y;
    w.minor_d = e.y;
    w.first = max(int(ceil(start - 0.5)), 0);
    w.last = min(int(ceil(end - 0.5)), int(w.x_major ? push.size.x : push.size.y)) - 1;
    w.per_pixel = 1.0 / e.x;
    w.depth0 = a.depth;
    w.depth1 = b.depth;
    const vec2 far = max(abs(p0), abs(p1));
    w.far = max(far.x, far.y);
    return true;
}

// Step i (a pixel column, or row, along the major axis): the pixel along the
// minor axis, which may lie outside the image, and t, 0 at a and 1 at b.
int walk_minor(Walk w, int i, out float t) {
    t = (float(i) + 0.5 - w.major0) * w.per_pixel;
    return int(floor(w.minor0 + t * w.minor_d));
}

// The word at t: the depth t = -1..1 as level 1..255 (0 is the background),
// looked up in the palette.
uint walk_word(Walk w, float t) {
    const float depth = clamp(0.5 + 0.5 * mix(w.depth0, w.depth1, t), 0.0, 1.0);
    return palette[1u + uint(depth * 254.0 + 0.5)];
}
// [/walk]
