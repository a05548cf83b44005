// Chapter 20, --raster binned: what its three passes (bounds.comp, bin.comp,
// tiles.comp) share.

// [line-range]
// Each object's lines, in chunks of CHUNK lines: its first line in the line
// list (main.cpp's index buffer), how many, and where its chunks' boxes start
// in the list of every chunk's box. Built once on the CPU.
struct LineRange {
    uint first_line, line_count;
    uint first_chunk, chunk_count;  // chunk_count = ceil(line_count / CHUNK)
};
const uint CHUNK = 64u;
// [/line-range]

// A box of pixels, lo to hi inclusive, packed in two words (x | y << 16); lo
// above hi marks it empty. The tile pass reads one box per chunk.
uvec2 pack_box(ivec2 lo, ivec2 hi) {
    if (any(greaterThan(lo, hi))) return uvec2(0xffffffffu, 0u);
    return uvec2(uint(lo.x) | uint(lo.y) << 16, uint(hi.x) | uint(hi.y) << 16);
}
bool box_overlaps(uvec2 box, ivec2 lo, ivec2 hi) {
    const ivec2 box_lo = ivec2(box.x & 0xffffu, box.x >> 16), box_hi = ivec2(box.y & 0xffffu, box.y >> 16);
    return all(lessThanEqual(box_lo, hi)) && all(greaterThanEqual(box_hi, lo));
}
