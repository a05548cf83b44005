// Chapter 20, --raster binned: what its three passes (boxes.comp, bin.comp,
// tiles.comp) share. Needs ndim.glsl.

// [bins]
// Per object: its lines in the line list (built once), and its box on the
// screen in pixels (boxes.comp, each frame), stored as (0xffff - lo.x,
// 0xffff - lo.y, hi.x, hi.y) so that every part grows with the box and
// atomicMax merges boxes, from all zeros: an empty box.
layout(std430, set = 0, binding = 7) readonly buffer ObjectLines { uvec2 object_lines[]; };
layout(std430, set = 0, binding = 8) buffer Boxes { uvec4 boxes[]; };
// The work list (bin.comp): one tile per entry, a piece of at most PIECE x
// PIECE pixels of one object's box, and the tile pass's indirect dispatch.
layout(std430, set = 0, binding = 9) buffer Tiles {
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

// How many pieces of PIECE x PIECE pixels cover the box, across and down.
uvec2 piece_grid(ivec2 lo, ivec2 hi, uint piece) { return (uvec2(hi - lo) + piece) / piece; }
