// Chapter 13's dispatch arithmetic (vkt/resources/compute.hpp): how many workgroups
// cover n items, how many items one dispatch may cover under a device's
// limits, and the split of a large job into dispatches; the std430 layout of
// the particle, C++ against the compiled shader; and, on whatever device the
// loader offers, the compute pipeline and barrier helpers running the
// chapter's shaders, against a CPU reference and a bounds-check sentinel.
#include "../../chapters/13_compute/particle.hpp"
#include "spirv_reflect.hpp"
#include "vkt/core/check.hpp"
#include "vkt/core/device.hpp"
#include "vkt/core/instance.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace {

// Only the limits max_items_per_dispatch reads.
VkPhysicalDeviceLimits limits(uint32_t max_groups_x, uint32_t max_range, uint32_t alignment) {
    VkPhysicalDeviceLimits l{};
    l.maxComputeWorkGroupCount[0] = max_groups_x;
    l.maxStorageBufferRange = max_range;
    l.minStorageBufferOffsetAlignment = alignment;
    return l;
}

}  // namespace

TEST_CASE("dispatch_count is ceil(n / group)", "[compute]") {
    // Multiples of the workgroup: exact.
    CHECK(vkt::dispatch_count(256, 256) == 1);
    CHECK(vkt::dispatch_count(65536, 256) == 256);
    CHECK(vkt::dispatch_count(1048576, 256) == 4096);
    CHECK(vkt::dispatch_count(16777216, 256) == 65536);
    // Not multiples: one more, partly idle, group.
    CHECK(vkt::dispatch_count(1, 256) == 1);
    CHECK(vkt::dispatch_count(255, 256) == 1);
    CHECK(vkt::dispatch_count(257, 256) == 2);
    CHECK(vkt::dispatch_count(1000, 256) == 4);  // 1024 invocations, 24 idle
    CHECK(vkt::dispatch_count(65537, 256) == 257);
    CHECK(vkt::dispatch_count(1000, 64) == 16);
    // Nothing to do: no groups. A group of one: one per item.
    CHECK(vkt::dispatch_count(0, 256) == 0);
    CHECK(vkt::dispatch_count(12345, 1) == 12345);
    // No overflow at the top of the range (n + group - 1 would wrap to 254).
    CHECK(vkt::dispatch_count(std::numeric_limits<uint64_t>::max(), 256) == (uint64_t(1) << 56));
    CHECK_THROWS_AS(vkt::dispatch_count(10, 0), std::invalid_argument);
    static_assert(vkt::dispatch_count(1000, 256) == 4);  // usable at compile time
}

TEST_CASE("max_items_per_dispatch: the smaller of the group-count and range limits", "[compute]") {
    // Lavapipe: 65,535 groups (16,776,960 items) but 128 MiB per descriptor,
    // 4,194,304 particles of 32 bytes: the range limits.
    CHECK(vkt::max_items_per_dispatch(limits(65535, 134217728, 16), 256, 32) == 4194304);
    // The smallest limits the specification allows (2^27 bytes, 65,535
    // groups, alignment up to 256): the same.
    CHECK(vkt::max_items_per_dispatch(limits(65535, 1u << 27, 256), 256, 32) == 4194304);
    // A range of 4 GiB - 1 with the minimum 65,535 groups: the group count
    // limits, and 16,777,216 particles need a second dispatch of one group.
    CHECK(vkt::max_items_per_dispatch(limits(65535, 0xffffffffu, 16), 256, 32) == 16776960);
    // A large GPU (2^31 - 1 groups, 4 GiB - 1 bytes): floor((2^32 - 1) / 32)
    // = 134,217,727, rounded down to whole workgroups.
    CHECK(vkt::max_items_per_dispatch(limits(0x7fffffffu, 0xffffffffu, 16), 256, 32) == 134217472);
    // Whole workgroups AND aligned offsets: items of 12 bytes, groups of 1,
    // alignment 64: a chunk must be a multiple of 16 items (192 bytes).
    CHECK(vkt::max_items_per_dispatch(limits(1000, 1000, 64), 1, 12) == 80);  // 83 -> 80
    // Not even one workgroup fits: an error, not zero.
    CHECK_THROWS_AS(vkt::max_items_per_dispatch(limits(65535, 4096, 16), 256, 32), vkt::Error);
    CHECK_THROWS_AS(vkt::max_items_per_dispatch(limits(0, 1u << 27, 16), 256, 32), vkt::Error);
}

TEST_CASE("split_dispatch: full chunks, then the rest", "[compute]") {
    SECTION("one dispatch when it fits") {
        const auto chunks = vkt::split_dispatch(65536, 256, 4194304);
        REQUIRE(chunks.size() == 1);
        CHECK(chunks[0].first == 0);
        CHECK(chunks[0].count == 65536);
        CHECK(chunks[0].groups == 256);
    }
    SECTION("16,777,216 particles on lavapipe: four dispatches of 4,194,304") {
        const auto chunks = vkt::split_dispatch(16777216, 256, 4194304);
        REQUIRE(chunks.size() == 4);
        for (size_t i = 0; i < 4; ++i) {
            CHECK(chunks[i].first == i * 4194304);
            CHECK(chunks[i].count == 4194304);
            CHECK(chunks[i].groups == 16384);
        }
    }
    SECTION("16,777,216 with only the group-count limit: 65,535 groups, then 1") {
        const auto chunks = vkt::split_dispatch(16777216, 256, 16776960);
        REQUIRE(chunks.size() == 2);
        CHECK(chunks[0].groups == 65535);
        CHECK(chunks[1].first == 16776960);
        CHECK(chunks[1].count == 256);
        CHECK(chunks[1].groups == 1);
    }
    SECTION("a last chunk that is not whole workgroups") {
        const auto chunks = vkt::split_dispatch(1000, 256, 512);
        REQUIRE(chunks.size() == 2);
        CHECK(chunks[0].count == 512);
        CHECK(chunks[0].groups == 2);
        CHECK(chunks[1].first == 512);
        CHECK(chunks[1].count == 488);
        CHECK(chunks[1].groups == 2);  // 512 invocations, 24 idle
    }
    SECTION("nothing") {
        CHECK(vkt::split_dispatch(0, 256, 512).empty());
    }
    SECTION("a chunk size that is not whole workgroups is a bug") {
        CHECK_THROWS_AS(vkt::split_dispatch(1000, 256, 300), std::invalid_argument);
        CHECK_THROWS_AS(vkt::split_dispatch(1000, 256, 0), std::invalid_argument);
    }
}

TEST_CASE("the particle's std430 layout matches the compiled compute shader", "[compute]") {
    const auto words = spirv::read(VKT_BINARY_DIR "/shaders/13_compute/simulate.comp.spv");
    const auto particle = spirv::offsets(words, "Particle");
    CHECK(particle.at("position") == offsetof(Particle, position));
    CHECK(particle.at("velocity") == offsetof(Particle, velocity));
    // The array of particles in the storage buffer: one Particle apart.
    CHECK(spirv::struct_members(words, "Particles").at("particles").array_stride ==
          sizeof(Particle));
}

// --- On a device: the helpers, the bounds check and the shaders' arithmetic --

namespace {

// The CPU reference of init.comp and simulate.comp, written from their
// formulas: the same hash, the same galaxy, the same semi-implicit Euler.
uint32_t hash(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
float uniform01(uint32_t i, uint32_t s) {
    return float(hash(i * 4u + s) >> 8) / 16777216.0f;
}

Particle cpu_particle(uint32_t i, uint32_t steps, float dt) {
    const float u = uniform01(i, 0), r = 0.08f + 1.6f * u;
    const float angle =
        float(i % 3u) * 2.0943951f + 2.6f * r + (uniform01(i, 1) - 0.5f) * (0.35f + 0.5f * r);
    const float height = (uniform01(i, 2) - 0.5f) * 0.08f;
    const float d2 = r * r + 0.02f;
    const float speed = std::sqrt(r * r / (d2 * std::sqrt(d2))) * (0.97f + 0.06f * uniform01(i, 3));
    glm::vec3 x(r * std::cos(angle), height, r * std::sin(angle));
    glm::vec3 v = speed * glm::vec3(-std::sin(angle), 0.0f, std::cos(angle));
    for (uint32_t s = 0; s < steps; ++s) {
        const float e2 = glm::dot(x, x) + 0.02f;
        v += -x / (e2 * std::sqrt(e2)) * dt;
        x += v * dt;
    }
    return {glm::vec4(x, u), glm::vec4(v, 0.0f)};
}

}  // namespace

TEST_CASE("the compute shaders on a device match the CPU, and idle invocations write nothing",
          "[compute][gpu]") {
    // Whatever device the loader offers (the tests' lavapipe, or a GPU).
    std::optional<vkt::Instance> instance;
    try {
        instance.emplace(vkt::InstanceConfig{
            .application_name = "test_dispatch",
            .validation = vkt::instance_layer_available(vkt::validation_layer_name)});
    } catch (const std::exception& e) {
        SKIP("no Vulkan instance: " << e.what());
    }
    vkt::DeviceRequirements requirements{.features = {VKT_FEATURE_13(maintenance4)}};
    const auto candidates = vkt::survey_devices(*instance, VK_NULL_HANDLE, requirements);
    bool any = false;
    for (const auto& candidate : candidates) any = any || candidate.unsuitable.empty();
    if (!any) SKIP("no Vulkan device can run chapter 13");
    {
        vkt::Device device(vkt::choose_device(candidates, ""), requirements);
        const vkt::Gpu gpu{device.physical(), device, device.queue(), device.queue_family()};

        // 1000 particles: 4 workgroups of 256, 24 idle invocations. The
        // buffer has room for 1024, and the last 24 hold a sentinel that the
        // bounds check must leave alone.
        constexpr uint32_t count = 1000, room = 1024, steps = 18, group = 256;
        const float dt = 1.0f / 120.0f;
        vkt::Buffer buffer = vkt::create_host_buffer(gpu, room * sizeof(Particle),
                                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        auto* particles = static_cast<Particle*>(buffer.mapped);
        const Particle sentinel{glm::vec4(-7.0f), glm::vec4(-7.0f)};
        for (uint32_t i = 0; i < room; ++i) particles[i] = sentinel;

        const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                                   VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        vkt::DescriptorSetLayout set_layout =
            vkt::create_descriptor_set_layout(device, {&binding, 1});
        const VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
        vkt::DescriptorPool pool = vkt::create_descriptor_pool(device, 1, {&pool_size, 1});
        const VkDescriptorSet set = vkt::allocate_descriptor_set(device, pool, set_layout);
        vkt::write_buffer_descriptor(device, set, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     buffer.buffer, 0, VK_WHOLE_SIZE);
        const VkPushConstantRange push_range{VK_SHADER_STAGE_COMPUTE_BIT, 0, 16};
        const VkDescriptorSetLayout layouts[] = {set_layout};
        vkt::PipelineLayout layout = vkt::create_pipeline_layout(device, layouts, {&push_range, 1});
        const VkSpecializationMapEntry entry{0, 0, sizeof(uint32_t)};
        const VkSpecializationInfo specialization{1, &entry, sizeof(group), &group};
        vkt::ShaderModule init_shader = vkt::load_shader(device, "13_compute", "init.comp");
        vkt::ShaderModule simulate_shader = vkt::load_shader(device, "13_compute", "simulate.comp");
        vkt::Pipeline init =
            vkt::create_compute_pipeline(device, init_shader, layout, &specialization);
        vkt::Pipeline simulate =
            vkt::create_compute_pipeline(device, simulate_shader, layout, &specialization);

        const auto groups = uint32_t(vkt::dispatch_count(count, group));
        REQUIRE(groups == 4);
        vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
            struct {
                uint32_t first, count, steps;
                float dt;
            } push{0, count, steps, dt};
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0,
                                    nullptr);
            vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, 16, &push);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, init);
            vkCmdDispatch(cmd, groups, 1, 1);
            vkt::buffer_barrier(
                cmd, buffer.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, simulate);
            vkCmdDispatch(cmd, groups, 1, 1);
            // The host reads the result: make the writes visible to it.
            vkt::buffer_barrier(cmd, buffer.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                                VK_ACCESS_2_HOST_READ_BIT);
        });

        // The GPU's sin, cos and sqrt may differ from the CPU's in the last
        // bits, and 18 steps carry that along: 1e-4 of a galaxy 3.4 wide.
        float worst = 0.0f;
        for (uint32_t i = 0; i < count; ++i) {
            const Particle expected = cpu_particle(i, steps, dt);
            worst =
                std::max({worst, glm::length(glm::vec3(particles[i].position - expected.position)),
                          glm::length(glm::vec3(particles[i].velocity - expected.velocity))});
            REQUIRE(particles[i].position.w == expected.position.w);  // exact: integer hash
        }
        INFO("largest difference from the CPU: " << worst);
        CHECK(worst < 1e-4f);
        for (uint32_t i = count; i < room; ++i) {
            INFO("particle " << i << " is past the end");
            CHECK(particles[i].position == sentinel.position);
            CHECK(particles[i].velocity == sentinel.velocity);
        }
    }
    // Everything is destroyed: the layer saw no misuse and no hazard.
    CHECK(instance->counts()->warnings == 0);
    CHECK(instance->counts()->errors == 0);
}
