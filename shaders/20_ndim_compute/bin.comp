#version 450
// Chapter 20, --raster binned, after the transform pass: the work list. Each
// object's box (transform_boxes.comp) is cut into pieces of at most PIECE x
// PIECE pixels, each small enough for one workgroup's shared memory: count
// each object's pieces, turn the counts into where each object's entries
// start (a prefix sum), and write one entry per piece. A few hundred objects: one workgroup.
#extension GL_GOOGLE_include_directive : require
#include "ndim.glsl"

layout(local_size_x = 256) in;
layout(constant_id = 0) const uint PIECE = 64;
#include "bins.glsl"

shared uint partial[256];

uint pieces(uint o) {
    ivec2 lo, hi;
    if (!object_box(o, lo, hi)) return 0u;
    const uvec2 grid = piece_grid(lo, hi, PIECE);
    return grid.x * grid.y;
}

void main() {
    const uint lid = gl_LocalInvocationID.x, objects = push.object_count;
    // [count-scan-scatter]
    // Each invocation takes a run of consecutive objects and counts their
    // pieces; the counts become where each run starts (a prefix sum); each
    // invocation then writes its run's entries from there.
    const uint per = (objects + 255u) / 256u;
    const uint begin = min(lid * per, objects), end = min(begin + per, objects);
    uint count = 0u;
    for (uint o = begin; o < end; ++o) count += pieces(o);
    // The counts' running sums, in eight steps of a scan: after the step
    // that adds the count `step` places back, each entry holds the sum of
    // the 2 * step counts up to and including its own.
    partial[lid] = count;
    barrier();
    for (uint step = 1u; step < 256u; step *= 2u) {
        const uint before = lid >= step ? partial[lid - step] : 0u;
        barrier();
        partial[lid] += before;
        barrier();
    }
    if (lid == 0u) {
        // The tile pass's workgroups, one per entry, in rows of 65,535.
        const uint total = partial[255];
        tile_count = total;
        const uint rows = (total + 65534u) / 65535u;
        tile_groups = uvec3(rows > 1u ? 65535u : total, rows, 1u);
    }
    uint at = partial[lid] - count;  // where this run's entries start
    for (uint o = begin; o < end; ++o) {
        const uint n = pieces(o);
        for (uint p = 0u; p < n; ++p) tiles[at++] = uvec2(o, p);
    }
    // [/count-scan-scatter]
}
