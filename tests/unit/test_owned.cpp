#include "vkt/core/owned.hpp"

#include <catch2/catch_test_macros.hpp>

#include <utility>

// A fake destroy function: counts calls and remembers the last handle.
namespace {
int destroyed = 0;
uint64_t last = 0;
void destroy_fake(VkDevice, VkFence fence, const VkAllocationCallbacks*) {
    ++destroyed;
    last = reinterpret_cast<uint64_t>(fence);
}
using FakeFence = vkt::Owned<VkFence, VkDevice, destroy_fake>;
VkFence handle(uint64_t value) {
    return reinterpret_cast<VkFence>(value);
}
}  // namespace

TEST_CASE("an owner destroys its handle once, when it goes", "[owned]") {
    destroyed = 0;
    {
        FakeFence f(VK_NULL_HANDLE, handle(7));
        CHECK(bool(f));
        CHECK(f.get() == handle(7));
    }
    CHECK(destroyed == 1);
    CHECK(last == 7);
}

TEST_CASE("moving hands the handle over without destroying it", "[owned]") {
    destroyed = 0;
    {
        FakeFence a(VK_NULL_HANDLE, handle(1));
        FakeFence b = std::move(a);
        CHECK_FALSE(bool(a));
        CHECK(b.get() == handle(1));
        CHECK(destroyed == 0);
        FakeFence c(VK_NULL_HANDLE, handle(2));
        c = std::move(b);  // c's old handle 2 is destroyed now
        CHECK(destroyed == 1);
        CHECK(last == 2);
    }
    CHECK(destroyed == 2);
    CHECK(last == 1);
}

TEST_CASE("an empty owner destroys nothing", "[owned]") {
    destroyed = 0;
    { FakeFence empty; }
    CHECK(destroyed == 0);
}
