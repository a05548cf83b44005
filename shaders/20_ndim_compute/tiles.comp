#version 450
// Chapter 20, --raster binned, pass 3 of 3: one workgroup per screen tile.
// It fills its tile, in shared memory, with the background; walks the lines
// of every object in its tile's list (bin.comp), the steps that fall in the
// tile only, skipping chunks of 64 lines whose box (bounds.comp) misses it;
// and writes the tile to the pixel buffer once. The words and the rule that
// picks them are raster.comp's (walk.glsl), so the picture is the same.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_memory_scope_semantics : require
#include "ndim.glsl"
#include "bins.glsl"

layout(local_size_x_id = 1) in;
// The tile's side in pixels, and the background word as the target stores it.
layout(constant_id = 0) const uint TILE = 64;
layout(constant_id = 2) const uint BACKGROUND = 0u;
layout(std430, set = 0, binding = 3) readonly buffer In { Projected projected[]; };
layout(std430, set = 0, binding = 4) readonly buffer Lines { uint ends[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Pixels { uint pixels[]; };
layout(std430, set = 0, binding = 6) readonly buffer Palette { uint palette[256]; };
layout(std430, set = 0, binding = 7) readonly buffer Objects { LineRange objects[]; };
layout(std430, set = 0, binding = 8) readonly buffer ChunkBoxes { uvec2 chunk_boxes[]; };
layout(std430, set = 0, binding = 10) readonly buffer TileRanges { uint tile_ranges[]; };
layout(std430, set = 0, binding = 11) readonly buffer TileObjects { uint tile_objects[]; };
#include "walk.glsl"

shared uint words[TILE * TILE];  // the tile, row after row
const uint BATCH = 256u;         // chunks culled at a time
shared uint chunks[BATCH];       // those of them that touch the tile
shared uint chunk_count;

// [tile-walk]
// The line's walk, the steps that land in the tile [lo, hi] only: the steps
// along the major axis within the tile's columns (or rows), narrowed to those
// whose pixel can fall in its rows (or columns), each still checked exactly.
void draw(uint line, ivec2 lo, ivec2 hi) {
    Walk w;
    if (!start_walk(projected[ends[2u * line]], projected[ends[2u * line + 1u]], w)) return;
    int first = max(w.first, lo[w.major]), last = min(w.last, hi[w.major]);
    // The minor coordinate moves `slope` pixels a step: the steps that reach
    // the tile's minor range, one step of margin each way for rounding. Left
    // to the exact check alone for lines nearly along the axis, and for ends
    // far off the screen, whose coordinates carry less precision.
    const float slope = w.d[w.minor] * w.per_pixel;
    const vec2 far = max(abs(w.p0), abs(w.p0 + w.d));
    if (abs(slope) >= 1.0 / 64.0 && max(far.x, far.y) < 16384.0) {
        const float to_lo = (float(lo[w.minor]) - w.p0[w.minor]) / slope;
        const float to_hi = (float(hi[w.minor] + 1) - w.p0[w.minor]) / slope;
        const float origin = w.p0[w.major] - 0.5;
        first = max(first, int(floor(origin + min(to_lo, to_hi))) - 1);
        last = min(last, int(ceil(origin + max(to_lo, to_hi))) + 1);
    }
    for (int i = first; i <= last; ++i) {
        float t;
        const int j = walk_minor(w, i, t);
        if (j < lo[w.minor] || j > hi[w.minor]) continue;
        const uint word = walk_word(w, t);
        const ivec2 at = (w.major == 0 ? ivec2(i, j) : ivec2(j, i)) - lo;
        const uint k = uint(at.y) * TILE + uint(at.x);
        // As raster.comp, but on shared memory: the workgroup's own tile.
        if (atomicLoad(words[k], gl_ScopeWorkgroup, gl_StorageSemanticsShared,
                       gl_SemanticsRelaxed) < word)
            atomicMax(words[k], word);
    }
}
// [/tile-walk]

void main() {
    const uvec2 tiles = (push.size + TILE - 1u) / TILE;
    const uint tile = gl_WorkGroupID.y * tiles.x + gl_WorkGroupID.x;
    const uint tile_count = tiles.x * tiles.y, lid = gl_LocalInvocationID.x;
    const uint group = gl_WorkGroupSize.x;
    // The tile's pixels, lo to hi inclusive (the last row and column of
    // tiles may stop at the image's edge).
    const ivec2 lo = ivec2(gl_WorkGroupID.xy * TILE);
    const ivec2 hi = min(lo + int(TILE) - 1, ivec2(push.size) - 1);

    // [tile]
    for (uint k = lid; k < TILE * TILE; k += group) words[k] = BACKGROUND;
    if (lid == 0u) chunk_count = 0u;
    barrier();
    // Every object in the tile's list; its chunks BATCH at a time: first
    // each invocation tests a few chunks' boxes against the tile and lists
    // those that touch it, then the invocations share out their lines, one
    // line each at a time.
    const uint list_end = tile_ranges[tile_count + tile];
    for (uint entry = tile_ranges[tile]; entry < list_end; ++entry) {
        const LineRange o = objects[tile_objects[entry]];
        for (uint base = 0u; base < o.chunk_count; base += BATCH) {
            for (uint c = base + lid; c < min(base + BATCH, o.chunk_count); c += group)
                if (box_overlaps(chunk_boxes[o.first_chunk + c], lo, hi))
                    chunks[atomicAdd(chunk_count, 1u)] = c;
            barrier();
            const uint lines = chunk_count * CHUNK;
            for (uint k = lid; k < lines; k += group) {
                const uint line = chunks[k / CHUNK] * CHUNK + k % CHUNK;
                if (line < o.line_count) draw(o.first_line + line, lo, hi);
            }
            barrier();
            if (lid == 0u) chunk_count = 0u;
            barrier();
        }
    }
    // The tile, written once: every pixel of the image belongs to one tile.
    for (uint k = lid; k < TILE * TILE; k += group) {
        const ivec2 p = lo + ivec2(k % TILE, k / TILE);
        if (all(lessThanEqual(p, hi))) pixels[uint(p.y) * push.size.x + uint(p.x)] = words[k];
    }
    // [/tile]
}
