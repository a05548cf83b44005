#version 450
// Chapter 20, --raster binned, the last pass: one workgroup per entry of the
// work list (bin.comp), a tile: a piece of one object's box. It walks every
// line of the object, the steps that fall in the tile only, into the tile in
// shared memory, then merges the tile into the pixel buffer: one atomicMax
// for each pixel that a line reached, however many lines reached it. The
// words and the rule that picks them are raster.comp's (walk.glsl), so the
// picture is the same.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_memory_scope_semantics : require
#include "ndim.glsl"

layout(local_size_x_id = 1) in;
// The largest tile's side in pixels.
layout(constant_id = 0) const uint PIECE = 64;
// The transform pass's output, through its set (TransformPass::projected_binding).
layout(std430, set = 0, binding = 3) readonly buffer In { Projected projected[]; };
// Set 1, ComputeRaster's: ends_binding, pixels_binding, palette_binding.
layout(std430, set = 1, binding = 0) readonly buffer Lines { uint ends[]; };
layout(std430, set = 1, binding = 1) buffer Pixels { uint pixels[]; };
layout(std430, set = 1, binding = 2) readonly buffer Palette { uint palette[256]; };
#include "bins.glsl"
#include "walk.glsl"

shared uint words[PIECE * PIECE];  // the tile, rows PIECE words apart; 0: no line
// [tile-walk]
// The line's walk, the steps that land in the tile [lo, hi] only: the steps
// along the major axis within the tile's columns (or rows), narrowed to those
// whose pixel can fall in its rows (or columns), each still checked exactly.
void draw(uint line, ivec2 lo, ivec2 hi) {
    Walk w;
    if (!start_walk(projected[ends[2u * line]], projected[ends[2u * line + 1u]], w)) return;
    // The tile with the major axis first.
    const ivec2 lo_m = w.x_major ? lo : lo.yx, hi_m = w.x_major ? hi : hi.yx;
    int first = max(w.first, lo_m.x), last = min(w.last, hi_m.x);
    // The minor coordinate moves `slope` pixels a step: the steps that reach
    // the tile's minor range, one step of margin each way for rounding. Left
    // to the exact check alone for lines nearly along the axis, and for ends
    // far off the screen, whose coordinates carry less precision.
    const float slope = w.minor_d * w.per_pixel;
    if (abs(slope) >= 1.0 / 64.0 && w.far < 16384.0) {
        const float to_lo = (float(lo_m.y) - w.minor0) / slope;
        const float to_hi = (float(hi_m.y + 1) - w.minor0) / slope;
        const float origin = w.major0 - 0.5;
        first = max(first, int(floor(origin + min(to_lo, to_hi))) - 1);
        last = min(last, int(ceil(origin + max(to_lo, to_hi))) + 1);
    }
    for (int i = first; i <= last; ++i) {
        float t;
        const int j = walk_minor(w, i, t);
        if (j < lo_m.y || j > hi_m.y) continue;
        const uint word = walk_word(w, t);
        const ivec2 at = (w.x_major ? ivec2(i, j) : ivec2(j, i)) - lo;
        const uint k = uint(at.y) * PIECE + uint(at.x);
        // As raster.comp, but on shared memory: the workgroup's own tile.
        if (atomicLoad(words[k], gl_ScopeWorkgroup, gl_StorageSemanticsShared,
                       gl_SemanticsRelaxed) < word)
            atomicMax(words[k], word);
    }
}
// [/tile-walk]

void main() {
    // The entry: which object, which piece of its box (row after row).
    const uint entry = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (entry >= tile_count) return;  // the whole workgroup: no barrier skipped
    const uvec2 e = tiles[entry];
    ivec2 box_lo, box_hi;
    object_box(e.x, box_lo, box_hi);
    const uint across = piece_grid(box_lo, box_hi, PIECE).x;
    const ivec2 lo = box_lo + ivec2(e.y % across, e.y / across) * int(PIECE);
    const ivec2 hi = min(lo + int(PIECE) - 1, box_hi);
    const uint lid = gl_LocalInvocationID.x, group = gl_WorkGroupSize.x;

    // [tile]
    // The tile's own pixels only: a small object's tile may be much smaller
    // than PIECE x PIECE.
    const uint width = uint(hi.x - lo.x) + 1u, pixels_in_tile = width * uint(hi.y - lo.y + 1);
    for (uint k = lid; k < pixels_in_tile; k += group) words[k / width * PIECE + k % width] = 0u;
    barrier();
    // Every line of the object, shared out among the invocations.
    const uvec2 lines = object_lines[e.x];  // first, count
    for (uint k = lid; k < lines.y; k += group) draw(lines.x + k, lo, hi);
    barrier();
    // The merge: the image was filled with the background, and tiles of
    // objects that overlap reach the same pixels, so each pixel a line
    // reached gets one look-first atomicMax, as in raster.comp.
    for (uint k = lid; k < pixels_in_tile; k += group) {
        const uint row = k / width, column = k % width;
        const uint word = words[row * PIECE + column];
        if (word == 0u) continue;
        const uint at = (uint(lo.y) + row) * push.size.x + uint(lo.x) + column;
        if (atomicLoad(pixels[at], gl_ScopeDevice, gl_StorageSemanticsBuffer,
                       gl_SemanticsRelaxed) < word)
            atomicMax(pixels[at], word);
    }
    // [/tile]
}
