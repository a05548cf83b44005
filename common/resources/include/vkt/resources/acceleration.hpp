#pragma once
// Acceleration structures, taught in chapter 24 (whose main.cpp builds them
// with every struct written out): a bottom level (BLAS) per triangle mesh,
// read from vertex and index buffers by device address, and a top level
// (TLAS) of instances of them, each with its transform. The tidy form here
// is what chapter 25 (the ray-tracing pipeline) traces against: one call
// builds the lot on the GPU, in one submit, scratch memory shared and aligned
// to minAccelerationStructureScratchOffsetAlignment, the barriers between the
// levels and after them included.

#include "vkt/resources/upload.hpp"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace vkt {

// VK_KHR_acceleration_structure's commands. An extension's commands are not
// exported by the Vulkan loader: each is asked of the device by name.
struct AccelerationCommands {
    explicit AccelerationCommands(VkDevice device);
    PFN_vkCreateAccelerationStructureKHR create = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroy = nullptr;
    PFN_vkGetAccelerationStructureBuildSizesKHR build_sizes = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR build = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR address = nullptr;
};

// A device-local buffer whose memory has a device address (the
// bufferDeviceAddress feature), with `usage` plus SHADER_DEVICE_ADDRESS and
// TRANSFER_DST; filled with data[0..size) when data is not null.
Buffer create_addressable_buffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage,
                                 const void* data = nullptr);
VkDeviceAddress buffer_address(VkDevice device, VkBuffer buffer);

// One acceleration structure and the buffer it lives in. Move-only; destroys
// the structure before its buffer.
class AccelerationStructure {
public:
    AccelerationStructure() = default;
    AccelerationStructure(VkDevice device, PFN_vkDestroyAccelerationStructureKHR destroy,
                          Buffer storage, VkAccelerationStructureKHR handle,
                          VkDeviceAddress address);
    ~AccelerationStructure() { reset(); }
    AccelerationStructure(AccelerationStructure&& other) noexcept { *this = std::move(other); }
    AccelerationStructure& operator=(AccelerationStructure&& other) noexcept;
    AccelerationStructure(const AccelerationStructure&) = delete;
    AccelerationStructure& operator=(const AccelerationStructure&) = delete;

    VkAccelerationStructureKHR get() const { return handle_; }
    VkDeviceAddress address() const { return address_; }  // what an instance refers to
    VkDeviceSize bytes() const { return storage_.size; }
    void reset();

private:
    VkDevice device_ = VK_NULL_HANDLE;
    PFN_vkDestroyAccelerationStructureKHR destroy_ = nullptr;
    Buffer storage_;
    VkAccelerationStructureKHR handle_ = VK_NULL_HANDLE;
    VkDeviceAddress address_ = 0;
};

// One mesh's triangles: three indices each, from `first_index` on in an index
// buffer, naming vertices of a buffer whose elements start with a position
// of three floats. Both buffers need the usages
// ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY and SHADER_DEVICE_ADDRESS.
struct TriangleMesh {
    VkDeviceAddress vertices = 0;
    VkDeviceSize vertex_stride = 0;
    uint32_t vertex_count = 0;
    VkDeviceAddress indices = 0;
    VkIndexType index_type = VK_INDEX_TYPE_UINT16;
    uint32_t first_index = 0;
    uint32_t triangle_count = 0;
};

// [mesh-instance]
// One placement of a mesh in the top level. custom_index is what a hit
// shader reads as gl_InstanceCustomIndexEXT; hit_group_offset is added to
// the hit group a ray asks for (instanceShaderBindingTableRecordOffset).
struct MeshInstance {
    uint32_t mesh = 0;  // index into the meshes given to build_scene
    glm::mat4 world_from_object{1.0f};
    uint32_t custom_index = 0;
    uint32_t hit_group_offset = 0;
    uint8_t mask = 0xff;
};
// [/mesh-instance]

// The row-major 3x4 matrix of an instance: GLM's column-major mat4 without
// its last row (which for an affine transform is 0 0 0 1).
VkTransformMatrixKHR instance_transform(const glm::mat4& m);

// Where each build's scratch memory starts in one shared buffer: every
// region at a multiple of `alignment`, one after another. The last element
// is the total size to allocate (plus `alignment`, for the buffer's own
// address to be rounded up to it).
std::vector<VkDeviceSize> scratch_offsets(std::span<const VkDeviceSize> sizes,
                                          VkDeviceSize alignment);

// Points `binding` of `set` (an ACCELERATION_STRUCTURE_KHR binding) at a top
// level: chapter 24's write, whose structure travels in a
// VkWriteDescriptorSetAccelerationStructureKHR chained to it.
void write_acceleration_structure_descriptor(VkDevice device, VkDescriptorSet set, uint32_t binding,
                                             VkAccelerationStructureKHR structure);

// A scene's structures: one BLAS per mesh and the TLAS over the instances.
struct AccelerationScene {
    std::vector<AccelerationStructure> bottom;
    AccelerationStructure top;
};

// Builds every structure for ray tracing (PREFER_FAST_TRACE, opaque
// geometry) and waits for the GPU: when this returns, any later command on
// the queue may trace against `top`.
AccelerationScene build_scene(const Gpu& gpu, const AccelerationCommands& commands,
                              std::span<const TriangleMesh> meshes,
                              std::span<const MeshInstance> instances);

}  // namespace vkt
