#include "vkt/core/check.hpp"

#include <catch2/catch_test_macros.hpp>

#include <string>
#include <type_traits>

TEST_CASE("result names are the enumerators' names", "[check]") {
    CHECK(std::string(vkt::result_name(VK_SUCCESS)) == "VK_SUCCESS");
    CHECK(std::string(vkt::result_name(VK_ERROR_OUT_OF_DATE_KHR)) == "VK_ERROR_OUT_OF_DATE_KHR");
    CHECK(std::string(vkt::result_name(VK_ERROR_DEVICE_LOST)) == "VK_ERROR_DEVICE_LOST");
    CHECK(std::string(vkt::result_name(VkResult(-12345))) == "VK_RESULT_UNKNOWN");
}

TEST_CASE("success and positive codes pass through", "[check]") {
    CHECK(VKT_CHECK(VK_SUCCESS) == VK_SUCCESS);
    CHECK(VKT_CHECK(VK_SUBOPTIMAL_KHR) == VK_SUBOPTIMAL_KHR);
    CHECK(VKT_CHECK(VK_INCOMPLETE) == VK_INCOMPLETE);
}

static VkResult vkFakeCreateThing(int) {
    return VK_ERROR_FEATURE_NOT_PRESENT;
}

TEST_CASE("an error names the call, the result and the place", "[check]") {
    try {
        VKT_CHECK(vkFakeCreateThing(42));
        FAIL("no exception");
    } catch (const vkt::VulkanError& e) {
        std::string what = e.what();
        CHECK(e.result() == VK_ERROR_FEATURE_NOT_PRESENT);
        CHECK(what.starts_with(
            "vkFakeCreateThing failed with VK_ERROR_FEATURE_NOT_PRESENT (-8) at test_check.cpp:"));
    }
}

TEST_CASE("a Vulkan failure is a vkt::Error, so one catch takes every error", "[check]") {
    // CONTRIBUTING.md and the debugging appendix promise `catch (const
    // vkt::Error&)` catches what VKT_CHECK throws.
    STATIC_REQUIRE(std::is_base_of_v<vkt::Error, vkt::VulkanError>);
    try {
        VKT_CHECK(vkFakeCreateThing(7));
        FAIL("no exception");
    } catch (const vkt::Error& e) {
        CHECK(std::string(e.what()).starts_with("vkFakeCreateThing failed with"));
    }
}
