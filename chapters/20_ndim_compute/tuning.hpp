#pragma once
// How chapter 20's passes are shaped for the device they run on: chosen once
// at start-up, in one place, and printed on the first line after the device's
// ("20_ndim_compute: tuned for a GPU: ..."). A GPU runs thousands of
// invocations at once and hides memory latency by switching between them; a
// CPU device such as lavapipe runs each "invocation" as one SIMD lane of a
// core, so fewer, fatter invocations and fewer barriers serve it better. The
// measurements behind each figure are in the book's performance part
// (perf_20_ndim_compute.md), not here.

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace ch20 {

struct Tuning {
    bool cpu_device = false;  // invocations are SIMD lanes of CPU cores
    // The transform pass (transform.glsl): invocations per workgroup, the
    // vertices each transforms, and whether each keeps its own copy of the
    // matrix (OWN_COPY) rather than sharing one per workgroup.
    uint32_t transform_group = 128;
    uint32_t vertices_per_lane = 1;
    VkBool32 own_matrix_copy = VK_FALSE;
    // The compute rasteriser: about how many invocations to launch in all; it
    // gives each line as many lanes (1 to 32) as fit in this.
    uint64_t raster_invocations = uint64_t(1) << 18;
    // The compute rasteriser looks at a pixel (an atomic load) before its
    // atomicMax, so that a pixel a nearer line holds costs no write, in
    // scenes of at least this many lines. On a CPU device an atomic is a loop
    // over the SIMD lanes and the look a second such loop: it pays only where
    // lines overlap so densely that most writes would lose anyway.
    uint64_t raster_look_from_lines = 0;
    // The binned rasteriser: invocations sharing out one tile's lines.
    uint32_t tile_group = 1024;
    // --to-target auto: store the pixels with a compute pass (else copy them).
    bool store_to_target = true;

    static Tuning for_device(const VkPhysicalDeviceProperties& properties) {
        Tuning t;
        t.cpu_device = properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
        // [for-device]
        if (t.cpu_device) {
            t.transform_group = 64;
            t.vertices_per_lane = 16;
            t.own_matrix_copy = VK_TRUE;
            t.raster_invocations = uint64_t(1) << 12;  // enough to keep every core busy
            t.raster_look_from_lines = 4000000;        // 250 12-cubes (6.1 million), not 11
            t.tile_group = 8;                          // one SIMD vector: no switching at barriers
            t.store_to_target = false;                 // a copy is a memcpy there
        }
        // [/for-device]
        t.tile_group = std::min(t.tile_group, properties.limits.maxComputeWorkGroupInvocations);
        return t;
    }

    // [auto-raster]
    // --raster auto (the default): the rasteriser that drew the chapter's
    // scenes fastest on each kind of device (the performance part has the
    // measurements). On a CPU device the compute rasteriser, in every scene:
    // the graphics pipeline's lines and the binned tiles both cost more
    // there. On a GPU the binned one from 100,000 lines on (250 7-cubes,
    // 112,000 lines, and more; 250 6-cubes are 48,000), where a tile gathers
    // enough lines to pay for the binning; below that, and where the device
    // cannot bin, the compute one.
    std::string auto_raster(uint64_t lines, bool can_bin) const {
        if (cpu_device) return "compute";
        return can_bin && lines >= 100000 ? "binned" : "compute";
    }
    // [/auto-raster]

    std::string describe() const {
        return std::string("tuned for a ") + (cpu_device ? "CPU device" : "GPU") +
               ": transform groups of " + std::to_string(transform_group) + " x " +
               std::to_string(vertices_per_lane) + " vertices" +
               (own_matrix_copy ? " (own matrix copies)" : "") + ", about " +
               std::to_string(raster_invocations) +
               " raster invocations (looking before each "
               "atomicMax from " +
               std::to_string(raster_look_from_lines) + " lines on), tile groups of " +
               std::to_string(tile_group) + ", pixels " + (store_to_target ? "stored" : "copied") +
               " into the target by default";
    }
};

}  // namespace ch20
