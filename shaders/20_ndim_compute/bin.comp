#version 450
// Chapter 20, --raster binned, pass 2 of 3: the objects sorted into screen
// tiles of TILE x TILE pixels. Each object goes into the list of every tile
// its box (bounds.comp) touches: count the objects per tile, turn the counts
// into where each tile's list starts (an exclusive prefix sum), then write
// each object into its tiles' lists. A few hundred objects, a few thousand
// tiles: one workgroup does it all, with barriers between the steps.
#extension GL_GOOGLE_include_directive : require
#include "ndim.glsl"

layout(local_size_x = 256) in;
layout(constant_id = 0) const uint TILE = 64;
layout(std430, set = 0, binding = 9) readonly buffer ObjectBoxes { uvec4 object_boxes[]; };
// [0, tiles): where each tile's list starts; [tiles, 2 tiles): its count,
// then, once the lists are written, where it ends. Coherent: invocations
// read what others wrote, after a barrier.
layout(std430, set = 0, binding = 10) coherent buffer TileRanges { uint tile_ranges[]; };
layout(std430, set = 0, binding = 11) writeonly buffer TileObjects { uint tile_objects[]; };

shared uint partial[256];

// The tiles object o's box touches, t0 to t1 inclusive; false if none.
bool object_tiles(uint o, out uvec2 t0, out uvec2 t1) {
    const uvec4 box = object_boxes[o];
    const uvec2 lo = 0xffffu - box.xy, hi = box.zw;
    t0 = lo / TILE;
    t1 = hi / TILE;
    return all(lessThanEqual(lo, hi));
}

void main() {
    const uvec2 tiles = (push.size + TILE - 1u) / TILE;
    const uint tile_count = tiles.x * tiles.y, lid = gl_LocalInvocationID.x;
    const uint group = gl_WorkGroupSize.x;
    // [count]
    for (uint t = lid; t < tile_count; t += group) tile_ranges[tile_count + t] = 0u;
    memoryBarrierBuffer();
    barrier();
    for (uint o = lid; o < push.object_count; o += group) {
        uvec2 t0, t1;
        if (object_tiles(o, t0, t1))
            for (uint y = t0.y; y <= t1.y; ++y)
                for (uint x = t0.x; x <= t1.x; ++x) atomicAdd(tile_ranges[tile_count + y * tiles.x + x], 1u);
    }
    memoryBarrierBuffer();
    barrier();
    // [/count]

    // [scan]
    // Each invocation sums a run of consecutive tiles; the first invocation
    // turns the 256 sums into where each run starts; each invocation then
    // walks its run again, writing each tile's start (and, as a cursor for
    // the next step, the same value over its count).
    const uint per = (tile_count + group - 1u) / group;
    const uint begin = min(lid * per, tile_count), end = min(begin + per, tile_count);
    uint sum = 0u;
    for (uint t = begin; t < end; ++t) sum += tile_ranges[tile_count + t];
    partial[lid] = sum;
    barrier();
    if (lid == 0u) {
        uint run = 0u;
        for (uint k = 0u; k < group; ++k) {
            const uint count = partial[k];
            partial[k] = run;
            run += count;
        }
    }
    barrier();
    uint run = partial[lid];
    for (uint t = begin; t < end; ++t) {
        const uint count = tile_ranges[tile_count + t];
        tile_ranges[t] = run;
        tile_ranges[tile_count + t] = run;
        run += count;
    }
    memoryBarrierBuffer();
    barrier();
    // [/scan]

    // [scatter]
    // The same tiles as in the count, each taking the next place in its list
    // with an atomic add on its cursor; the cursors end where the lists do.
    // The order within a list depends on timing; the picture does not, since
    // each pixel keeps the largest word whatever the order.
    for (uint o = lid; o < push.object_count; o += group) {
        uvec2 t0, t1;
        if (object_tiles(o, t0, t1))
            for (uint y = t0.y; y <= t1.y; ++y)
                for (uint x = t0.x; x <= t1.x; ++x)
                    tile_objects[atomicAdd(tile_ranges[tile_count + y * tiles.x + x], 1u)] = o;
    }
    // [/scatter]
}
