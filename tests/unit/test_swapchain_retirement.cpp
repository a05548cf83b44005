// Chapter 03's swapchain retirement (vkt/core/swapchain_retirement.hpp): the
// fallback's proof, step by step, on whatever device the loader offers. A
// retired "swapchain" here is a token whose destructor says when it went; the
// window tests (window_resize_storm.sh) retire real ones under validation.
#include "vkt/core/device.hpp"
#include "vkt/core/instance.hpp"
#include "vkt/core/swapchain_retirement.hpp"

#include <catch2/catch_test_macros.hpp>

#include <optional>
#include <utility>

namespace {

// Stands for a retired swapchain and its semaphores: notes its destruction.
struct Token {
    bool* gone;
    explicit Token(bool* flag) : gone(flag) {}
    Token(Token&& other) noexcept : gone(std::exchange(other.gone, nullptr)) {}
    Token& operator=(Token&&) = delete;
    ~Token() {
        if (gone) *gone = true;
    }
};

// An instance and the device the loader offers: the test is skipped without one.
struct AnyDevice {
    std::optional<vkt::Instance> instance;
    std::optional<vkt::Device> device;
    AnyDevice() {
        try {
            instance.emplace(vkt::InstanceConfig{.application_name = "test_swapchain_retirement"});
        } catch (const std::exception& e) {
            SKIP("no Vulkan instance: " << e.what());
        }
        const vkt::DeviceRequirements requirements{};
        const auto candidates = vkt::survey_devices(*instance, VK_NULL_HANDLE, requirements);
        bool any = false;
        for (const auto& candidate : candidates) any = any || candidate.unsuitable.empty();
        if (!any) SKIP("no Vulkan device");
        device.emplace(vkt::choose_device(candidates, ""), requirements);
    }
};

}  // namespace

TEST_CASE("without present fences, a retired swapchain goes once a later present is proven over",
          "[swapchain][gpu]") {
    const AnyDevice any;
    const vkt::Device& device = *any.device;

    bool first_gone = false, second_gone = false;
    {
        vkt::SwapchainRetirement retirement(device, false);
        CHECK_FALSE(retirement.present_fences());
        CHECK(retirement.present(0) == nullptr);  // nothing to chain without the extension
        retirement.acquired(1, 1);
        retirement.slot_finished(0);
        retirement.slot_finished(1);

        // Recreated: the first swapchain is retired, the new one presents image 2 first.
        retirement.retire(Token(&first_gone));
        CHECK(retirement.kept() == 1);
        retirement.acquired(2, 0);
        CHECK(retirement.present(2) == nullptr);
        // Other images come and go: they prove nothing about image 2's present.
        retirement.acquired(0, 1);
        retirement.present(0);
        retirement.slot_finished(0);
        retirement.slot_finished(1);
        CHECK_FALSE(first_gone);
        // Image 2 again, in slot 0: only once that frame is finished is its
        // earlier present over, and the first swapchain with it.
        retirement.acquired(2, 0);
        retirement.slot_finished(1);
        CHECK_FALSE(first_gone);
        retirement.slot_finished(0);
        CHECK(first_gone);
        CHECK(retirement.kept() == 0);

        // Two recreations before any proof: both wait, then go together.
        retirement.present(2);
        retirement.retire(Token(&second_gone));
        retirement.retire(Token(&first_gone));  // a token already counted: reset below
        first_gone = false;
        CHECK(retirement.kept() == 2);
        retirement.acquired(0, 1);
        retirement.present(0);
        retirement.slot_finished(1);
        CHECK(retirement.kept() == 2);
        retirement.acquired(0, 1);
        retirement.slot_finished(1);
        CHECK(second_gone);
        CHECK(first_gone);
        CHECK(retirement.kept() == 0);

        // What is still retired when the loop ends goes with the retirement.
        second_gone = false;
        retirement.present(0);
        retirement.retire(Token(&second_gone));
        CHECK_FALSE(second_gone);
    }
    CHECK(second_gone);
}

TEST_CASE("with present fences, a retired swapchain goes once its presents' fences signal",
          "[swapchain][gpu]") {
    // The present-fence path (VK_EXT_swapchain_maintenance1), which lavapipe
    // takes only in a window under a 1.3.290+ layer: each present's fence is
    // taken from the pNext chain present() returns, and signalled here by an
    // empty submission, as the driver would once the present let go.
    const AnyDevice any;
    const vkt::Device& device = *any.device;
    const auto fence_of = [](const void* next) {
        const auto* info = static_cast<const VkSwapchainPresentFenceInfoEXT*>(next);
        REQUIRE(info != nullptr);
        CHECK(info->sType == VK_STRUCTURE_TYPE_SWAPCHAIN_PRESENT_FENCE_INFO_EXT);
        CHECK(info->swapchainCount == 1);
        return info->pFences[0];
    };
    const auto signal = [&](VkFence fence) {
        REQUIRE(vkQueueSubmit(device.queue(), 0, nullptr, fence) == VK_SUCCESS);
        REQUIRE(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX) == VK_SUCCESS);
    };

    bool old_gone = false, newer_gone = false;
    {
        vkt::SwapchainRetirement retirement(device, true);
        CHECK(retirement.present_fences());
        const VkFence old_present = fence_of(retirement.present(0));
        retirement.retire(Token(&old_gone));  // recreated: the first swapchain retired
        const VkFence new_present = fence_of(retirement.present(1));
        CHECK(new_present != old_present);
        retirement.slot_finished(0);
        CHECK_FALSE(old_gone);  // its present may still hold its semaphore
        CHECK(retirement.kept() == 1);
        // Its fence signals: it goes, although the new swapchain's present
        // is still pending (that one proves nothing about the old).
        signal(old_present);
        retirement.slot_finished(0);
        CHECK(old_gone);
        CHECK(retirement.kept() == 0);
        // The signalled fence is reset and reused for the next present.
        const VkFence reused = fence_of(retirement.present(2));
        CHECK(reused == old_present);
        CHECK(vkGetFenceStatus(device, reused) == VK_NOT_READY);
        // A second retirement waits for both pending presents of its own
        // swapchain, whichever signals first.
        retirement.retire(Token(&newer_gone));
        signal(reused);
        retirement.slot_finished(1);
        CHECK_FALSE(newer_gone);  // new_present, of the same swapchain, still pending
        signal(new_present);
        retirement.slot_finished(1);
        CHECK(newer_gone);
        CHECK(retirement.kept() == 0);
    }
}
