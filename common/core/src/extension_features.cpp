#include "vkt/core/extension_features.hpp"

#include "vkt/core/device.hpp"

#include <cstddef>
#include <cstring>
#include <vector>

namespace vkt {

namespace {

// One VkBool32 member of a feature struct: its name and where it lies.
struct Member {
    const char* name;
    std::size_t offset;
};
#define VKT_MEMBER(Struct, member)        \
    Member {                              \
#member, offsetof(Struct, member) \
    }

// The feature structs the chapters link, with every VkBool32 member each has.
struct Kind {
    VkStructureType type;
    std::size_t size;
    const char* extension;
    std::vector<Member> members;
};

const std::vector<Kind>& kinds() {
    using Mesh = VkPhysicalDeviceMeshShaderFeaturesEXT;
    using Query = VkPhysicalDeviceRayQueryFeaturesKHR;
    using Structure = VkPhysicalDeviceAccelerationStructureFeaturesKHR;
    using Pipeline = VkPhysicalDeviceRayTracingPipelineFeaturesKHR;
    static const std::vector<Kind> table = {
        {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT,
         sizeof(Mesh),
         VK_EXT_MESH_SHADER_EXTENSION_NAME,
         {VKT_MEMBER(Mesh, taskShader), VKT_MEMBER(Mesh, meshShader),
          VKT_MEMBER(Mesh, multiviewMeshShader),
          VKT_MEMBER(Mesh, primitiveFragmentShadingRateMeshShader),
          VKT_MEMBER(Mesh, meshShaderQueries)}},
        {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR,
         sizeof(Query),
         VK_KHR_RAY_QUERY_EXTENSION_NAME,
         {VKT_MEMBER(Query, rayQuery)}},
        {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR,
         sizeof(Structure),
         VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
         {VKT_MEMBER(Structure, accelerationStructure),
          VKT_MEMBER(Structure, accelerationStructureCaptureReplay),
          VKT_MEMBER(Structure, accelerationStructureIndirectBuild),
          VKT_MEMBER(Structure, accelerationStructureHostCommands),
          VKT_MEMBER(Structure, descriptorBindingAccelerationStructureUpdateAfterBind)}},
        {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR,
         sizeof(Pipeline),
         VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
         {VKT_MEMBER(Pipeline, rayTracingPipeline),
          VKT_MEMBER(Pipeline, rayTracingPipelineShaderGroupHandleCaptureReplay),
          VKT_MEMBER(Pipeline, rayTracingPipelineShaderGroupHandleCaptureReplayMixed),
          VKT_MEMBER(Pipeline, rayTracingPipelineTraceRaysIndirect),
          VKT_MEMBER(Pipeline, rayTraversalPrimitiveCulling)}},
    };
    return table;
}

VkBool32 member_of(const void* object, const Member& member) {
    VkBool32 value = VK_FALSE;
    std::memcpy(&value, static_cast<const std::byte*>(object) + member.offset, sizeof value);
    return value;
}

}  // namespace

std::string extension_feature_shortfall(VkPhysicalDevice device, const void* wanted,
                                        const HiddenNames& hidden) {
    for (auto* link = static_cast<const VkBaseInStructure*>(wanted); link; link = link->pNext) {
        const Kind* kind = nullptr;
        for (const Kind& k : kinds())
            if (k.type == link->sType) kind = &k;
        if (!kind)
            throw Error("extension_feature_shortfall: a feature struct of type " +
                        std::to_string(int(link->sType)) +
                        " that vkt/core/extension_features.cpp does not list");
        // The device's own answer, in a struct of the same kind (8-byte
        // aligned storage: the struct starts with a pointer).
        std::vector<uint64_t> storage((kind->size + 7) / 8, 0);
        auto* has = reinterpret_cast<VkBaseOutStructure*>(storage.data());
        has->sType = kind->type;
        VkPhysicalDeviceFeatures2 query{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                        .pNext = has};
        vkGetPhysicalDeviceFeatures2(device, &query);
        for (const Member& member : kind->members) {
            if (member_of(link, member) != VK_TRUE) continue;
            if (member_of(has, member) != VK_TRUE || hidden.hides(member.name))
                return lacks_feature(member.name, kind->extension, hidden.hides(member.name));
        }
    }
    return {};
}

}  // namespace vkt
