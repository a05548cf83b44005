#pragma once
// Chapter 24's pieces around an acceleration structure: the extension's
// functions (no loader exports them: they are asked of the device), a buffer
// with a GPU address, and an owner that destroys a structure with its buffer.

#include "vkt/core/check.hpp"
#include "vkt/core/memory.hpp"
#include "vkt/resources/upload.hpp"

#include <string>
#include <utility>

namespace ch24 {

// VK_KHR_acceleration_structure's commands are extension functions: the
// Vulkan loader does not export them, so the chapter asks the device for
// each one by name, once, after the device exists.
struct RayFunctions {
    PFN_vkGetAccelerationStructureBuildSizesKHR build_sizes = nullptr;
    PFN_vkCreateAccelerationStructureKHR create = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroy = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR address = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR cmd_build = nullptr;
    PFN_vkCmdWriteAccelerationStructuresPropertiesKHR cmd_write_properties = nullptr;
    PFN_vkCmdCopyAccelerationStructureKHR cmd_copy = nullptr;

    explicit RayFunctions(VkDevice device) {
        load(device, build_sizes, "vkGetAccelerationStructureBuildSizesKHR");
        load(device, create, "vkCreateAccelerationStructureKHR");
        load(device, destroy, "vkDestroyAccelerationStructureKHR");
        load(device, address, "vkGetAccelerationStructureDeviceAddressKHR");
        load(device, cmd_build, "vkCmdBuildAccelerationStructuresKHR");
        load(device, cmd_write_properties, "vkCmdWriteAccelerationStructuresPropertiesKHR");
        load(device, cmd_copy, "vkCmdCopyAccelerationStructureKHR");
    }

private:
    template <typename Pfn>
    static void load(VkDevice device, Pfn& out, const char* name) {
        out = reinterpret_cast<Pfn>(vkGetDeviceProcAddr(device, name));
        if (!out) throw vkt::Error(std::string("the device gave no ") + name);
    }
};

// A buffer the GPU reaches by address: the build reads its vertices, indices
// and instances through 64-bit addresses, and a structure's storage is a
// buffer too. Usage SHADER_DEVICE_ADDRESS, and memory allocated with the
// DEVICE_ADDRESS flag (the bufferDeviceAddress feature allows both).
struct AddressBuffer {
    vkt::Buffer owner;
    VkDeviceAddress address = 0;
};

inline AddressBuffer create_address_buffer(const vkt::Gpu& gpu, VkDeviceSize size,
                                           VkBufferUsageFlags usage, bool host_visible) {
    AddressBuffer out;
    out.owner.size = size;
    const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                  .size = size,
                                  .usage = usage | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                  .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    VkBuffer buffer;
    VKT_CHECK(vkCreateBuffer(gpu.device, &info, nullptr, &buffer));
    out.owner.buffer = vkt::BufferHandle(gpu.device, buffer);
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(gpu.device, buffer, &needs);
    const VkMemoryPropertyFlags where =
        host_visible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                     : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    const VkMemoryAllocateFlagsInfo address_flag{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO,
        .flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT};
    const VkMemoryAllocateInfo allocate{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .pNext = &address_flag,
        .allocationSize = needs.size,
        .memoryTypeIndex = vkt::find_memory_type(gpu.physical, needs.memoryTypeBits, where)};
    VkDeviceMemory memory;
    VKT_CHECK(vkAllocateMemory(gpu.device, &allocate, nullptr, &memory));
    out.owner.memory = vkt::DeviceMemory(gpu.device, memory);
    VKT_CHECK(vkBindBufferMemory(gpu.device, buffer, memory, 0));
    if (host_visible) VKT_CHECK(vkMapMemory(gpu.device, memory, 0, size, 0, &out.owner.mapped));
    const VkBufferDeviceAddressInfo which{.sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO,
                                          .buffer = buffer};
    out.address = vkGetBufferDeviceAddress(gpu.device, &which);
    return out;
}

// One acceleration structure and the buffer that holds it, destroyed in that
// order. Move-only, like the owners of vkt/core/owned.hpp.
class AccelerationStructure {
public:
    AccelerationStructure() = default;
    AccelerationStructure(const vkt::Gpu& gpu, const RayFunctions& ray,
                          VkAccelerationStructureTypeKHR type, VkDeviceSize size)
        : device_(gpu.device), destroy_(ray.destroy) {
        // [create]
        // The structure lives in a buffer of ours (usage
        // ACCELERATION_STRUCTURE_STORAGE), at an offset that must be a
        // multiple of 256; its size comes from the build sizes query.
        storage_ = create_address_buffer(
            gpu, size, VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR, false);
        const VkAccelerationStructureCreateInfoKHR info{
            .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR,
            .buffer = storage_.owner.buffer,
            .offset = 0,
            .size = size,
            .type = type,
        };
        VKT_CHECK(ray.create(device_, &info, nullptr, &handle_));
        const VkAccelerationStructureDeviceAddressInfoKHR which{
            .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR,
            .accelerationStructure = handle_};
        address_ = ray.address(device_, &which);
        // [/create]
    }
    ~AccelerationStructure() { reset(); }
    AccelerationStructure(AccelerationStructure&& other) noexcept { *this = std::move(other); }
    AccelerationStructure& operator=(AccelerationStructure&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = other.device_;
            destroy_ = other.destroy_;
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
            address_ = other.address_;
            storage_ = std::move(other.storage_);
        }
        return *this;
    }
    void reset() {
        if (handle_) destroy_(device_, std::exchange(handle_, VK_NULL_HANDLE), nullptr);
        storage_ = {};
    }
    VkAccelerationStructureKHR get() const { return handle_; }
    VkDeviceAddress address() const { return address_; }
    VkDeviceSize size() const { return storage_.owner.size; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    PFN_vkDestroyAccelerationStructureKHR destroy_ = nullptr;
    VkAccelerationStructureKHR handle_ = VK_NULL_HANDLE;
    VkDeviceAddress address_ = 0;
    AddressBuffer storage_;
};

}  // namespace ch24
