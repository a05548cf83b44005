#pragma once
// Chapter 25's shader binding table, laid out from the device's three
// numbers: where each table starts and how far apart its records are. A
// pure function of those numbers, so tests/unit/test_binding_table.cpp can
// check it with devices other than the one at hand (lavapipe's handle,
// record and base are all 32 bytes, where the rounding never shows).

#include "vkt/resources/align.hpp"

#include <vulkan/vulkan.h>

struct BindingTableLayout {
    VkDeviceSize record = 0;                      // one handle, padded
    VkDeviceSize raygen_size = 0;                 // stride == size: one record
    VkDeviceSize miss_offset = 0, miss_size = 0;  // two records: sky, shadow
    VkDeviceSize hit_offset = 0, hit_size = 0;    // one record: the hit group
    VkDeviceSize size = 0;                        // all three tables
};

inline BindingTableLayout binding_table_layout(VkDeviceSize handle, VkDeviceSize handle_alignment,
                                               VkDeviceSize base) {
    // [sbt-layout]
    // Each record is a group's handle (opaque bytes the device hands
    // out), padded to shaderGroupHandleAlignment; each table (ray
    // generation, miss, hit) starts at a multiple of
    // shaderGroupBaseAlignment. The ray-generation table holds one
    // record, and its stride must equal its size.
    BindingTableLayout t;
    t.record = vkt::align_up(handle, handle_alignment);
    t.raygen_size = vkt::align_up(t.record, base);
    t.miss_offset = t.raygen_size;
    t.miss_size = vkt::align_up(2 * t.record, base);
    t.hit_offset = t.miss_offset + t.miss_size;
    t.hit_size = t.record;
    t.size = t.hit_offset + t.hit_size;
    // [/sbt-layout]
    return t;
}
