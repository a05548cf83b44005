// Chapter 20, --raster binned: what its passes (transform_boxes.comp, bin.comp,
// tiles.comp) share. Needs ndim.glsl.

// [bins]
// Per object: its lines in the line list (built once), and its box on the
// screen in pixels (the transform pass, each frame), stored as (0xffff - lo.x,
// 0xffff - lo.y, hi.x, hi.y) so that every part grows with the box and
// atomicMax merges boxes, from all zeros: an empty box. Set 2, BinnedRaster's:
// object_lines_binding, boxes_binding, tiles_binding.
layout(std430, set = 2, binding = 0) readonly buffer ObjectLines { uvec2 object_lines[]; };
layout(std430, set = 2, binding = 1) buffer Boxes { uvec4 boxes[]; };
// The work list (bin.comp): one tile per entry, a piece of at most PIECE x
// PIECE pixels of one object's box, and the tile pass's indirect dispatch.
layout(std430, set = 2, binding = 2) buffer Tiles {
    uvec3 tile_groups;  // VkDispatchIndirectCommand
    uint tile_count;
    uvec2 tiles[];      // (object, piece)
};
// [/bins]

// Object o's box, lo to hi inclusive; false if empty.
bool object_box(uint o, out ivec2 lo, out ivec2 hi) {
    const uvec4 box = boxes[o];
    lo = ivec2(0xffffu - box.xy);
    hi = ivec2(box.zw);
    return all(lessThanEqual(lo, hi));
}

// [vertex-box]
// A line lies between its ends, so the box of an object's visible vertices
// holds every line of it that is drawn (lines with an end behind the eye are
// not). The walk (walk.glsl) picks pixels within one pixel of the line, give
// or take rounding: a pixel of slack each way, more for a vertex far off the
// screen, whose coordinates carry less precision. An empty box is lo = size,
// hi = -1: min and max leave it.
void vertex_box(Projected p, inout ivec2 lo, inout ivec2 hi) {
    if ((p.colour >> 24) == 0u) return;
    const ivec2 size = ivec2(push.size);
    const vec2 at = (p.xy * 0.5 + 0.5) * vec2(size);
    const float slack = 1.0 + max(abs(at.x), abs(at.y)) / 1048576.0;
    lo = min(lo, max(ivec2(clamp(floor(at - slack), -1.0, 65535.0)), 0));
    hi = max(hi, min(ivec2(clamp(floor(at + slack), -1.0, 65535.0)), size - 1));
}
// [/vertex-box]

// How many pieces of PIECE x PIECE pixels cover the box, across and down.
uvec2 piece_grid(ivec2 lo, ivec2 hi, uint piece) { return (uvec2(hi - lo) + piece) / piece; }
