#include "vkt/resources/acceleration.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/resources/align.hpp"

#include <string>

namespace vkt {

namespace {

template <typename Pfn>
void load(VkDevice device, const char* name, Pfn& out) {
    out = reinterpret_cast<Pfn>(vkGetDeviceProcAddr(device, name));
    if (!out) throw Error(std::string("the device has no command ") + name);
}

// What one build needs besides its structure: the geometry it reads (kept
// here, since the build info points at it), its ranges and its sizes.
struct Pending {
    VkAccelerationStructureGeometryKHR geometry{};
    VkAccelerationStructureBuildRangeInfoKHR range{};
    VkAccelerationStructureBuildGeometryInfoKHR info{};
    VkAccelerationStructureBuildSizesInfoKHR sizes{};
};

// Asks how large a structure of this geometry gets, and how much scratch
// memory its build needs (the device's own answer: no formula gives it).
void size_up(VkDevice device, const AccelerationCommands& commands, Pending& p,
             VkAccelerationStructureTypeKHR type) {
    p.info = {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR,
        .type = type,
        .flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR,
        .mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR,
        .geometryCount = 1,
        .pGeometries = &p.geometry,
    };
    p.sizes = {.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    commands.build_sizes(device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &p.info,
                         &p.range.primitiveCount, &p.sizes);
}

// The structure itself: a buffer of the size asked for, and the object
// that lives at its start.
AccelerationStructure create_structure(const Gpu& gpu, const AccelerationCommands& commands,
                                       Pending& p, VkAccelerationStructureTypeKHR type) {
    Buffer storage =
        create_addressable_buffer(gpu, p.sizes.accelerationStructureSize,
                                  VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR);
    const VkAccelerationStructureCreateInfoKHR info{
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR,
        .buffer = storage.buffer,
        .size = p.sizes.accelerationStructureSize,
        .type = type,
    };
    VkAccelerationStructureKHR handle;
    VKT_CHECK(commands.create(gpu.device, &info, nullptr, &handle));
    const VkAccelerationStructureDeviceAddressInfoKHR where{
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR,
        .accelerationStructure = handle,
    };
    const VkDeviceAddress address = commands.address(gpu.device, &where);
    p.info.dstAccelerationStructure = handle;
    return {gpu.device, commands.destroy, std::move(storage), handle, address};
}

// Build writes made visible to what reads the structures next: the top
// level's build (it reads the bottom levels), then every shader.
void build_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 next_stage) {
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                   VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR, next_stage,
                   VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR);
}

}  // namespace

AccelerationCommands::AccelerationCommands(VkDevice device) {
    load(device, "vkCreateAccelerationStructureKHR", create);
    load(device, "vkDestroyAccelerationStructureKHR", destroy);
    load(device, "vkGetAccelerationStructureBuildSizesKHR", build_sizes);
    load(device, "vkCmdBuildAccelerationStructuresKHR", build);
    load(device, "vkGetAccelerationStructureDeviceAddressKHR", address);
}

VkDeviceAddress buffer_address(VkDevice device, VkBuffer buffer) {
    const VkBufferDeviceAddressInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO,
                                         .buffer = buffer};
    return vkGetBufferDeviceAddress(device, &info);
}

Buffer create_addressable_buffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage,
                                 const void* data) {
    Buffer out;
    out.size = size;
    const VkBufferCreateInfo buffer_info{
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = size,
        .usage =
            usage | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
    };
    VkBuffer buffer;
    VKT_CHECK(vkCreateBuffer(gpu.device, &buffer_info, nullptr, &buffer));
    out.buffer = BufferHandle(gpu.device, buffer);
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(gpu.device, buffer, &needs);
    // The memory must say it will be addressed, or the address is invalid.
    const VkMemoryAllocateFlagsInfo addressed{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO,
                                              .flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT};
    const VkMemoryAllocateInfo memory_info{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .pNext = &addressed,
        .allocationSize = needs.size,
        .memoryTypeIndex = find_memory_type(gpu.physical, needs.memoryTypeBits,
                                            VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT),
    };
    VkDeviceMemory memory;
    VKT_CHECK(vkAllocateMemory(gpu.device, &memory_info, nullptr, &memory));
    out.memory = DeviceMemory(gpu.device, memory);
    VKT_CHECK(vkBindBufferMemory(gpu.device, buffer, memory, 0));
    if (data) upload_to_buffer(gpu, buffer, data, size);
    return out;
}

AccelerationStructure::AccelerationStructure(VkDevice device,
                                             PFN_vkDestroyAccelerationStructureKHR destroy,
                                             Buffer storage, VkAccelerationStructureKHR handle,
                                             VkDeviceAddress address)
    : device_(device),
      destroy_(destroy),
      storage_(std::move(storage)),
      handle_(handle),
      address_(address) {}

AccelerationStructure& AccelerationStructure::operator=(AccelerationStructure&& other) noexcept {
    if (this == &other) return *this;
    reset();
    device_ = other.device_;
    destroy_ = other.destroy_;
    storage_ = std::move(other.storage_);
    handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    address_ = std::exchange(other.address_, 0);
    return *this;
}

void AccelerationStructure::reset() {
    if (handle_ != VK_NULL_HANDLE)
        destroy_(device_, std::exchange(handle_, VK_NULL_HANDLE), nullptr);
    storage_ = Buffer{};  // the memory after the structure that lived in it
    address_ = 0;
}

void write_acceleration_structure_descriptor(VkDevice device, VkDescriptorSet set, uint32_t binding,
                                             VkAccelerationStructureKHR structure) {
    const VkWriteDescriptorSetAccelerationStructureKHR chained{
        .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR,
        .accelerationStructureCount = 1,
        .pAccelerationStructures = &structure};
    const VkWriteDescriptorSet write{
        .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
        .pNext = &chained,
        .dstSet = set,
        .dstBinding = binding,
        .descriptorCount = 1,
        .descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR};
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

VkTransformMatrixKHR instance_transform(const glm::mat4& m) {
    VkTransformMatrixKHR out;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 4; ++column) out.matrix[row][column] = m[column][row];
    return out;
}

std::vector<VkDeviceSize> scratch_offsets(std::span<const VkDeviceSize> sizes,
                                          VkDeviceSize alignment) {
    std::vector<VkDeviceSize> offsets{0};
    for (VkDeviceSize size : sizes) offsets.push_back(align_up(offsets.back() + size, alignment));
    return offsets;
}

AccelerationScene build_scene(const Gpu& gpu, const AccelerationCommands& commands,
                              std::span<const TriangleMesh> meshes,
                              std::span<const MeshInstance> instances) {
    VkPhysicalDeviceAccelerationStructurePropertiesKHR limits{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
    VkPhysicalDeviceProperties2 properties{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                           .pNext = &limits};
    vkGetPhysicalDeviceProperties2(gpu.physical, &properties);

    AccelerationScene scene;
    // One build per mesh, then one for the instances: pending.back() is the top.
    std::vector<Pending> pending(meshes.size() + 1);
    for (size_t i = 0; i < meshes.size(); ++i) {
        const TriangleMesh& mesh = meshes[i];
        const VkDeviceSize index_bytes = mesh.index_type == VK_INDEX_TYPE_UINT16 ? 2 : 4;
        Pending& p = pending[i];
        p.geometry = {
            .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR,
            .geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR,
            .geometry =
                {.triangles =
                     {
                         .sType =
                             VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR,
                         .vertexFormat = VK_FORMAT_R32G32B32_SFLOAT,
                         .vertexData = {.deviceAddress = mesh.vertices},
                         .vertexStride = mesh.vertex_stride,
                         .maxVertex = mesh.vertex_count - 1,
                         .indexType = mesh.index_type,
                         .indexData = {.deviceAddress = mesh.indices},
                     }},
            .flags = VK_GEOMETRY_OPAQUE_BIT_KHR,  // no any-hit shader is asked
        };
        p.range = {.primitiveCount = mesh.triangle_count,
                   .primitiveOffset = uint32_t(mesh.first_index * index_bytes)};
        size_up(gpu.device, commands, p, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR);
        scene.bottom.push_back(
            create_structure(gpu, commands, p, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR));
    }

    // [instance-records]
    // The instances, in the layout the device reads: each refers to its
    // bottom level by that structure's device address.
    std::vector<VkAccelerationStructureInstanceKHR> records;
    for (const MeshInstance& instance : instances)
        records.push_back({
            .transform = instance_transform(instance.world_from_object),
            .instanceCustomIndex = instance.custom_index & 0xffffffu,
            .mask = instance.mask,
            .instanceShaderBindingTableRecordOffset = instance.hit_group_offset & 0xffffffu,
            .flags = 0,
            .accelerationStructureReference = scene.bottom.at(instance.mesh).address(),
        });
    // [/instance-records]
    const Buffer instance_buffer = create_addressable_buffer(
        gpu, records.size() * sizeof(records[0]),
        VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR, records.data());
    Pending& top = pending.back();
    top.geometry = {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR,
        .geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR,
        .geometry =
            {.instances =
                 {
                     .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR,
                     .data = {.deviceAddress = buffer_address(gpu.device, instance_buffer.buffer)},
                 }},
    };
    top.range = {.primitiveCount = uint32_t(records.size())};
    size_up(gpu.device, commands, top, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR);
    scene.top = create_structure(gpu, commands, top, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR);

    // One scratch buffer for every build, each region aligned; its address
    // rounded up to the alignment too (a buffer's own is only its memory's).
    const VkDeviceSize alignment = limits.minAccelerationStructureScratchOffsetAlignment;
    std::vector<VkDeviceSize> sizes;
    sizes.reserve(pending.size());
    for (const Pending& p : pending) sizes.push_back(p.sizes.buildScratchSize);
    const std::vector<VkDeviceSize> offsets = scratch_offsets(sizes, alignment);
    const Buffer scratch = create_addressable_buffer(gpu, offsets.back() + alignment,
                                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const VkDeviceAddress base = align_up(buffer_address(gpu.device, scratch.buffer), alignment);
    for (size_t i = 0; i < pending.size(); ++i)
        pending[i].info.scratchData.deviceAddress = base + offsets[i];

    one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        // The bottom levels in one call (their scratch regions do not
        // overlap), the barrier, then the top level that reads them.
        std::vector<VkAccelerationStructureBuildGeometryInfoKHR> infos;
        std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> ranges;
        for (size_t i = 0; i + 1 < pending.size(); ++i) {
            infos.push_back(pending[i].info);
            ranges.push_back(&pending[i].range);
        }
        if (!infos.empty())
            commands.build(cmd, uint32_t(infos.size()), infos.data(), ranges.data());
        build_barrier(cmd, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR);
        const VkAccelerationStructureBuildRangeInfoKHR* top_range = &top.range;
        commands.build(cmd, 1, &top.info, &top_range);
        build_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT);
    });
    return scene;
}

}  // namespace vkt
