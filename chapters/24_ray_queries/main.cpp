// Chapter 24: acceleration structures and ray queries.
//
// Chapter 22 asked "does anything lie between this point and the light?" of a
// shadow map: a picture of the scene from the light, with its texels, its
// bias and its acne. Here the same question is asked of the scene itself: a
// ray from the point towards the light, traced in the fragment shader (a ray
// query) through an acceleration structure, the tree of boxes around the
// scene's triangles that lets a ray skip everything it cannot hit. The scene
// is chapter 22's, with its sphere and torus moving, so the top level of the
// structure changes every frame.

#include "bottom_level.hpp"
#include "box_view.hpp"
#include "shadow_map.hpp"
#include "top_level.hpp"

#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/camera_math.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

// As scene.vert and scene.frag declare it (shaders/24_ray_queries/frame.glsl).
struct FrameBlock {
    glm::mat4 clip_from_world;
    glm::mat4 light_from_world;
    glm::vec4 light;
    glm::uvec4 settings;  // x: 0 map, 1 rays, 2 compare
};

enum Mesh { floor_mesh, cube_mesh, sphere_mesh, torus_mesh, mesh_count };

struct Object {
    glm::mat4 world_from_object;
    glm::vec4 colour;
    vkt::shapes::MeshRange mesh;
    Mesh kind;
};

// Where the shadow ray starts, scene.frag's specialization constants 0 and 1
// (page 24b): --ray-offset D, D along the normal (0 to 1, 0.01 by default),
// or --ray-offset ulp, Waechter and Binder's floating-point offset alone.
struct RayStart {
    float distance = 0.01f;
    VkBool32 float_offset = VK_FALSE;
};

RayStart ray_start(const vkt::Options& options) {
    const std::string& text = options.text("--ray-offset");
    if (text == "ulp") return {.float_offset = VK_TRUE};
    float distance = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), distance);
    if (error != std::errc{} || end != text.data() + text.size() ||
        !(distance >= 0 && distance <= 1))
        throw vkt::UsageError("--ray-offset wants a distance from 0 to 1 along the normal, " +
                              std::string("or ulp, not '") + text + "'");
    return {.distance = distance};
}

// [scene]
// Chapter 22's scene: a floor 60 units deep, two rows of pillars, a sphere
// and a torus near the camera. Now the sphere bobs and the torus turns, as
// functions of time (frame / 60 in a test, so the pictures are the same on
// every run). --crowd adds small cubes drifting far behind the pillars: many
// moving instances, for the top level's benchmark.
std::vector<Object> make_scene(const vkt::shapes::MeshRange (&mesh)[mesh_count], double time,
                               uint32_t crowd) {
    const float t = float(time);
    std::vector<Object> objects;
    objects.push_back({vkt::transform({0, 0, -22}, 0, {0, 1, 0}, {40, 1, 60}),
                       {0.8f, 0.8f, 0.75f, 1},
                       mesh[floor_mesh],
                       floor_mesh});
    for (int i = 0; i < 8; ++i)
        for (float x : {-3.0f, 3.0f})
            objects.push_back({vkt::transform({x, 1.5f, 2.0f - 7.0f * float(i)}, 0.3f * float(i),
                                              {0, 1, 0}, {0.6f, 3.0f, 0.6f}),
                               {0.85f, 0.45f, 0.3f, 1},
                               mesh[cube_mesh],
                               cube_mesh});
    objects.push_back({vkt::transform({-0.8f, 0.7f + 0.3f * std::sin(2.0f * t), 3.0f}, 0, {0, 1, 0},
                                      glm::vec3(1.4f)),
                       {0.3f, 0.55f, 0.9f, 1},
                       mesh[sphere_mesh],
                       sphere_mesh});
    objects.push_back({vkt::transform({1.2f, 0.9f, 1.0f}, 0.6f + t, {1, 0, 0}, glm::vec3(1.6f)),
                       {0.35f, 0.8f, 0.45f, 1},
                       mesh[torus_mesh],
                       torus_mesh});
    for (uint32_t i = 0; i < crowd; ++i) {
        const uint32_t row = i / 64, column = i % 64;  // rows of 64 cubes
        const float x = -16.0f + 0.5f * float(column), z = -44.0f - 0.5f * float(row);
        objects.push_back({vkt::transform({x, 6.0f + std::sin(2.0f * t + 0.1f * float(i)), z},
                                          t + float(i), {0, 1, 0}, glm::vec3(0.3f)),
                           {0.6f, 0.6f, 0.65f, 1},
                           mesh[cube_mesh],
                           cube_mesh});
    }
    return objects;
}
// [/scene]

class RayQueries : public vkt::Renderer {
public:
    explicit RayQueries(const vkt::Context& context)
        : device_(context.device),
          physical_(context.physical),
          ray_(context.device),
          mode_(context.options.text("--shadows") == "map"    ? 0u
                : context.options.text("--shadows") == "rays" ? 1u
                                                              : 2u),
          crowd_(uint32_t(context.options.integer("--crowd"))) {
        const vkt::Gpu gpu = context.gpu();
        vkt::shapes::MeshBuilder builder;
        mesh_[floor_mesh] = builder.floor(1);
        mesh_[cube_mesh] = builder.cube();
        mesh_[sphere_mesh] = builder.sphere(32, 16);
        mesh_[torus_mesh] = builder.torus(48, 16, 0.25f);

        // [limits]
        // The acceleration structure extension's limits, among them the
        // alignment of every scratch address.
        VkPhysicalDeviceAccelerationStructurePropertiesKHR limits{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
        VkPhysicalDeviceProperties2 properties{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &limits};
        vkGetPhysicalDeviceProperties2(physical_, &properties);
        const VkDeviceSize scratch_alignment =
            limits.minAccelerationStructureScratchOffsetAlignment;
        // [/limits]

        // [inputs]
        // The vertex and index buffers, drawn from as ever, are also the
        // builds' inputs: usage BUILD_INPUT_READ_ONLY, and a GPU address.
        const VkDeviceSize vertex_bytes = builder.vertices.size() * sizeof(vkt::shapes::Vertex),
                           index_bytes = builder.indices.size() * sizeof(uint16_t);
        constexpr VkBufferUsageFlags input =
            VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
            VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        vertices_ = ch24::create_address_buffer(gpu, vertex_bytes,
                                                input | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, false);
        indices_ = ch24::create_address_buffer(gpu, index_bytes,
                                               input | VK_BUFFER_USAGE_INDEX_BUFFER_BIT, false);
        vkt::upload_to_buffer(gpu, vertices_.owner.buffer, builder.vertices.data(), vertex_bytes);
        vkt::upload_to_buffer(gpu, indices_.owner.buffer, builder.indices.data(), index_bytes);
        // [/inputs]

        ch24::BottomLevelReport report;
        bottom_ =
            ch24::build_bottom_levels(gpu, ray_, scratch_alignment, mesh_, vertices_.address,
                                      uint32_t(builder.vertices.size()), indices_.address, report);
        objects_ = make_scene(mesh_, 0.0, crowd_);
        const bool update = context.options.text("--tlas") == "update";
        top_ = std::make_unique<ch24::TopLevel>(gpu, ray_, scratch_alignment,
                                                uint32_t(objects_.size()), context.frames_in_flight,
                                                update);
        shadow_map_ = std::make_unique<ch24::ShadowMap>(gpu, context.chapter);

        frame_buffer_ =
            vkt::create_host_buffer(gpu, sizeof(FrameBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        // [descriptors]
        // The top level is one more descriptor: type ACCELERATION_STRUCTURE,
        // written through a VkWriteDescriptorSetAccelerationStructureKHR in
        // the write's pNext. The structure is rebuilt in place, so the
        // descriptor is written once.
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
             VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr},
            {2, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr},
        };
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
                                              {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1}};
        pool_ = vkt::create_descriptor_pool(device_, 1, sizes);
        set_ = vkt::allocate_descriptor_set(device_, pool_, set_layout_);
        vkt::write_buffer_descriptor(device_, set_, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                     frame_buffer_.buffer, 0, sizeof(FrameBlock));
        vkt::write_image_descriptor(device_, set_, 1, shadow_map_->view(), shadow_map_->sampler(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        const VkAccelerationStructureKHR tlas = top_->get();
        const VkWriteDescriptorSetAccelerationStructureKHR structure{
            .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR,
            .accelerationStructureCount = 1,
            .pAccelerationStructures = &tlas,
        };
        const VkWriteDescriptorSet write{
            .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
            .pNext = &structure,
            .dstSet = set_,
            .dstBinding = 2,
            .descriptorCount = 1,
            .descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR,
        };
        vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
        // [/descriptors]

        const VkVertexInputBindingDescription binding{0, sizeof(vkt::shapes::Vertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::shapes::Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::shapes::Vertex, normal)},
        };
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                       sizeof(glm::mat4) + sizeof(glm::vec4)};
        const VkDescriptorSetLayout set_layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(device_, set_layouts, {&push, 1});
        const vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "scene.vert");
        const vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "scene.frag");
        const RayStart start = ray_start(context.options);
        const VkSpecializationMapEntry entries[] = {
            {0, offsetof(RayStart, distance), sizeof start.distance},
            {1, offsetof(RayStart, float_offset), sizeof start.float_offset}};
        const VkSpecializationInfo specialization{2, entries, sizeof start, &start};
        depth_format_ = vkt::choose_depth_format(physical_);
        pipeline_ =
            vkt::create_graphics_pipeline(device_, {.vertex = vertex,
                                                    .fragment = fragment,
                                                    .layout = layout_,
                                                    .bindings = {&binding, 1},
                                                    .attributes = attributes,
                                                    .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                    .color_formats = {context.color_format},
                                                    .depth_format = depth_format_,
                                                    .fragment_specialization = &specialization});
        if (context.options.text("--view") == "boxes") {
            boxes_ = std::make_unique<ch24::BoxView>(gpu, context.chapter, context.color_format,
                                                     depth_format_, context.frames_in_flight,
                                                     uint32_t(objects_.size()), builder, mesh_);
            std::fprintf(stderr,
                         "24_ray_queries: boxes drawn: orange, each bottom level's bounds "
                         "in the world; blue, the box each instance gets from them\n");
        }
        resize(context.extent);
        const auto kib = [](VkDeviceSize bytes) { return double(bytes) / 1024.0; };
        std::fprintf(stderr,
                     "24_ray_queries: shadows %s, top level %s; %d bottom levels %.1f KiB built, "
                     "%.1f KiB compacted (%.0f%% saved), scratch %.1f KiB; top level %zu "
                     "instances %.1f KiB, scratch %.1f KiB\n",
                     context.options.text("--shadows").c_str(), update ? "updated" : "rebuilt",
                     int(mesh_count), kib(report.built_bytes), kib(report.compacted_bytes),
                     100.0 - 100.0 * double(report.compacted_bytes) / double(report.built_bytes),
                     kib(report.scratch_bytes), objects_.size(), kib(top_->bytes()),
                     kib(top_->scratch_bytes()));
    }

    void resize(VkExtent2D extent) override {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent);
        // Chapter 22's camera and light.
        const glm::vec3 eye{0.0f, 3.0f, 8.0f}, forward = glm::normalize(glm::vec3(0, -0.25f, -1));
        const glm::vec3 light = glm::normalize(glm::vec3(-0.6f, -1.0f, -0.45f));
        block_.clip_from_world =
            vkt::vulkan_perspective(glm::radians(50.0f), float(extent.width) / float(extent.height),
                                    0.1f, 60.0f) *
            glm::lookAt(eye, eye + forward, glm::vec3(0, 1, 0));
        block_.light_from_world = ch24::ShadowMap::light_from_world({0, 1.5f, -22}, 37.0f, light);
        block_.light = glm::vec4(light, 0);
        block_.settings = {mode_, 0, 0, 0};
        std::memcpy(frame_buffer_.mapped, &block_, sizeof block_);
    }

    void record(const vkt::Frame& frame) override {
        const VkCommandBuffer cmd = frame.cmd;
        objects_ = make_scene(mesh_, frame.time, crowd_);
        std::vector<glm::mat4> transforms;
        std::vector<VkDeviceAddress> bottom;
        std::vector<uint32_t> kinds;
        for (const Object& o : objects_) {
            transforms.push_back(o.world_from_object);
            bottom.push_back(bottom_[o.kind].address());
            kinds.push_back(o.kind);
        }
        top_->write_instances(frame.slot, transforms, bottom);
        {
            auto scope = frame.gpu_scope("tlas");
            // [tlas-barriers]
            // Before the build: the last frame's ray queries (fragment
            // shader) are done with the structure, and the last build's
            // writes (structure and scratch) are finished. After it: the
            // structure is complete before any fragment's ray reads it.
            const VkMemoryBarrier2 before{
                .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                .srcStageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                .srcAccessMask = VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                .dstStageMask = VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                .dstAccessMask = VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                                 VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
            };
            const VkMemoryBarrier2 after{
                .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                .srcStageMask = VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                .srcAccessMask = VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                .dstStageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                .dstAccessMask = VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR,
            };
            const VkDependencyInfo wait_before{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                               .memoryBarrierCount = 1,
                                               .pMemoryBarriers = &before};
            const VkDependencyInfo wait_after{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                              .memoryBarrierCount = 1,
                                              .pMemoryBarriers = &after};
            vkCmdPipelineBarrier2(cmd, &wait_before);
            top_->record(cmd, frame.slot);
            vkCmdPipelineBarrier2(cmd, &wait_after);
            // [/tlas-barriers]
        }

        const VkBuffer vertex_buffer = vertices_.owner.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(cmd, indices_.owner.buffer, 0, VK_INDEX_TYPE_UINT16);
        if (mode_ != 1) {  // the shadow map: drawn only where it is read
            auto scope = frame.gpu_scope("shadow");
            shadow_map_->record(cmd, block_.light_from_world, objects_);
        }

        auto scope = frame.gpu_scope("lit");
        vkt::begin_depth_frame(cmd, depth_.image);
        vkt::begin_rendering(cmd, frame.target_view, frame.extent, {{0.45f, 0.6f, 0.8f, 1.0f}},
                             depth_.view);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(cmd, frame.extent);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                                nullptr);
        for (const Object& o : objects_) {
            vkCmdPushConstants(cmd, layout_,
                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                               sizeof(glm::mat4) + sizeof(glm::vec4), &o);
            vkCmdDrawIndexed(cmd, o.mesh.index_count, 1, o.mesh.first_index, 0, 0);
        }
        if (boxes_) boxes_->record(cmd, frame.slot, block_.clip_from_world, transforms, kinds);
        vkCmdEndRendering(cmd);
    }

private:
    VkDevice device_;
    VkPhysicalDevice physical_;
    ch24::RayFunctions ray_;
    uint32_t mode_, crowd_;
    vkt::shapes::MeshRange mesh_[mesh_count];
    std::vector<Object> objects_;
    ch24::AddressBuffer vertices_, indices_;
    std::vector<ch24::AccelerationStructure> bottom_;  // one per Mesh, compacted
    std::unique_ptr<ch24::TopLevel> top_;
    std::unique_ptr<ch24::ShadowMap> shadow_map_;
    std::unique_ptr<ch24::BoxView> boxes_;  // --view boxes
    vkt::Buffer frame_buffer_;
    FrameBlock block_{};
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vkt::Image depth_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    // Three extensions: acceleration structures (which need deferred host
    // operations, though this chapter builds on the GPU only) and ray
    // queries, each with a feature struct linked into the device's pNext
    // chain; and buffer device address, a Vulkan 1.2 feature.
    VkPhysicalDeviceRayQueryFeaturesKHR ray_query{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR, .rayQuery = VK_TRUE};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR acceleration{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR,
        .pNext = &ray_query,
        .accelerationStructure = VK_TRUE};
    vkt::ChapterSpec spec{.name = "24_ray_queries", .title = "24 - Ray queries"};
    spec.requirements.extensions = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
                                    VK_KHR_RAY_QUERY_EXTENSION_NAME};
    spec.requirements.extension_features = &acceleration;
    spec.requirements.features = {VKT_FEATURE_12(bufferDeviceAddress),
                                  VKT_FEATURE_12(separateDepthStencilLayouts)};
    // [/spec]
    spec.options = {
        {.name = "--shadows",
         .type = vkt::OptionType::choice,
         .value_name = "HOW",
         .help = "map: chapter 22's shadow map; rays: ray queries; compare: where they differ",
         .default_value = "rays",
         .choices = {"map", "rays", "compare"}},
        {.name = "--tlas",
         .type = vkt::OptionType::choice,
         .value_name = "HOW",
         .help = "update: refit the top level each frame; rebuild: build it anew",
         .default_value = "update",
         .choices = {"update", "rebuild"}},
        {.name = "--crowd",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "N more moving cubes behind the pillars (0..16384), for --benchmark",
         .default_value = "0",
         .min = 0,
         .max = 16384},
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .value_name = "VIEW",
         .help = "scene: the lit scene; boxes: it, with each bottom level's bounds and the "
                 "box each instance gets from them",
         .default_value = "scene",
         .choices = {"scene", "boxes"}},
        {.name = "--ray-offset",
         .value_name = "D|ulp",
         .help = "where the shadow ray starts: D along the normal (0 to 1), or ulp: Waechter and "
                 "Binder's floating-point offset alone",
         .default_value = "0.01"},
    };
    spec.check_options = [](const vkt::Options& options) { ray_start(options); };
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<RayQueries>(context);
    });
}
