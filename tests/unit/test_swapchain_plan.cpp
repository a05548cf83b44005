// plan_swapchain (chapter 03): every setting of the swapchain from what the
// surface offers, for surfaces that lack what a typical window has: no
// TRANSFER_DST usage (the specification promises only COLOR_ATTACHMENT), no
// opaque composite alpha, no _SRGB format, no TRANSFER_SRC for --screenshot.

#include "vkt/core/check.hpp"
#include "vkt/core/swapchain.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

using Catch::Matchers::ContainsSubstring;

namespace {

constexpr VkImageUsageFlags attach = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
constexpr VkImageUsageFlags copy_in = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr VkImageUsageFlags copy_out = VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

// A window as X11 drivers usually offer it: _SRGB and _UNORM BGRA, opaque,
// every usage, FIFO and MAILBOX, a fixed size.
vkt::SurfaceOffer window() {
    vkt::SurfaceOffer offer;
    offer.capabilities.minImageCount = 2;
    offer.capabilities.maxImageCount = 8;
    offer.capabilities.currentExtent = {640, 480};
    offer.capabilities.minImageExtent = {1, 1};
    offer.capabilities.maxImageExtent = {16384, 16384};
    offer.capabilities.supportedTransforms = VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR;
    offer.capabilities.currentTransform = VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR;
    offer.capabilities.supportedCompositeAlpha =
        VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR | VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
    offer.capabilities.supportedUsageFlags = attach | copy_in | copy_out;
    offer.formats = {{VK_FORMAT_B8G8R8A8_SRGB, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR},
                     {VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR}};
    offer.modes = {VK_PRESENT_MODE_FIFO_KHR, VK_PRESENT_MODE_MAILBOX_KHR};
    return offer;
}

// What the runner asks by default: draw straight in where possible.
vkt::SwapchainRequest drawing() {
    return {.extent = {800, 600}, .draw_into = true};
}

}  // namespace

TEST_CASE("a typical window: drawn into, with only the usages needed", "[swapchain]") {
    const vkt::SwapchainPlan plan = vkt::plan_swapchain(window(), drawing());
    CHECK(plan.drawn_into);
    CHECK_FALSE(plan.readable);
    CHECK(plan.usage == attach);  // no TRANSFER_DST: nothing is copied in
    CHECK(plan.format.format == VK_FORMAT_B8G8R8A8_SRGB);
    CHECK(plan.extent.width == 640);
    CHECK(plan.image_count == 3);
    CHECK(plan.present_mode == VK_PRESENT_MODE_FIFO_KHR);
    CHECK(plan.composite_alpha == VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR);
    CHECK(plan.transform == VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR);
    CHECK(plan.clipped);  // nothing reads the images: hidden pixels may be skipped
}

TEST_CASE("a chapter that clears or copies into its frame gets TRANSFER_DST", "[swapchain]") {
    vkt::SwapchainRequest request = drawing();
    request.transfer_into = true;
    const vkt::SwapchainPlan plan = vkt::plan_swapchain(window(), request);
    CHECK(plan.drawn_into);
    CHECK(plan.usage == (attach | copy_in));
}

TEST_CASE("a screenshot adds TRANSFER_SRC where offered", "[swapchain]") {
    vkt::SwapchainRequest request = drawing();
    request.readable = true;
    const vkt::SwapchainPlan plan = vkt::plan_swapchain(window(), request);
    CHECK(plan.readable);
    CHECK(plan.drawn_into);
    CHECK(plan.usage == (attach | copy_out));
    // Read back, pixels behind another window must be kept: clipped would
    // leave them undefined.
    CHECK_FALSE(plan.clipped);
}

TEST_CASE("copied in with --copy-to-swapchain: no COLOR_ATTACHMENT", "[swapchain]") {
    vkt::SwapchainRequest request = drawing();
    request.draw_into = false;
    const vkt::SwapchainPlan plan = vkt::plan_swapchain(window(), request);
    CHECK_FALSE(plan.drawn_into);
    CHECK(plan.usage == copy_in);
}

TEST_CASE("no TRANSFER_DST usage", "[swapchain]") {
    vkt::SurfaceOffer offer = window();
    offer.capabilities.supportedUsageFlags = attach | copy_out;
    SECTION("drawing straight in needs none") {
        const vkt::SwapchainPlan plan = vkt::plan_swapchain(offer, drawing());
        CHECK(plan.drawn_into);
        CHECK(plan.usage == attach);
    }
    SECTION("a chapter that clears into its frame cannot run, and is told why") {
        vkt::SwapchainRequest request = drawing();
        request.transfer_into = true;
        REQUIRE_THROWS_WITH(
            vkt::plan_swapchain(offer, request),
            ContainsSubstring("no TRANSFER_DST usage") && ContainsSubstring("transfer commands"));
    }
    SECTION("--copy-to-swapchain cannot copy") {
        vkt::SwapchainRequest request = drawing();
        request.draw_into = false;
        REQUIRE_THROWS_WITH(vkt::plan_swapchain(offer, request),
                            ContainsSubstring("--copy-to-swapchain"));
    }
    SECTION("with only _UNORM formats there is no way in") {
        offer.formats = {{VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR}};
        REQUIRE_THROWS_WITH(
            vkt::plan_swapchain(offer, drawing()),
            ContainsSubstring("not an _SRGB one") && ContainsSubstring("B8G8R8A8_UNORM"));
    }
}

TEST_CASE("no opaque composite alpha: the first mode offered", "[swapchain]") {
    vkt::SurfaceOffer offer = window();
    offer.capabilities.supportedCompositeAlpha =
        VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR | VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
    CHECK(vkt::plan_swapchain(offer, drawing()).composite_alpha ==
          VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR);
    CHECK(vkt::choose_composite_alpha(VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR) ==
          VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR);
}

TEST_CASE("no _SRGB format (lavapipe's headless surface): copied in", "[swapchain]") {
    vkt::SurfaceOffer offer = window();
    offer.capabilities.currentExtent = {UINT32_MAX, UINT32_MAX};  // "you choose"
    offer.formats = {{VK_FORMAT_R8G8B8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR},
                     {VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR}};
    vkt::SwapchainRequest request = drawing();
    request.readable = true;
    const vkt::SwapchainPlan plan = vkt::plan_swapchain(offer, request);
    CHECK_FALSE(plan.drawn_into);  // our linear colours would be taken as encoded
    CHECK(plan.usage == (copy_in | copy_out));
    CHECK(plan.extent.width == 800);
    CHECK(plan.extent.height == 600);
}

TEST_CASE("no TRANSFER_SRC: --screenshot reads our own target instead", "[swapchain]") {
    vkt::SurfaceOffer offer = window();
    offer.capabilities.supportedUsageFlags = attach | copy_in;
    vkt::SwapchainRequest request = drawing();
    request.readable = true;
    const vkt::SwapchainPlan plan = vkt::plan_swapchain(offer, request);
    CHECK_FALSE(plan.readable);
    CHECK_FALSE(plan.drawn_into);  // the frame goes through our target, which is read back
    CHECK(plan.usage == copy_in);
}
