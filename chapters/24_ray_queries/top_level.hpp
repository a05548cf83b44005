#pragma once
// Chapter 24's top-level acceleration structure: one instance per object of
// the scene, each pointing at its mesh's bottom-level structure with its own
// transform, rebuilt or updated every frame as the objects move.

#include "acceleration.hpp"

#include "vkt/resources/align.hpp"

#include <glm/glm.hpp>

#include <cstring>
#include <span>
#include <vector>

namespace ch24 {

class TopLevel {
public:
    // update: built once with ALLOW_UPDATE, then refitted each frame (the
    // tree kept, its boxes moved); else built from nothing each frame.
    TopLevel(const vkt::Gpu& gpu, const RayFunctions& ray, VkDeviceSize scratch_alignment,
             uint32_t instance_count, uint32_t frames_in_flight, bool update)
        : ray_(ray), count_(instance_count), update_(update) {
        // One instance buffer per frame in flight: the CPU writes the next
        // frame's while the GPU may still read the last frame's.
        for (uint32_t i = 0; i < frames_in_flight; ++i)
            instances_.push_back(create_address_buffer(
                gpu, count_ * sizeof(VkAccelerationStructureInstanceKHR),
                VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR, true));
        // [tlas-geometry]
        // The top level's one geometry: the instances, read from a buffer
        // by address (its address is set before each build).
        geometry_ = VkAccelerationStructureGeometryKHR{
            .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR,
            .geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR,
            .geometry =
                {.instances =
                     {.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR,
                      .arrayOfPointers = VK_FALSE}},
            // No flags: opacity belongs to the bottom levels' triangles (and
            // an instance's FORCE_OPAQUE); OPAQUE here would say nothing.
            .flags = 0,
        };
        build_ = VkAccelerationStructureBuildGeometryInfoKHR{
            .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR,
            .type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
            .flags = update_ ? VkBuildAccelerationStructureFlagsKHR(
                                   VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR |
                                   VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR)
                             : VkBuildAccelerationStructureFlagsKHR(
                                   VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR),
            .mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR,
            .geometryCount = 1,
            .pGeometries = &geometry_,
        };
        VkAccelerationStructureBuildSizesInfoKHR sizes{
            .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
        ray.build_sizes(gpu.device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build_,
                        &count_, &sizes);
        // [/tlas-geometry]
        tlas_ = AccelerationStructure(gpu, ray, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                      sizes.accelerationStructureSize);
        // An update needs its own (usually smaller) scratch size.
        const VkDeviceSize scratch = std::max(sizes.buildScratchSize, sizes.updateScratchSize);
        scratch_ = create_address_buffer(gpu, scratch + scratch_alignment,
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
        scratch_address_ = vkt::align_up(scratch_.address, scratch_alignment);
        scratch_bytes_ = scratch;
    }

    // Not copyable: build_ points at geometry_, inside the object itself.
    TopLevel(const TopLevel&) = delete;
    TopLevel& operator=(const TopLevel&) = delete;

    VkAccelerationStructureKHR get() const { return tlas_.get(); }
    VkDeviceSize bytes() const { return tlas_.size(); }
    VkDeviceSize scratch_bytes() const { return scratch_bytes_; }

    // [instances]
    // One VkAccelerationStructureInstanceKHR per object: a 3x4 row-major
    // transform (the top three rows of world_from_object), the address of
    // its mesh's bottom level, a mask every ray accepts, and no face culling
    // even for a ray that asks for it (a shadow ray must stop at any side of
    // a caster).
    void write_instances(uint32_t slot, std::span<const glm::mat4> world_from_object,
                         std::span<const VkDeviceAddress> bottom_level) {
        auto* out = static_cast<VkAccelerationStructureInstanceKHR*>(instances_[slot].owner.mapped);
        for (uint32_t i = 0; i < count_; ++i) {
            VkAccelerationStructureInstanceKHR instance{
                .instanceCustomIndex = i & 0xFFFFFF,
                .mask = 0xFF,
                .instanceShaderBindingTableRecordOffset = 0,
                .flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR,
                .accelerationStructureReference = bottom_level[i],
            };
            const glm::mat4& m = world_from_object[i];  // glm: m[column][row]
            for (int row = 0; row < 3; ++row)
                for (int column = 0; column < 4; ++column)
                    instance.transform.matrix[row][column] = m[column][row];
            std::memcpy(out + i, &instance, sizeof instance);
        }
    }
    // [/instances]

    // [record-build]
    // Records this frame's build: the first one (and every one, unless
    // refitting) from nothing; later ones in update mode rewrite the
    // structure in place, reading it (src) and writing it (dst).
    void record(VkCommandBuffer cmd, uint32_t slot) {
        const bool refit = update_ && built_once_;
        build_.mode = refit ? VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR
                            : VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
        build_.srcAccelerationStructure = refit ? tlas_.get() : VK_NULL_HANDLE;
        build_.dstAccelerationStructure = tlas_.get();
        build_.scratchData.deviceAddress = scratch_address_;
        geometry_.geometry.instances.data.deviceAddress = instances_[slot].address;
        const VkAccelerationStructureBuildRangeInfoKHR range{.primitiveCount = count_};
        const VkAccelerationStructureBuildRangeInfoKHR* ranges[] = {&range};
        ray_.cmd_build(cmd, 1, &build_, ranges);
        built_once_ = true;
    }
    // [/record-build]

private:
    const RayFunctions& ray_;
    uint32_t count_;
    bool update_, built_once_ = false;
    std::vector<AddressBuffer> instances_;
    VkAccelerationStructureGeometryKHR geometry_{};
    VkAccelerationStructureBuildGeometryInfoKHR build_{};
    AccelerationStructure tlas_;
    AddressBuffer scratch_;
    VkDeviceAddress scratch_address_ = 0;
    VkDeviceSize scratch_bytes_ = 0;
};

}  // namespace ch24
