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

}  // namespace

TEST_CASE("without present fences, a retired swapchain goes once a later present is proven over",
          "[swapchain][gpu]") {
    std::optional<vkt::Instance> instance;
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
    vkt::Device device(vkt::choose_device(candidates, ""), requirements);

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
