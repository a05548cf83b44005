// as_bench: what chapter 24's acceleration structures cost to build, timed
// on the GPU with timestamp queries. Not a test: it prints one line per figure.
//
//   build/release/bin/as_bench [--rounds R] [--builds B] [--instances N,N,...]
//                              [--dense S,S,...] [--device NAME|INDEX] [--no-validation]
//
// Bottom levels: chapter 24's four meshes (its build_bottom_levels once, for
// its report; then each mesh alone) and, for each S of --dense, a UV sphere
// of S slices and S/2 stacks (16-bit indices where its vertices fit, else
// 32-bit): build time, built and compacted size, compacting copy time.
// Top level: chapter 24's TopLevel at each N of --instances; per round B
// builds from nothing (--tlas rebuild) and B refits (--tlas update), every
// instance moved before each. Each line: the median of the R rounds' medians
// and their spread [min..max]. Exit status 1 without a device that has
// VK_KHR_acceleration_structure (acceleration_device.hpp) or after any
// validation message; 2 for bad arguments.
#include "bottom_level.hpp"
#include "top_level.hpp"

#include "acceleration_device.hpp"

#include "vkt/core/instance.hpp"
#include "vkt/frame/args.hpp"
#include "vkt/scene/camera_math.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <vector>

namespace {

struct Spread {
    double median = 0, min = 0, max = 0;
};

double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n == 0 ? 0.0 : n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

Spread spread_of(const std::vector<double>& values) {
    return {median_of(values), *std::min_element(values.begin(), values.end()),
            *std::max_element(values.begin(), values.end())};
}

std::vector<uint32_t> parse_list(const std::string& flag, const std::string& text, uint32_t min,
                                 uint32_t max) {
    std::vector<uint32_t> out;
    for (size_t start = 0; start <= text.size();) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        char* end = nullptr;
        const unsigned long value = std::strtoul(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || value < min || value > max)
            throw vkt::UsageError(flag + " wants whole numbers from " + std::to_string(min) +
                                  " to " + std::to_string(max) + " separated by commas, not '" +
                                  text + "'");
        out.push_back(uint32_t(value));
        start = comma + 1;
    }
    return out;
}

// Two timestamps around the commands a lambda records, read back as
// milliseconds once the submit has finished.
class Stopwatch {
public:
    Stopwatch(const vkt::Gpu& gpu, const VkPhysicalDeviceProperties& properties)
        : gpu_(gpu), period_ns_(properties.limits.timestampPeriod) {
        const VkQueryPoolCreateInfo info{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                         .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                         .queryCount = 2};
        VkQueryPool pool;
        VKT_CHECK(vkCreateQueryPool(gpu.device, &info, nullptr, &pool));
        pool_ = vkt::QueryPool(gpu.device, pool);
    }
    template <typename Record>
    double time_ms(Record&& record) {
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            vkCmdResetQueryPool(cmd, pool_, 0, 2);
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 0);
            record(cmd);
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 1);
        });
        uint64_t ticks[2];
        VKT_CHECK(vkGetQueryPoolResults(gpu_.device, pool_, 0, 2, sizeof ticks, ticks,
                                        sizeof(uint64_t),
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
        return double(ticks[1] - ticks[0]) * double(period_ns_) * 1e-6;
    }

private:
    const vkt::Gpu& gpu_;
    float period_ns_;
    vkt::QueryPool pool_;
};

// The barrier chapter 24 puts between a build and what reads its result.
const VkMemoryBarrier2 build_to_build{
    .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
    .srcStageMask = VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
    .srcAccessMask = VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
    .dstStageMask = VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
    .dstAccessMask = VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                     VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
};
const VkDependencyInfo after_build{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                   .memoryBarrierCount = 1,
                                   .pMemoryBarriers = &build_to_build};

// One triangle mesh on the GPU, as the builds read it.
struct Mesh {
    std::string name;
    ch24::AddressBuffer vertices, indices;
    uint32_t vertex_count = 0, triangles = 0;
    VkIndexType index_type = VK_INDEX_TYPE_UINT16;
};

template <typename Index>
Mesh upload_mesh(const vkt::Gpu& gpu, std::string name,
                 const std::vector<vkt::shapes::Vertex>& vertices,
                 const std::vector<Index>& indices) {
    constexpr VkBufferUsageFlags input =
        VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
        VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    Mesh mesh{
        .name = std::move(name),
        .vertices =
            ch24::create_address_buffer(gpu, vertices.size() * sizeof vertices[0], input, false),
        .indices = ch24::create_address_buffer(gpu, indices.size() * sizeof(Index), input, false),
        .vertex_count = uint32_t(vertices.size()),
        .triangles = uint32_t(indices.size() / 3),
        .index_type = sizeof(Index) == 2 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32};
    vkt::upload_to_buffer(gpu, mesh.vertices.owner.buffer, vertices.data(),
                          mesh.vertices.owner.size);
    vkt::upload_to_buffer(gpu, mesh.indices.owner.buffer, indices.data(), mesh.indices.owner.size);
    return mesh;
}

// MeshBuilder's sphere, with 32-bit indices: the dense spheres whose
// vertices outgrow 16 bits. Positions only matter to the build.
Mesh wide_sphere(const vkt::Gpu& gpu, std::string name, uint32_t slices, uint32_t stacks) {
    std::vector<vkt::shapes::Vertex> vertices;
    std::vector<uint32_t> indices;
    for (uint32_t j = 0; j <= stacks; ++j)
        for (uint32_t i = 0; i <= slices; ++i) {
            const float theta = std::numbers::pi_v<float> * float(j) / float(stacks),
                        phi = 2.0f * std::numbers::pi_v<float> * float(i) / float(slices);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            vertices.push_back({0.5f * n, n});
        }
    for (uint32_t j = 0; j < stacks; ++j)
        for (uint32_t i = 0; i < slices; ++i) {
            const uint32_t a = j * (slices + 1) + i, below = a + slices + 1;
            if (j != 0) indices.insert(indices.end(), {a, a + 1, below + 1});
            if (j + 1 != stacks) indices.insert(indices.end(), {a, below + 1, below});
        }
    return upload_mesh(gpu, std::move(name), vertices, indices);
}

struct BottomSample {
    double build_ms = 0, copy_ms = 0;
    VkDeviceSize built = 0, compacted = 0, scratch = 0;
};

// One mesh's bottom level as chapter 24 builds it (PREFER_FAST_TRACE,
// ALLOW_COMPACTION, opaque), timed alone: the build, then the compacting copy.
BottomSample time_bottom_level(const vkt::Gpu& gpu, const ch24::RayFunctions& ray,
                               VkDeviceSize alignment, Stopwatch& watch, const Mesh& mesh) {
    const VkAccelerationStructureGeometryKHR geometry = ch24::triangle_geometry(
        mesh.vertices.address, mesh.vertex_count, mesh.index_type, mesh.indices.address);
    VkAccelerationStructureBuildGeometryInfoKHR build = ch24::bottom_level_build(&geometry);
    VkAccelerationStructureBuildSizesInfoKHR sizes{
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    ray.build_sizes(gpu.device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build,
                    &mesh.triangles, &sizes);
    BottomSample out{.built = sizes.accelerationStructureSize, .scratch = sizes.buildScratchSize};
    ch24::AccelerationStructure built(gpu, ray, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                                      sizes.accelerationStructureSize);
    const ch24::AddressBuffer scratch = ch24::create_address_buffer(
        gpu, sizes.buildScratchSize + alignment, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    build.dstAccelerationStructure = built.get();
    build.scratchData.deviceAddress = vkt::align_up(scratch.address, alignment);

    const VkQueryPoolCreateInfo pool_info{
        .sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
        .queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR,
        .queryCount = 1};
    VkQueryPool raw_pool;
    VKT_CHECK(vkCreateQueryPool(gpu.device, &pool_info, nullptr, &raw_pool));
    const vkt::QueryPool pool(gpu.device, raw_pool);
    const VkAccelerationStructureBuildRangeInfoKHR range{.primitiveCount = mesh.triangles};
    const VkAccelerationStructureBuildRangeInfoKHR* ranges[] = {&range};
    const VkAccelerationStructureKHR handle = built.get();
    out.build_ms = watch.time_ms([&](VkCommandBuffer cmd) {
        vkCmdResetQueryPool(cmd, pool, 0, 1);
        ray.cmd_build(cmd, 1, &build, ranges);
        vkCmdPipelineBarrier2(cmd, &after_build);
        ray.cmd_write_properties(cmd, 1, &handle,
                                 VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, pool, 0);
    });
    VKT_CHECK(vkGetQueryPoolResults(gpu.device, pool, 0, 1, sizeof out.compacted, &out.compacted,
                                    sizeof out.compacted,
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const ch24::AccelerationStructure compacted(
        gpu, ray, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, out.compacted);
    const VkCopyAccelerationStructureInfoKHR copy{
        .sType = VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR,
        .src = built.get(),
        .dst = compacted.get(),
        .mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR};
    out.copy_ms = watch.time_ms([&](VkCommandBuffer cmd) {
        vkCmdPipelineBarrier2(cmd, &after_build);
        ray.cmd_copy(cmd, &copy);
    });
    return out;
}

// N instances of the chapter's four meshes on a grid, each bobbing and
// turning with time t: after a step of t every instance has moved.
void place(uint32_t n, double time, std::span<const VkDeviceAddress> bottom,
           std::vector<glm::mat4>& transforms, std::vector<VkDeviceAddress>& addresses) {
    transforms.resize(n);
    addresses.resize(n);
    const uint32_t row = uint32_t(std::ceil(std::sqrt(double(n))));
    const float t = float(time);
    for (uint32_t i = 0; i < n; ++i) {
        const float x = 2.0f * float(i % row), z = -2.0f * float(i / row);
        transforms[i] = vkt::transform({x, std::sin(2.0f * t + 0.1f * float(i)), z}, t + float(i),
                                       {0, 1, 0}, glm::vec3(0.8f));
        addresses[i] = bottom[i % bottom.size()];
    }
}

double kib(VkDeviceSize bytes) {
    return double(bytes) / 1024.0;
}

void bench(const vkt::Gpu& gpu, const VkPhysicalDeviceProperties& properties, const char* tracer,
           bool validation, const vkt::Options& options,
           const std::vector<uint32_t>& instance_counts, const std::vector<uint32_t>& dense) {
    const uint32_t rounds = uint32_t(options.integer("--rounds")),
                   builds = uint32_t(options.integer("--builds"));
    const ch24::RayFunctions ray(gpu.device);
    VkPhysicalDeviceAccelerationStructurePropertiesKHR limits{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
    VkPhysicalDeviceDriverProperties driver{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES, .pNext = &limits};
    VkPhysicalDeviceProperties2 properties2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                            .pNext = &driver};
    vkGetPhysicalDeviceProperties2(gpu.physical, &properties2);
    std::printf(
        "as_bench: %s (%s %s, with %s), validation %s, %u rounds, %u top-level builds "
        "per round\n",
        properties.deviceName, driver.driverName, driver.driverInfo, tracer,
        validation ? "on" : "off", rounds, builds);
    const VkDeviceSize alignment = limits.minAccelerationStructureScratchOffsetAlignment;
    Stopwatch watch(gpu, properties);

    // Chapter 24's meshes, as its main.cpp makes them, in one buffer pair.
    vkt::shapes::MeshBuilder builder;
    const vkt::shapes::MeshRange ranges[] = {builder.floor(1), builder.cube(),
                                             builder.sphere(32, 16), builder.torus(48, 16, 0.25f)};
    const char* names[] = {"floor", "cube", "sphere 32x16", "torus 48x16"};
    const Mesh scene = upload_mesh(gpu, "scene", builder.vertices, builder.indices);
    ch24::BottomLevelReport report;
    const std::vector<ch24::AccelerationStructure> bottom =
        ch24::build_bottom_levels(gpu, ray, alignment, ranges, scene.vertices.address,
                                  scene.vertex_count, scene.indices.address, report);
    std::printf(
        "chapter 24's build_bottom_levels: 4 bottom levels %.1f KiB built, %.1f KiB "
        "compacted (%.0f%% saved), scratch %.1f KiB\n",
        kib(report.built_bytes), kib(report.compacted_bytes),
        100.0 - 100.0 * double(report.compacted_bytes) / double(report.built_bytes),
        kib(report.scratch_bytes));

    // Each mesh alone: the chapter's four (their index ranges cut out of the
    // shared buffers) and the dense spheres.
    std::vector<Mesh> meshes;
    for (int i = 0; i < 4; ++i) {
        const auto first = builder.indices.begin() + ranges[i].first_index;
        meshes.push_back(upload_mesh(gpu, names[i], builder.vertices,
                                     std::vector<uint16_t>(first, first + ranges[i].index_count)));
    }
    for (uint32_t slices : dense) {
        const uint32_t stacks = slices / 2;
        const std::string name = "sphere " + std::to_string(slices) + "x" + std::to_string(stacks);
        if ((slices + 1) * (stacks + 1) <= 65536) {
            vkt::shapes::MeshBuilder big;
            big.sphere(int(slices), int(stacks));
            meshes.push_back(upload_mesh(gpu, name + " (16-bit)", big.vertices, big.indices));
        } else {
            meshes.push_back(wide_sphere(gpu, name + " (32-bit)", slices, stacks));
        }
    }
    for (const Mesh& mesh : meshes) {
        std::vector<double> build_ms, copy_ms;
        BottomSample sample;
        for (uint32_t r = 0; r < rounds; ++r) {
            sample = time_bottom_level(gpu, ray, alignment, watch, mesh);
            build_ms.push_back(sample.build_ms);
            copy_ms.push_back(sample.copy_ms);
        }
        const Spread b = spread_of(build_ms), c = spread_of(copy_ms);
        std::printf(
            "blas %-26s %8u triangles: build %.4f ms [%.4f..%.4f], compacting copy %.4f "
            "ms [%.4f..%.4f]; %.1f KiB built, %.1f KiB compacted (%.0f%% saved), "
            "scratch %.1f KiB\n",
            mesh.name.c_str(), mesh.triangles, b.median, b.min, b.max, c.median, c.min, c.max,
            kib(sample.built), kib(sample.compacted),
            100.0 - 100.0 * double(sample.compacted) / double(sample.built), kib(sample.scratch));
    }

    // The top level: rounds of builds from nothing against refits.
    std::vector<VkDeviceAddress> bottom_addresses;
    for (const auto& structure : bottom) bottom_addresses.push_back(structure.address());
    std::vector<glm::mat4> transforms;
    std::vector<VkDeviceAddress> addresses;
    for (uint32_t n : instance_counts) {
        std::vector<double> medians[2], first_builds;
        VkDeviceSize bytes = 0, scratch = 0;
        for (uint32_t r = 0; r < rounds; ++r)
            for (int update = 0; update < 2; ++update) {
                ch24::TopLevel top(gpu, ray, alignment, n, 1, update != 0);
                bytes = top.bytes();
                scratch = top.scratch_bytes();
                std::vector<double> times;
                // Build 0 is from nothing in both modes (an update needs a
                // built structure to refit); builds 1..B are what is compared.
                for (uint32_t b = 0; b <= builds; ++b) {
                    place(n, double(b + r * builds) / 60.0, bottom_addresses, transforms,
                          addresses);
                    top.write_instances(0, transforms, addresses);
                    const double ms = watch.time_ms([&](VkCommandBuffer cmd) {
                        vkCmdPipelineBarrier2(cmd, &after_build);
                        top.record(cmd, 0);
                    });
                    if (b == 0 && update) first_builds.push_back(ms);
                    if (b > 0) times.push_back(ms);
                }
                medians[update].push_back(median_of(times));
            }
        const Spread rebuild = spread_of(medians[0]), refit = spread_of(medians[1]),
                     first = spread_of(first_builds);
        std::printf(
            "tlas %6u instances: rebuild %.4f ms [%.4f..%.4f], update %.4f ms "
            "[%.4f..%.4f], update/rebuild %.2f; the updatable one's first build %.4f ms; "
            "%.1f KiB, scratch %.1f KiB\n",
            n, rebuild.median, rebuild.min, rebuild.max, refit.median, refit.min, refit.max,
            refit.median / rebuild.median, first.median, kib(bytes), kib(scratch));
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<vkt::OptionSpec> specs = {
        {.name = "--rounds",
         .type = vkt::OptionType::integer,
         .value_name = "R",
         .help = "rounds of every measurement (medians and spread over them)",
         .default_value = "5",
         .min = 1,
         .max = 100},
        {.name = "--builds",
         .type = vkt::OptionType::integer,
         .value_name = "B",
         .help = "top-level builds and updates per round",
         .default_value = "100",
         .min = 1,
         .max = 10000},
        {.name = "--instances",
         .value_name = "N,N,...",
         .help = "top-level instance counts (1..1000000)",
         .default_value = "19,10000,100000"},
        {.name = "--dense",
         .value_name = "S,S,...",
         .help = "dense spheres of S slices and S/2 stacks (4..4096)",
         .default_value = "360,1024"},
    };
    std::vector<const char*> args(argv + 1, argv + argc);
    vkt::Options options;
    std::vector<uint32_t> counts, dense;
    try {
        options = vkt::parse_args(args, vkt::Flags::device, specs);
        counts = parse_list("--instances", options.text("--instances"), 1, 1000000);
        dense = parse_list("--dense", options.text("--dense"), 4, 4096);
    } catch (const vkt::UsageError& e) {
        std::fprintf(stderr, "as_bench: %s\n%s\n", e.what(),
                     vkt::usage_line("as_bench", vkt::Flags::device, specs).c_str());
        return 2;
    }
    if (options.help) {
        std::printf("%s", vkt::help_text("as_bench", vkt::Flags::device, specs).c_str());
        return 0;
    }
    const bool validation =
        options.validation.value_or(vkt::instance_layer_available(vkt::validation_layer_name));
    std::shared_ptr<const vkt::ValidationCounts> messages;
    try {
        const vkt::Instance instance({.application_name = "as_bench", .validation = validation});
        messages = instance.counts();
        const char* tracer = "";
        const std::unique_ptr<vkt::Device> owner =
            open_acceleration_device(instance, options.device, tracer);
        const vkt::Device& device = *owner;
        const vkt::Gpu gpu{device.physical(), device.get(), device.queue(), device.queue_family()};
        bench(gpu, device.properties(), tracer, validation, options, counts, dense);
        VKT_CHECK(vkDeviceWaitIdle(gpu.device));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "as_bench: %s\n", e.what());
        return 1;
    }
    if (!validation) return 0;
    // The chapters' closing line, which the tests look for.
    const uint32_t warnings = messages->warnings, errors = messages->errors;
    std::fprintf(stderr, "as_bench: validation: %u warnings, %u errors\n", warnings, errors);
    return warnings + errors > 0 ? 1 : 0;
}
