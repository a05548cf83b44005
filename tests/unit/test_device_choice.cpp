#include "vkt/core/device.hpp"

#include <catch2/catch_test_macros.hpp>

#include <vector>

using vkt::DeviceCandidate;

static DeviceCandidate candidate(uint32_t index, const char* name, VkPhysicalDeviceType type,
                                 const char* unsuitable = "") {
    return {.index = index,
            .name = name,
            .type = type,
            .api_version = VK_API_VERSION_1_3,
            .unsuitable = unsuitable};
}

TEST_CASE("device types rank discrete > integrated > virtual > CPU > other", "[device]") {
    CHECK(vkt::device_type_score(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU) >
          vkt::device_type_score(VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU));
    CHECK(vkt::device_type_score(VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU) >
          vkt::device_type_score(VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU));
    CHECK(vkt::device_type_score(VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU) >
          vkt::device_type_score(VK_PHYSICAL_DEVICE_TYPE_CPU));
    CHECK(vkt::device_type_score(VK_PHYSICAL_DEVICE_TYPE_CPU) >
          vkt::device_type_score(VK_PHYSICAL_DEVICE_TYPE_OTHER));
}

TEST_CASE("the score ranks by type, then by the largest image size", "[device]") {
    DeviceCandidate small = candidate(0, "a", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU);
    DeviceCandidate big = candidate(1, "b", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU);
    DeviceCandidate cpu = candidate(2, "c", VK_PHYSICAL_DEVICE_TYPE_CPU);
    small.max_image_dimension = 16384;
    big.max_image_dimension = 32768;
    cpu.max_image_dimension = 1 << 20;
    CHECK(vkt::device_score(small) == 4016);  // as chapter 02 prints it
    CHECK(vkt::device_score(big) > vkt::device_score(small));
    CHECK(vkt::device_score(small) > vkt::device_score(cpu));
    std::vector<DeviceCandidate> devices{small, big};
    CHECK(vkt::choose_device(devices, "").name == "b");
}

TEST_CASE("without --device the best suitable device wins", "[device]") {
    std::vector<DeviceCandidate> devices{
        candidate(0, "llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU),
        candidate(1, "Big GPU", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU,
                  "lacks the dynamicRendering feature"),
        candidate(2, "Laptop GPU", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU),
    };
    CHECK(vkt::choose_device(devices, "").name == "Laptop GPU");
}

TEST_CASE("the device flag picks by index or by part of the name, any case", "[device]") {
    std::vector<DeviceCandidate> devices{
        candidate(0, "llvmpipe (LLVM 15)", VK_PHYSICAL_DEVICE_TYPE_CPU),
        candidate(1, "NVIDIA H100", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
    };
    CHECK(vkt::choose_device(devices, "0").name == "llvmpipe (LLVM 15)");
    CHECK(vkt::choose_device(devices, "1").name == "NVIDIA H100");
    CHECK(vkt::choose_device(devices, "LLVMPIPE").index == 0);
    CHECK(vkt::choose_device(devices, "h100").index == 1);
}

TEST_CASE("impossible choices explain themselves", "[device]") {
    std::vector<DeviceCandidate> devices{
        candidate(0, "Old GPU", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU,
                  "supports only Vulkan 1.1, not 1.3"),
    };
    auto message = [&](std::string_view selector) {
        try {
            vkt::choose_device(devices, selector);
        } catch (const vkt::Error& e) {
            return std::string(e.what());
        }
        return std::string("no exception");
    };
    CHECK(message("") ==
          "no Vulkan device can run this chapter; Old GPU supports only Vulkan 1.1, not 1.3");
    CHECK(message("0") == "device 0 (Old GPU) supports only Vulkan 1.1, not 1.3");
    CHECK(message("3") == "--device 3: there are only 1 device(s), numbered from 0");
    CHECK(message("radeon") == "--device radeon: no device has that in its name");
    CHECK(message("-1") == "--device -1: no device has that in its name");
    CHECK(message("99999999999999999999") ==
          "--device 99999999999999999999: there are only 1 device(s), numbered from 0");
    std::vector<DeviceCandidate> none;
    CHECK_THROWS_AS(vkt::choose_device(none, ""), vkt::Error);
}
