#version 450
// Chapter 20, --raster binned, pass 2 of 3: the work list. Each object's box
// (boxes.comp) is cut into pieces of at most PIECE x PIECE pixels, each small
// enough for one workgroup's shared memory: count each object's pieces, turn
// the counts into where each object's entries start (an exclusive prefix
// sum), and write one entry per piece. A few hundred objects: one workgroup.
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
    // pieces; the first invocation turns the 256 counts into where each run
    // starts; each invocation then writes its run's entries from there.
    const uint per = (objects + 255u) / 256u;
    const uint begin = min(lid * per, objects), end = min(begin + per, objects);
    uint count = 0u;
    for (uint o = begin; o < end; ++o) count += pieces(o);
    partial[lid] = count;
    barrier();
    if (lid == 0u) {
        uint run = 0u;
        for (uint k = 0u; k < 256u; ++k) {
            const uint c = partial[k];
            partial[k] = run;
            run += c;
        }
        // The tile pass's workgroups, one per entry, in rows of 65,535.
        tile_count = run;
        const uint rows = (run + 65534u) / 65535u;
        tile_groups = uvec3(rows > 1u ? 65535u : run, rows, 1u);
    }
    barrier();
    uint at = partial[lid];
    for (uint o = begin; o < end; ++o) {
        const uint n = pieces(o);
        for (uint p = 0u; p < n; ++p) tiles[at++] = uvec2(o, p);
    }
    // [/count-scan-scatter]
}
