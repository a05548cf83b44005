// Chapter 29's second queue: DeviceRequirements::compute_family asks for a
// queue of a family that computes but cannot draw. Where the device has one
// (the H200's family 2), Device hands out a queue of it beside the graphics
// queue; where it has none (lavapipe's single family), the compute queue is
// the graphics queue itself, and nothing else changes.

#include "vkt/core/device.hpp"
#include "vkt/core/instance.hpp"

#include <catch2/catch_test_macros.hpp>

#include <optional>
#include <stdexcept>
#include <vector>

TEST_CASE("a compute-only family's queue where the device has one, else the graphics queue",
          "[device][gpu]") {
    std::optional<vkt::Instance> instance;
    try {
        instance.emplace(vkt::InstanceConfig{.application_name = "test_compute_queue"});
    } catch (const std::exception& e) {
        SKIP("no Vulkan instance: " << e.what());
    }
    vkt::DeviceRequirements asked{.compute_family = true};
    const auto candidates = vkt::survey_devices(*instance, VK_NULL_HANDLE, asked);
    bool any = false;
    for (const auto& candidate : candidates) any = any || candidate.unsuitable.empty();
    if (!any) SKIP("no Vulkan device");
    const vkt::DeviceCandidate& chosen = vkt::choose_device(candidates, "");

    // The families, read here on their own: the first that has COMPUTE and
    // lacks GRAPHICS, if any.
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(chosen.handle, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(chosen.handle, &count, families.data());
    std::optional<uint32_t> compute_only;
    for (uint32_t i = 0; i < count && !compute_only; ++i)
        if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) &&
            !(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT))
            compute_only = i;
    CHECK(vkt::compute_only_family(chosen.handle) == compute_only.value_or(UINT32_MAX));

    {
        const vkt::Device device(chosen, asked);
        REQUIRE(device.queue() != VK_NULL_HANDLE);
        REQUIRE(device.compute_queue() != VK_NULL_HANDLE);
        if (compute_only) {
            CHECK(device.compute_family() == *compute_only);
            CHECK(device.compute_family() != device.queue_family());
            CHECK(device.compute_queue() != device.queue());
        } else {
            CHECK(device.compute_family() == device.queue_family());
            CHECK(device.compute_queue() == device.queue());
        }
    }
    {
        // Not asked: the one queue, as every chapter before 29 has it.
        const vkt::Device device(chosen, vkt::DeviceRequirements{});
        CHECK(device.compute_family() == device.queue_family());
        CHECK(device.compute_queue() == device.queue());
    }
}
