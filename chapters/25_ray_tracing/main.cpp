// Chapter 25: the ray-tracing pipeline.
//
// Until now every picture came from rasterising triangles: each one projected
// onto the screen, its pixels filled. A ray-tracing pipeline turns that
// round: for each pixel a shader sends a ray into the scene, and the device
// finds the nearest triangle it meets (through chapter 24's acceleration
// structures) and runs a shader for the hit, or one for the miss. Those
// shaders may trace rays of their own: here a shadow ray towards the light
// and a reflected ray off every shiny surface. Which shader runs for which
// ray is read from a table in GPU memory, the shader binding table, laid out
// to the device's alignments.

#include "binding_table.hpp"
#include "scene.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/acceleration.hpp"
#include "vkt/resources/align.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// The push constants of every stage (ray_common.glsl's Push).
struct Push {
    glm::vec4 eye, right, up, forward, light;
    uint32_t bounces, max_depth;
};

class RayTracing : public vkt::Renderer {
public:
    explicit RayTracing(const vkt::Context& context)
        : gpu_(context.gpu()), as_commands_(context.device) {
        // [commands]
        // The pipeline's three commands, fetched from the device as every
        // extension's are (chapter 01 fetched the debug messenger's).
        create_pipelines_ = reinterpret_cast<PFN_vkCreateRayTracingPipelinesKHR>(
            vkGetDeviceProcAddr(gpu_.device, "vkCreateRayTracingPipelinesKHR"));
        get_handles_ = reinterpret_cast<PFN_vkGetRayTracingShaderGroupHandlesKHR>(
            vkGetDeviceProcAddr(gpu_.device, "vkGetRayTracingShaderGroupHandlesKHR"));
        trace_rays_ = reinterpret_cast<PFN_vkCmdTraceRaysKHR>(
            vkGetDeviceProcAddr(gpu_.device, "vkCmdTraceRaysKHR"));
        if (!create_pipelines_ || !get_handles_ || !trace_rays_)
            throw vkt::Error("the device lacks the commands of VK_KHR_ray_tracing_pipeline");
        // [/commands]

        // [limits]
        // The pipeline's limits: how large a shader group's handle is, how
        // records and tables must be aligned, how deep rays may recurse.
        rt_limits_ = {.sType =
                          VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
        VkPhysicalDeviceProperties2 properties{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &rt_limits_};
        vkGetPhysicalDeviceProperties2(gpu_.physical, &properties);
        // Every ray from the closest-hit shader is one level deeper: the
        // camera's ray is 1, each reflection adds 1, and the last surface's
        // shadow ray 1 more. A device that cannot go 2 deep cannot shadow.
        // (VKT_HIDE_FEATURES=maxRayRecursionDepth plays a device that allows 1.)
        const uint32_t limit =
            context.hidden.hides("maxRayRecursionDepth") ? 1u : rt_limits_.maxRayRecursionDepth;
        if (limit < 2)
            throw vkt::Error(
                "this chapter traces shadow rays from its closest-hit shader, which "
                "needs maxRayRecursionDepth 2; the device allows " +
                std::to_string(limit));
        const uint32_t asked = uint32_t(context.options.integer("--bounces"));
        push_.bounces = std::min(asked, limit - 2);
        push_.max_depth = push_.bounces + 2;
        // [/limits]

        build_scene();
        create_descriptors();
        create_pipeline(context.chapter);
        create_binding_table();
        resize(context.extent);

        std::fprintf(stderr, "25_ray_tracing: %u bounces, recursion depth %u of %u%s\n",
                     push_.bounces, push_.max_depth, limit,
                     asked > push_.bounces ? " (--bounces clamped to the device's limit)" : "");
    }

    void resize(VkExtent2D extent) override {
        // [image]
        // The rays' colours go to an image of our own, in floating point
        // (linear light), which each frame is then blitted into the target:
        // the blit encodes it as sRGB, whatever the target's byte order.
        image_ =
            vkt::create_image_2d(gpu_.physical, gpu_.device, VK_FORMAT_R16G16B16A16_SFLOAT, extent,
                                 VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                 VK_IMAGE_ASPECT_COLOR_BIT);
        vkt::write_storage_image_descriptor(gpu_.device, set_, 1, image_.view);
        // [/image]
        const glm::vec3 eye{0.0f, 2.4f, 7.0f}, target{0.0f, 0.8f, 0.0f};
        const glm::vec3 forward = glm::normalize(target - eye);
        const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
        const float half_height = std::tan(glm::radians(45.0f) / 2.0f);
        const float aspect = float(extent.width) / float(extent.height);
        push_.eye = glm::vec4(eye, 1);
        push_.forward = glm::vec4(forward, 0);
        push_.right = glm::vec4(right * half_height * aspect, 0);
        push_.up = glm::vec4(glm::cross(right, forward) * half_height, 0);
        push_.light = glm::vec4(glm::normalize(glm::vec3(0.7f, -1.0f, -0.25f)), 0);
    }

    void record(const vkt::Frame& frame) override {
        const VkCommandBuffer cmd = frame.cmd;
        // [trace]
        // Once the last frame's blit has read the image, the rays may write
        // every pixel of it again: its old contents are not kept (UNDEFINED),
        // and storage writes want the GENERAL layout.
        vkt::image_barrier(cmd, image_.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                           VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_NONE,
                           VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout_, 0, 1, &set_,
                                0, nullptr);
        vkCmdPushConstants(cmd, layout_, all_stages, 0, sizeof push_, &push_);
        {
            auto scope = frame.gpu_scope("trace");
            const VkStridedDeviceAddressRegionKHR no_callables{};
            trace_rays_(cmd, &raygen_region_, &miss_region_, &hit_region_, &no_callables,
                        frame.extent.width, frame.extent.height, 1);
        }
        // [/trace]
        // [blit]
        // Storage writes to the blit's reads; the target from wherever the
        // runner has it to a transfer destination.
        vkt::image_barrier(
            cmd, image_.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
            VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        vkt::image_barrier(cmd, frame.target, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, frame.target_ready,
                           VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_BLIT_BIT,
                           VK_ACCESS_2_TRANSFER_WRITE_BIT);
        const VkOffset3D corner{int32_t(frame.extent.width), int32_t(frame.extent.height), 1};
        const VkImageBlit region{
            .srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
            .srcOffsets = {{0, 0, 0}, corner},
            .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
            .dstOffsets = {{0, 0, 0}, corner},
        };
        vkCmdBlitImage(cmd, image_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, frame.target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
        // [/blit]
    }

    vkt::TargetWrite target_after(const vkt::Frame&) const override {
        return vkt::written_by_transfer;  // the blit
    }

private:
    static constexpr VkShaderStageFlags all_stages = VK_SHADER_STAGE_RAYGEN_BIT_KHR |
                                                     VK_SHADER_STAGE_MISS_BIT_KHR |
                                                     VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR;

    // The meshes in buffers the builds and the closest-hit shader both
    // read, and chapter 24's structures over them (vkt::build_scene).
    void build_scene() {
        ch25::Scene scene = ch25::make_scene();
        std::vector<uint16_t>& indices = scene.meshes.indices;
        if (indices.size() % 2) indices.push_back(0);  // whole words for the shader
        const VkBufferUsageFlags usage =
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
            VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;
        const std::vector<vkt::shapes::Vertex>& vertices = scene.meshes.vertices;
        vertices_ = vkt::create_addressable_buffer(gpu_, vertices.size() * sizeof vertices[0],
                                                   usage, vertices.data());
        indices_ = vkt::create_addressable_buffer(gpu_, indices.size() * sizeof(uint16_t), usage,
                                                  indices.data());
        objects_ = vkt::create_addressable_buffer(gpu_, scene.objects.size() * sizeof(ch25::Object),
                                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                  scene.objects.data());
        std::vector<vkt::TriangleMesh> meshes;
        meshes.reserve(scene.ranges.size());
        for (const vkt::shapes::MeshRange& range : scene.ranges)
            meshes.push_back({.vertices = vkt::buffer_address(gpu_.device, vertices_.buffer),
                              .vertex_stride = sizeof(vkt::shapes::Vertex),
                              .vertex_count = uint32_t(vertices.size()),
                              .indices = vkt::buffer_address(gpu_.device, indices_.buffer),
                              .index_type = VK_INDEX_TYPE_UINT16,
                              .first_index = range.first_index,
                              .triangle_count = range.index_count / 3});
        structures_ = vkt::build_scene(gpu_, as_commands_, meshes, scene.instances);
    }

    void create_descriptors() {
        // [descriptors]
        // What the shaders read: the top level (ray generation and closest
        // hit trace against it), the output image, and the closest-hit
        // shader's vertices, indices and Object records.
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1,
             VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_RAYGEN_BIT_KHR, nullptr},
            {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, nullptr},
            {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, nullptr},
            {4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, nullptr},
        };
        set_layout_ = vkt::create_descriptor_set_layout(gpu_.device, bindings);
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                              {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1},
                                              {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3}};
        pool_ = vkt::create_descriptor_pool(gpu_.device, 1, sizes);
        set_ = vkt::allocate_descriptor_set(gpu_.device, pool_, set_layout_);
        // The top level (chapter 24's write), then the meshes' buffers.
        vkt::write_acceleration_structure_descriptor(gpu_.device, set_, 0, structures_.top.get());
        const VkBuffer buffers[] = {vertices_.buffer, indices_.buffer, objects_.buffer};
        for (uint32_t i = 0; i < 3; ++i)
            vkt::write_buffer_descriptor(gpu_.device, set_, 2 + i,
                                         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i], 0,
                                         VK_WHOLE_SIZE);
        // [/descriptors]
    }

    void create_pipeline(const std::string& chapter) {
        const VkPushConstantRange push{all_stages, 0, sizeof(Push)};
        const VkDescriptorSetLayout set_layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(gpu_.device, set_layouts, {&push, 1});
        const vkt::ShaderModule raygen = vkt::load_shader(gpu_.device, chapter, "raygen.rgen");
        const vkt::ShaderModule sky = vkt::load_shader(gpu_.device, chapter, "sky.rmiss");
        const vkt::ShaderModule shadow = vkt::load_shader(gpu_.device, chapter, "shadow.rmiss");
        const vkt::ShaderModule closest = vkt::load_shader(gpu_.device, chapter, "closest.rchit");
        // [pipeline]
        // Four stages, and four shader groups over them: the ray-generation
        // shader, two miss shaders (general groups of one shader each), and
        // one hit group of triangles whose only shader is the closest hit.
        const auto stage = [](VkShaderStageFlagBits which, VkShaderModule module) {
            return VkPipelineShaderStageCreateInfo{
                .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                .stage = which,
                .module = module,
                .pName = "main"};
        };
        const VkPipelineShaderStageCreateInfo stages[] = {
            stage(VK_SHADER_STAGE_RAYGEN_BIT_KHR, raygen),
            stage(VK_SHADER_STAGE_MISS_BIT_KHR, sky),
            stage(VK_SHADER_STAGE_MISS_BIT_KHR, shadow),
            stage(VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, closest),
        };
        const auto group = [](VkRayTracingShaderGroupTypeKHR type, uint32_t general,
                              uint32_t closest_hit) {
            return VkRayTracingShaderGroupCreateInfoKHR{
                .sType = VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR,
                .type = type,
                .generalShader = general,
                .closestHitShader = closest_hit,
                .anyHitShader = VK_SHADER_UNUSED_KHR,
                .intersectionShader = VK_SHADER_UNUSED_KHR};
        };
        constexpr auto general = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
        const VkRayTracingShaderGroupCreateInfoKHR groups[] = {
            group(general, 0, VK_SHADER_UNUSED_KHR),  // 0: ray generation
            group(general, 1, VK_SHADER_UNUSED_KHR),  // 1: miss, the sky
            group(general, 2, VK_SHADER_UNUSED_KHR),  // 2: miss, the shadow ray's
            group(VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR, VK_SHADER_UNUSED_KHR,
                  3),  // 3: hit group
        };
        const VkRayTracingPipelineCreateInfoKHR info{
            .sType = VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR,
            .stageCount = 4,
            .pStages = stages,
            .groupCount = 4,
            .pGroups = groups,
            .maxPipelineRayRecursionDepth = push_.max_depth,
            .layout = layout_,
        };
        VkPipeline pipeline;
        VKT_CHECK(create_pipelines_(gpu_.device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &info, nullptr,
                                    &pipeline));
        pipeline_ = vkt::Pipeline(gpu_.device, pipeline);
        // [/pipeline]
    }

    void create_binding_table() {
        // The layout (binding_table.hpp): records padded to the handle
        // alignment, each table at a multiple of the base alignment.
        const VkDeviceSize handle = rt_limits_.shaderGroupHandleSize;
        const VkDeviceSize base = rt_limits_.shaderGroupBaseAlignment;
        const BindingTableLayout layout =
            binding_table_layout(handle, rt_limits_.shaderGroupHandleAlignment, base);
        const VkDeviceSize record = layout.record, miss_offset = layout.miss_offset;
        const VkDeviceSize hit_offset = layout.hit_offset, table_size = layout.size;

        // [sbt-fill]
        // The handles of the four groups, one after another, copied to
        // their records; the table's start rounded up to the base alignment
        // within a buffer one alignment larger.
        std::vector<uint8_t> handles(4 * handle);
        VKT_CHECK(get_handles_(gpu_.device, pipeline_, 0, 4, handles.size(), handles.data()));
        table_ = vkt::create_addressable_buffer(gpu_, table_size + base,
                                                VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR);
        const VkDeviceAddress address = vkt::buffer_address(gpu_.device, table_.buffer);
        const VkDeviceAddress start = vkt::align_up(address, base);
        std::vector<uint8_t> bytes(start - address + table_size);
        uint8_t* table = bytes.data() + (start - address);
        std::memcpy(table, &handles[0], handle);                                  // ray generation
        std::memcpy(table + miss_offset, &handles[handle], handle);               // sky
        std::memcpy(table + miss_offset + record, &handles[2 * handle], handle);  // shadow
        std::memcpy(table + hit_offset, &handles[3 * handle], handle);            // hit group
        vkt::upload_to_buffer(gpu_, table_.buffer, bytes.data(), bytes.size());
        raygen_region_ = {start, layout.raygen_size, layout.raygen_size};
        miss_region_ = {start + miss_offset, record, layout.miss_size};
        hit_region_ = {start + hit_offset, record, layout.hit_size};
        // [/sbt-fill]
        std::fprintf(stderr,
                     "25_ray_tracing: shader binding table: handles %u bytes, records %u "
                     "(handle alignment %u), tables at multiples of %u: ray generation at 0, "
                     "miss at %u (2 records), hit at %u (1 record), %u bytes\n",
                     unsigned(handle), unsigned(record), rt_limits_.shaderGroupHandleAlignment,
                     unsigned(base), unsigned(miss_offset), unsigned(hit_offset),
                     unsigned(table_size));
    }

    vkt::Gpu gpu_;
    vkt::AccelerationCommands as_commands_;
    PFN_vkCreateRayTracingPipelinesKHR create_pipelines_ = nullptr;
    PFN_vkGetRayTracingShaderGroupHandlesKHR get_handles_ = nullptr;
    PFN_vkCmdTraceRaysKHR trace_rays_ = nullptr;
    VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt_limits_{};
    Push push_{};
    vkt::Buffer vertices_, indices_, objects_, table_;
    vkt::AccelerationScene structures_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
    VkStridedDeviceAddressRegionKHR raygen_region_{}, miss_region_{}, hit_region_{};
    vkt::Image image_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    // Three extensions: the pipeline, the acceleration structures it traces
    // against, and deferred host operations (which the structures' extension
    // requires, for building on the CPU; unused here). Their features are
    // turned on through the feature chain's pNext.
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline_features{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR,
        .rayTracingPipeline = VK_TRUE};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR structure_features{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR,
        .pNext = &pipeline_features,
        .accelerationStructure = VK_TRUE};
    vkt::ChapterSpec spec{.name = "25_ray_tracing", .title = "25 - The ray-tracing pipeline"};
    spec.requirements.extensions = {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                                    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
    spec.requirements.features = {VKT_FEATURE_12(bufferDeviceAddress)};
    spec.requirements.extension_features = &structure_features;
    // The frame arrives untouched and leaves by a blit.
    spec.target_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    spec.transfers_into_target = true;
    spec.options = {
        {.name = "--bounces",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "reflections traced after the first hit (0..64; the device's "
                 "maxRayRecursionDepth may allow fewer)",
         .default_value = "2",
         .min = 0,
         .max = 64},
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<RayTracing>(context);
    });
}
