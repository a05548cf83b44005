#include "vkt/core/device.hpp"

#include <catch2/catch_test_macros.hpp>

#include <string>

TEST_CASE("a feature chain links the 1.0 to 1.3 feature structs", "[device][features]") {
    vkt::FeatureChain chain;
    VkPhysicalDeviceFeatures2* head = chain.head();
    REQUIRE(head->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    auto* f11 = static_cast<VkPhysicalDeviceVulkan11Features*>(head->pNext);
    REQUIRE(f11->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
    auto* f12 = static_cast<VkPhysicalDeviceVulkan12Features*>(f11->pNext);
    REQUIRE(f12->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
    auto* f13 = static_cast<VkPhysicalDeviceVulkan13Features*>(f12->pNext);
    REQUIRE(f13->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    CHECK(f13->pNext == nullptr);
}

TEST_CASE("a feature names exactly its own member", "[device][features]") {
    vkt::FeatureChain chain;
    CHECK_FALSE(chain.has(VKT_FEATURE_10(samplerAnisotropy)));
    chain[VKT_FEATURE_10(samplerAnisotropy)] = VK_TRUE;
    chain[VKT_FEATURE_11(shaderDrawParameters)] = VK_TRUE;
    chain[VKT_FEATURE_12(descriptorIndexing)] = VK_TRUE;
    chain[VKT_FEATURE_13(dynamicRendering)] = VK_TRUE;
    VkPhysicalDeviceFeatures2* head = chain.head();
    CHECK(head->features.samplerAnisotropy == VK_TRUE);
    CHECK(head->features.geometryShader == VK_FALSE);
    auto* f11 = static_cast<VkPhysicalDeviceVulkan11Features*>(head->pNext);
    auto* f12 = static_cast<VkPhysicalDeviceVulkan12Features*>(f11->pNext);
    auto* f13 = static_cast<VkPhysicalDeviceVulkan13Features*>(f12->pNext);
    CHECK(f11->shaderDrawParameters == VK_TRUE);
    CHECK(f11->multiview == VK_FALSE);
    CHECK(f12->descriptorIndexing == VK_TRUE);
    CHECK(f12->bufferDeviceAddress == VK_FALSE);
    CHECK(f13->dynamicRendering == VK_TRUE);
    CHECK(f13->synchronization2 == VK_FALSE);
    CHECK(std::string(VKT_FEATURE_12(descriptorIndexing).name) == "descriptorIndexing");
}

TEST_CASE("every chapter needs dynamic rendering and synchronization2", "[device][features]") {
    auto base = vkt::base_features();
    REQUIRE(base.size() == 2);
    CHECK(std::string(base[0].name) == "dynamicRendering");
    CHECK(std::string(base[1].name) == "synchronization2");
}
