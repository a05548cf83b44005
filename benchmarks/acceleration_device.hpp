#pragma once
// as_bench's device (benchmarks/acceleration_build.cpp): what chapter 24's
// acceleration structures need, and no more. VK_KHR_acceleration_structure
// (with deferred host operations and bufferDeviceAddress) is required, as in
// the chapter's [spec]; VK_KHR_ray_query is not, so that the bench runs where
// the chapter cannot (the H200's driver has no ray queries).

#include "vkt/core/device.hpp"
#include "vkt/core/instance.hpp"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

// The device --device names (or the best suitable one); tracer says which
// ray feature it was opened with. Throws vkt::Error naming what a device lacks.
inline std::unique_ptr<vkt::Device> open_acceleration_device(const vkt::Instance& instance,
                                                             std::string_view selector,
                                                             const char*& tracer) {
    VkPhysicalDeviceAccelerationStructureFeaturesKHR acceleration{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR,
        .accelerationStructure = VK_TRUE};
    tracer = "";
    vkt::DeviceRequirements requirements{
        .extensions = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                       VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME},
        .features = {VKT_FEATURE_12(bufferDeviceAddress)},
        .extension_features = &acceleration};
    // The tests' way to play a device without the extension (as the
    // chapters' harness reads it): VKT_HIDE_FEATURES=name,name,...
    const char* hidden = std::getenv("VKT_HIDE_FEATURES");
    for (std::string rest = hidden ? hidden : ""; !rest.empty();) {
        const size_t comma = std::min(rest.find(','), rest.size());
        requirements.hidden.names.push_back(rest.substr(0, comma));
        rest.erase(0, std::min(comma + 1, rest.size()));
    }
    const auto candidates = vkt::survey_devices(instance, VK_NULL_HANDLE, requirements);
    const vkt::DeviceCandidate& chosen = vkt::choose_device(candidates, selector);
    // vkGetAccelerationStructureBuildSizesKHR wants one of the features
    // that trace rays enabled (VUID-...-03617), though nothing here
    // traces: the ray-tracing pipeline's (the H200 has it), else ray
    // queries'. What the structures cost does not depend on which.
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    VkPhysicalDeviceRayQueryFeaturesKHR query{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR, .pNext = &pipeline};
    VkPhysicalDeviceFeatures2 has{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                  .pNext = &query};
    vkGetPhysicalDeviceFeatures2(chosen.handle, &has);
    const auto offers = [&](const char* extension, VkBool32 feature) {
        return feature && !requirements.hidden.hides(extension) &&
               vkt::device_extension_available(chosen.handle, extension);
    };
    if (offers(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME, pipeline.rayTracingPipeline)) {
        tracer = VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME;
        pipeline = {.sType = pipeline.sType, .rayTracingPipeline = VK_TRUE};
        acceleration.pNext = &pipeline;
    } else if (offers(VK_KHR_RAY_QUERY_EXTENSION_NAME, query.rayQuery)) {
        tracer = VK_KHR_RAY_QUERY_EXTENSION_NAME;
        query = {.sType = query.sType, .rayQuery = VK_TRUE};
        acceleration.pNext = &query;
    } else {
        throw vkt::Error(chosen.name + " lacks both VK_KHR_ray_tracing_pipeline and " +
                         "VK_KHR_ray_query, one of which the build-size query needs");
    }
    requirements.extensions.push_back(tracer);
    auto device = std::make_unique<vkt::Device>(chosen, requirements);
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(chosen.handle, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(chosen.handle, &count, families.data());
    if (families[device->queue_family()].timestampValidBits == 0)
        throw vkt::Error(chosen.name + " has no timestamps on its queue");
    return device;
}
