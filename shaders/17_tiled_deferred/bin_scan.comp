#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 17, --cull binned: the prefix sum between the light pass's count and
// its fill, in one workgroup. Each tile's bin starts where the bins before it
// end: bin_offsets[t] = bin_counts[0] + ... + bin_counts[t - 1] (an exclusive
// scan). The counts go back to 0, for the fill to count again.
#define TILE_WRITER
#include "tiles.glsl"
#include "bins.glsl"

layout(local_size_x = 256) in;

shared uint sums[256];

// [scan]
void main() {
    uvec2 size = uvec2(textureSize(gbuffer_depth, 0));
    uint tiles = ((size.x + TILE_SIZE - 1) / TILE_SIZE) * ((size.y + TILE_SIZE - 1) / TILE_SIZE);
    // Invocation k takes a run of consecutive tiles and sums their counts...
    uint k = gl_LocalInvocationIndex;
    uint run = (tiles + 255) / 256, first = min(k * run, tiles), end = min(first + run, tiles);
    uint sum = 0;
    for (uint t = first; t < end; ++t) sum += bin_counts[t];
    sums[k] = sum;
    memoryBarrierShared();
    barrier();
    // ...the 256 sums are scanned in shared memory, in 8 steps: after the
    // step of `stride`, sums[k] holds the sum of up to 2 * stride runs ending at k...
    for (uint stride = 1; stride < 256; stride *= 2) {
        uint before = k >= stride ? sums[k - stride] : 0;
        memoryBarrierShared();
        barrier();
        sums[k] += before;
        memoryBarrierShared();
        barrier();
    }
    // ...and each invocation writes its run's starts, from the sum of the runs before it.
    uint offset = sums[k] - sum;
    for (uint t = first; t < end; ++t) {
        uint count = bin_counts[t];
        bin_offsets[t] = offset;
        bin_counts[t] = 0;
        offset += count;
    }
    if (k == 255) {  // for the CPU: what the bins need, and what they have
        stats.binned_entries = sums[255];
        stats.binned_budget = bin_lights.length();
    }
}
// [/scan]
