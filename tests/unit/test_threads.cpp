// Chapter 27's plain C++ (chapters/27_threads/): the crew of worker threads
// runs every share exactly once per frame, on as many threads as asked, and
// hands back what they wrote and what they threw; the pipeline cache's
// header check accepts this device's header and refuses a short, garbled or
// foreign one, saying which.

#include "../../chapters/27_threads/pipeline_cache.hpp"
#include "../../chapters/27_threads/workers.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <atomic>
#include <chrono>
#include <cstring>
#include <set>
#include <stdexcept>
#include <thread>

using Catch::Matchers::ContainsSubstring;

TEST_CASE("chapter 27's workers run every index once per run, on its own thread", "[threads]") {
    for (uint32_t count : {1u, 2u, 7u}) {
        ch27::Workers workers(count);
        REQUIRE(workers.count() == count);
        std::vector<int> calls(count, 0);  // each index writes only its own element
        std::vector<std::thread::id> ids(count);
        for (int frame = 0; frame < 200; ++frame)
            workers.run([&](uint32_t i) {
                ++calls[i];
                ids[i] = std::this_thread::get_id();
            });
        // Read after the join: every write is visible (ThreadSanitizer and
        // the asan preset would flag a race here).
        for (uint32_t i = 0; i < count; ++i) CHECK(calls[i] == 200);
        CHECK(ids[0] == std::this_thread::get_id());  // index 0 is the caller's
        CHECK(std::set<std::thread::id>(ids.begin(), ids.end()).size() == count);
    }
}

TEST_CASE("chapter 27's workers: run returns only when every share is done", "[threads]") {
    ch27::Workers workers(4);
    std::atomic<int> finished = 0;
    for (int frame = 0; frame < 50; ++frame) {
        finished = 0;
        workers.run([&](uint32_t i) {
            if (i == 3) std::this_thread::sleep_for(std::chrono::milliseconds(1));
            ++finished;
        });
        CHECK(finished == 4);
    }
}

TEST_CASE("chapter 27's workers hand an exception of any share to the caller", "[threads]") {
    ch27::Workers workers(3);
    CHECK_THROWS_WITH(workers.run([](uint32_t i) {
        if (i == 2) throw std::runtime_error("share 2 failed");
    }),
                      "share 2 failed");
    // And the crew still works afterwards.
    int calls = 0;
    workers.run([&](uint32_t i) {
        if (i == 0) ++calls;
    });
    CHECK(calls == 1);
}

namespace {

VkPhysicalDeviceProperties this_device() {
    VkPhysicalDeviceProperties p{};
    p.vendorID = 0x10005;
    p.deviceID = 0;
    std::strcpy(p.deviceName, "llvmpipe");
    for (uint8_t i = 0; i < VK_UUID_SIZE; ++i) p.pipelineCacheUUID[i] = uint8_t(i * 17);
    return p;
}

std::vector<char> header_of(const VkPhysicalDeviceProperties& p) {
    VkPipelineCacheHeaderVersionOne h{};
    h.headerSize = 32;
    h.headerVersion = VK_PIPELINE_CACHE_HEADER_VERSION_ONE;
    h.vendorID = p.vendorID;
    h.deviceID = p.deviceID;
    std::memcpy(h.pipelineCacheUUID, p.pipelineCacheUUID, VK_UUID_SIZE);
    std::vector<char> data(sizeof h + 10, 'x');  // the driver's data follows
    std::memcpy(data.data(), &h, sizeof h);
    return data;
}

}  // namespace

TEST_CASE("chapter 27's cache header check", "[threads]") {
    const VkPhysicalDeviceProperties me = this_device();
    static_assert(sizeof(VkPipelineCacheHeaderVersionOne) == 32);
    CHECK(ch27::cache_header_problem(header_of(me), me).empty());

    std::vector<char> data = header_of(me);
    CHECK_THAT(ch27::cache_header_problem({data.begin(), data.begin() + 31}, me),
               ContainsSubstring("31 bytes, shorter than the 32-byte header"));
    CHECK_THAT(ch27::cache_header_problem({}, me), ContainsSubstring("0 bytes"));

    data[0] = 40;  // headerSize
    CHECK_THAT(ch27::cache_header_problem(data, me),
               ContainsSubstring("header size 40, version 1; expected 32, 1"));
    data = header_of(me);
    data[4] = 2;  // headerVersion
    CHECK_THAT(ch27::cache_header_problem(data, me), ContainsSubstring("version 2"));

    VkPhysicalDeviceProperties other = me;
    other.vendorID = 0x10de;
    CHECK_THAT(ch27::cache_header_problem(header_of(other), me),
               ContainsSubstring("made by another device or driver (vendor 0x10de, device 0x0"));
    other = me;
    other.deviceID = 7;
    CHECK_THAT(ch27::cache_header_problem(header_of(other), me), ContainsSubstring("device 0x7"));
    // The same vendor and device, another driver build: only the UUID differs.
    other = me;
    other.pipelineCacheUUID[15] ^= 1;
    CHECK_THAT(ch27::cache_header_problem(header_of(other), me),
               ContainsSubstring("cache UUID 00112233445566778899aabbccddeefe; this one is "
                                 "llvmpipe, cache UUID 00112233445566778899aabbccddeeff"));
}
