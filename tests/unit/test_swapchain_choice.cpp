#include "vkt/core/swapchain.hpp"

#include "vkt/core/check.hpp"

#include <catch2/catch_test_macros.hpp>

#include <vector>

static VkSurfaceFormatKHR srgb(VkFormat format) {
    return {format, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
}

TEST_CASE("an _SRGB surface format is preferred", "[swapchain]") {
    std::vector<VkSurfaceFormatKHR> window{srgb(VK_FORMAT_B8G8R8A8_UNORM),
                                           srgb(VK_FORMAT_B8G8R8A8_SRGB)};
    CHECK(vkt::choose_surface_format(window).format == VK_FORMAT_B8G8R8A8_SRGB);
}

TEST_CASE("lavapipe's headless formats are accepted", "[swapchain]") {
    std::vector<VkSurfaceFormatKHR> headless{srgb(VK_FORMAT_R8G8B8A8_UNORM),
                                             srgb(VK_FORMAT_B8G8R8A8_UNORM)};
    CHECK(vkt::choose_surface_format(headless).format == VK_FORMAT_B8G8R8A8_UNORM);
}

TEST_CASE("a recreated swapchain keeps its format where it can", "[swapchain]") {
    std::vector<VkSurfaceFormatKHR> window{srgb(VK_FORMAT_B8G8R8A8_SRGB),
                                           srgb(VK_FORMAT_R8G8B8A8_UNORM)};
    CHECK(vkt::choose_surface_format(window, VK_FORMAT_R8G8B8A8_UNORM).format ==
          VK_FORMAT_R8G8B8A8_UNORM);
    CHECK(vkt::choose_surface_format(window, VK_FORMAT_B8G8R8A8_UNORM).format ==
          VK_FORMAT_B8G8R8A8_SRGB);
    // Gone: its sibling with the same byte order wins over the general order.
    std::vector<VkSurfaceFormatKHR> changed{srgb(VK_FORMAT_B8G8R8A8_SRGB),
                                            srgb(VK_FORMAT_R8G8B8A8_UNORM)};
    CHECK(vkt::choose_surface_format(changed, VK_FORMAT_R8G8B8A8_SRGB).format ==
          VK_FORMAT_R8G8B8A8_UNORM);
}

TEST_CASE("a surface without an 8-bit sRGB-space format is refused", "[swapchain]") {
    std::vector<VkSurfaceFormatKHR> odd{
        srgb(VK_FORMAT_A2B10G10R10_UNORM_PACK32),
        {VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_EXTENDED_SRGB_LINEAR_EXT}};
    CHECK_THROWS_AS(vkt::choose_surface_format(odd), vkt::Error);
}

TEST_CASE("we render in the _SRGB format with the swapchain's byte order", "[swapchain]") {
    CHECK(vkt::render_format_for(VK_FORMAT_B8G8R8A8_UNORM) == VK_FORMAT_B8G8R8A8_SRGB);
    CHECK(vkt::render_format_for(VK_FORMAT_B8G8R8A8_SRGB) == VK_FORMAT_B8G8R8A8_SRGB);
    CHECK(vkt::render_format_for(VK_FORMAT_R8G8B8A8_UNORM) == VK_FORMAT_R8G8B8A8_SRGB);
    CHECK(vkt::render_format_for(VK_FORMAT_R8G8B8A8_SRGB) == VK_FORMAT_R8G8B8A8_SRGB);
    CHECK_THROWS_AS(vkt::render_format_for(VK_FORMAT_R16G16B16A16_SFLOAT), vkt::Error);
}

TEST_CASE("present modes: FIFO normally, uncapped for benchmarks", "[swapchain]") {
    std::vector<VkPresentModeKHR> all{VK_PRESENT_MODE_FIFO_KHR, VK_PRESENT_MODE_MAILBOX_KHR,
                                      VK_PRESENT_MODE_IMMEDIATE_KHR};
    std::vector<VkPresentModeKHR> mailbox{VK_PRESENT_MODE_FIFO_KHR, VK_PRESENT_MODE_MAILBOX_KHR};
    std::vector<VkPresentModeKHR> fifo{VK_PRESENT_MODE_FIFO_KHR};
    CHECK(vkt::choose_present_mode(all, false) == VK_PRESENT_MODE_FIFO_KHR);
    CHECK(vkt::choose_present_mode(all, true) == VK_PRESENT_MODE_IMMEDIATE_KHR);
    CHECK(vkt::choose_present_mode(mailbox, true) == VK_PRESENT_MODE_MAILBOX_KHR);
    CHECK(vkt::choose_present_mode(fifo, true) == VK_PRESENT_MODE_FIFO_KHR);
}

TEST_CASE("extent: the window's own, or the wanted size within limits", "[swapchain]") {
    VkSurfaceCapabilitiesKHR window{};
    window.currentExtent = {1024, 768};
    CHECK(vkt::choose_extent(window, {800, 600}).width == 1024);

    VkSurfaceCapabilitiesKHR headless{};
    headless.currentExtent = {UINT32_MAX, UINT32_MAX};
    headless.minImageExtent = {1, 1};
    headless.maxImageExtent = {4096, 2048};
    VkExtent2D e = vkt::choose_extent(headless, {800, 600});
    CHECK((e.width == 800 && e.height == 600));
    e = vkt::choose_extent(headless, {8000, 3000});
    CHECK((e.width == 4096 && e.height == 2048));
}

TEST_CASE("image count: one more than the minimum, within the maximum", "[swapchain]") {
    VkSurfaceCapabilitiesKHR c{};
    c.minImageCount = 2;
    c.maxImageCount = 0;  // no limit
    CHECK(vkt::choose_image_count(c) == 3);
    c.maxImageCount = 2;
    CHECK(vkt::choose_image_count(c) == 2);
}
