// Chapter 26: mesh shaders.
//
// A glTF model cut into meshlets on the CPU (meshlets.hpp: at most 64
// vertices and 124 triangles each, a bounding sphere and a normal cone per
// meshlet), drawn without vertex input or input assembly: a task shader
// culls whole meshlets (outside the frustum, or facing away) and launches one
// mesh shader workgroup for each that survives, which writes its vertices and
// triangles straight to the rasteriser. The task shader counts what it culls;
// the last frame's counts are printed beside the CPU's own for the same view.
// --draw indirect draws the same model chapter 15's way, for the comparison
// the book measures; --view meshlets colours each meshlet, --view culled
// each by the task shader's verdict (culled_view.hpp).

#include "culled_view.hpp"
#include "mesh_limits.hpp"
#include "meshlets.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"
#include "vkt/core/memory_budget.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/mesh_pipeline.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/gltf.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// Must match meshlet_data.glsl.
struct Push {
    glm::mat4 clip_from_world;
    glm::vec4 eye;
    glm::vec4 base_colour;
    uint32_t view, meshlet_count, counter_base, cull;
};
struct GpuVertex {
    glm::vec4 position, normal;
};
using ch26::kMeshVertices, ch26::kMeshTriangles, ch26::kTaskGroup;
const char* const kViews[] = {"lit", "meshlets", "culled"};  // by ch26::View
constexpr uint32_t kCounters = 4;  // per frame: frustum, cone, triangles, meshlets drawn
constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT |
                                       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// The camera circles the model outside its bounding sphere, 25 degrees above
// it, and --turn swings its gaze that many degrees to the left of the model.
// `opposite`: --view culled's second camera, across the model from the first.
struct View {
    glm::mat4 clip_from_world;
    glm::vec3 eye;
};
View camera(glm::vec3 lo, glm::vec3 hi, VkExtent2D extent, double time, float turn_degrees,
            bool opposite = false) {
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-4f);
    const float aspect = float(extent.width) / float(extent.height), fov = glm::radians(45.0f);
    const float half = std::min(fov, 2.0f * std::atan(std::tan(fov / 2.0f) * aspect)) / 2.0f;
    const float distance = radius / std::sin(half);
    const float azimuth = 0.6f + 0.25f * float(time), elevation = glm::radians(25.0f);
    const glm::vec3 eye =
        centre + (opposite ? -distance : distance) *
                     glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                               std::cos(elevation) * std::cos(azimuth));
    const glm::mat4 turn =
        glm::rotate(glm::mat4(1.0f), glm::radians(turn_degrees), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::vec3 gaze = glm::vec3(turn * glm::vec4(centre - eye, 0.0f));
    const glm::mat4 view = glm::lookAt(eye, eye + gaze, glm::vec3(0.0f, 1.0f, 0.0f));
    const float z_near = 0.05f * distance, z_far = 1.1f * (distance + radius);
    return {vkt::vulkan_perspective(fov, aspect, z_near, z_far) * view, eye};
}

class MeshShaders : public vkt::Renderer {
public:
    explicit MeshShaders(const vkt::Context& context)
        : physical_(context.physical), device_(context.device) {
        const vkt::Gpu gpu = context.gpu();
        indirect_ = context.options.text("--draw") == "indirect";
        view_ = ch26::parse_view(context.options.text("--view"));
        cull_ = context.options.text("--cull") == "on" ? 1 : 0;
        turn_ = float(context.options.number("--turn"));

        // The model, every draw's vertices moved into the world: one mesh.
        const std::string path = context.options.has("--model")
                                     ? context.options.text("--model")
                                     : vkt::asset_path("gltf/knot.glb").string();
        const std::string shown = vkt::shown_path(path);  // for messages: quoted where odd
        const vkt::GltfScene scene =
            vkt::load_gltf(path, uint64_t(context.options.integer("--max-memory")));
        for (const std::string& warning : scene.warnings)
            std::fprintf(stderr, "26_mesh_shaders: %s: warning: %s\n", shown.c_str(),
                         warning.c_str());
        // The flattened copy is charged to the same budget as the load: a
        // mesh that many nodes share is copied once for each (its vertices
        // here, staged and on the GPU; its indices, and the meshlets' arrays
        // of at most 40 bytes an index).
        vkt::MemoryBudget budget(uint64_t(context.options.integer("--max-memory")));
        budget.charge(scene.memory_charged, shown + ": the scene as loaded");
        uint64_t drawn_vertices = 0, drawn_indices = 0;
        for (const vkt::GltfDraw& draw : scene.draws) {
            drawn_vertices += scene.primitives[draw.primitive].vertex_count;
            drawn_indices += scene.primitives[draw.primitive].index_count;
        }
        budget.charge(drawn_vertices * (3 * sizeof(GpuVertex) + sizeof(glm::vec3)) +
                          drawn_indices * (3 * sizeof(uint32_t) + 40),
                      shown + ": its draws flattened into one mesh");
        std::vector<GpuVertex> vertices;
        std::vector<glm::vec3> positions;
        std::vector<uint32_t> indices;
        for (const vkt::GltfDraw& draw : scene.draws) {
            const vkt::GltfPrimitive& primitive = scene.primitives[draw.primitive];
            const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(draw.world)));
            const auto base = uint32_t(vertices.size());
            for (uint32_t v = 0; v < primitive.vertex_count; ++v) {
                const vkt::GltfVertex& in = scene.vertices[primitive.first_vertex + v];
                const glm::vec3 p = glm::vec3(draw.world * glm::vec4(in.position, 1.0f));
                vertices.push_back({glm::vec4(p, 1.0f),
                                    glm::vec4(glm::normalize(normal_matrix * in.normal), 0.0f)});
                positions.push_back(p);
            }
            for (uint32_t i = 0; i < primitive.index_count; ++i)
                indices.push_back(base + scene.indices[primitive.first_index + i] -
                                  primitive.first_vertex);
        }
        bounds_lo_ = scene.bounds_min;
        bounds_hi_ = scene.bounds_max;
        base_colour_ =
            scene.materials[scene.primitives[scene.draws[0].primitive].material].base_color_factor;

        // [limits]
        // What this device's mesh shaders may do, and what it prefers. The
        // vertex and primitive maxima need no check (every device allows 256
        // of each; meshlets.mesh declares 64 and 124). What can fail is the
        // output memory those maxima take; the preferences decide the mesh
        // workgroup's size (both in mesh_limits.hpp).
        VkPhysicalDeviceMeshShaderPropertiesEXT mesh_properties{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_PROPERTIES_EXT};
        VkPhysicalDeviceProperties2 properties{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &mesh_properties};
        vkGetPhysicalDeviceProperties2(physical_, &properties);
        const uint32_t output_bytes = ch26::mesh_output_bytes(mesh_properties);
        if (output_bytes > mesh_properties.maxMeshOutputMemorySize)
            throw vkt::Error("meshlets.mesh's outputs take " + std::to_string(output_bytes) +
                             " bytes, more than this device's maxMeshOutputMemorySize (" +
                             std::to_string(mesh_properties.maxMeshOutputMemorySize) + ")");
        const ch26::MeshWorkgroup workgroup = ch26::choose_mesh_workgroup(mesh_properties);
        mesh_workgroup_ = workgroup.size;
        const auto yes = [](VkBool32 b) { return b == VK_TRUE ? "yes" : "no"; };
        std::fprintf(
            stderr,
            "26_mesh_shaders: mesh shader outputs %u of %u bytes (granularity %u vertices, "
            "%u primitives); mesh workgroups of %u (%s; preferred at most %u, "
            "local-invocation output %s/%s, compact vertices %s), task workgroups of %u "
            "(preferred at most %u)\n",
            output_bytes, mesh_properties.maxMeshOutputMemorySize,
            mesh_properties.meshOutputPerVertexGranularity,
            mesh_properties.meshOutputPerPrimitiveGranularity, workgroup.size, workgroup.why,
            mesh_properties.maxPreferredMeshWorkGroupInvocations,
            yes(mesh_properties.prefersLocalInvocationVertexOutput),
            yes(mesh_properties.prefersLocalInvocationPrimitiveOutput),
            yes(mesh_properties.prefersCompactVertexOutput), ch26::kTaskGroup,
            mesh_properties.maxPreferredTaskWorkGroupInvocations);
        // [/limits]

        // [build-meshlets]
        const ch26::Meshlets built =
            ch26::build_meshlets(positions, indices, kMeshVertices, kMeshTriangles);
        meshlets_ = built;
        meshlet_count_ = uint32_t(built.meshlets.size());
        // One draw launches one task workgroup per 32 meshlets, and a device
        // allows at most maxTaskWorkGroupCount[0] of them along x.
        task_groups_ = (meshlet_count_ + kTaskGroup - 1) / kTaskGroup;
        if (task_groups_ > mesh_properties.maxTaskWorkGroupCount[0])
            throw vkt::Error(shown + ": " + std::to_string(meshlet_count_) +
                             " meshlets need more task workgroups than this device's "
                             "maxTaskWorkGroupCount[0] (" +
                             std::to_string(mesh_properties.maxTaskWorkGroupCount[0]) + ")");
        // [/build-meshlets]
        triangle_count_ = uint32_t(indices.size() / 3);
        std::fprintf(stderr,
                     "26_mesh_shaders: %s: %u triangles, %zu vertices -> %u meshlets "
                     "(at most %u vertices and %u triangles each; the device allows %u and %u)\n",
                     shown.c_str(), triangle_count_, vertices.size(), meshlet_count_, kMeshVertices,
                     kMeshTriangles, mesh_properties.maxMeshOutputVertices,
                     mesh_properties.maxMeshOutputPrimitives);

        // The buffers both pipelines read (chapter 13's storage buffers), the
        // index buffer and the one indirect command of --draw indirect.
        const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        const VkDeviceSize largest =
            std::max(vertices.size() * sizeof(GpuVertex), built.vertices.size() * sizeof(uint32_t));
        if (largest > context.properties.limits.maxStorageBufferRange)
            throw vkt::Error(shown + ": its vertices need a storage buffer of " +
                             std::to_string(largest) +
                             " bytes, more than this device's "
                             "maxStorageBufferRange (" +
                             std::to_string(context.properties.limits.maxStorageBufferRange) + ")");
        buffers_.push_back(vkt::create_device_buffer(gpu, vertices.data(),
                                                     vertices.size() * sizeof(GpuVertex), storage));
        buffers_.push_back(vkt::create_device_buffer(
            gpu, built.meshlets.data(), built.meshlets.size() * sizeof(ch26::Meshlet), storage));
        buffers_.push_back(vkt::create_device_buffer(
            gpu, built.vertices.data(), built.vertices.size() * sizeof(uint32_t), storage));
        buffers_.push_back(vkt::create_device_buffer(
            gpu, built.triangles.data(), built.triangles.size() * sizeof(uint32_t), storage));
        // --view culled: the second camera, per frame in flight, from record()
        shown_ = vkt::create_host_buffer(
            gpu, std::size_t(context.frames_in_flight) * sizeof(glm::mat4), storage);
        counters_ = vkt::create_host_buffer(
            gpu, std::size_t(context.frames_in_flight) * kCounters * sizeof(uint32_t), storage);
        std::memset(counters_.mapped, 0, counters_.size);
        index_buffer_ =
            vkt::create_device_buffer(gpu, indices.data(), indices.size() * sizeof(uint32_t),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        const VkDrawIndexedIndirectCommand whole_model{.indexCount = uint32_t(indices.size()),
                                                       .instanceCount = 1};
        indirect_buffer_ = vkt::create_device_buffer(gpu, &whole_model, sizeof(whole_model),
                                                     VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);

        // One set: the six storage buffers (chapter 07's helpers).
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (uint32_t b = 0; b < 6; ++b)
            bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kStages, nullptr});
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 6};
        pool_ = vkt::create_descriptor_pool(device_, 1, {&pool_size, 1});
        set_ = vkt::allocate_descriptor_set(device_, pool_, set_layout_);
        for (uint32_t b = 0; b < 4; ++b)
            vkt::write_buffer_descriptor(device_, set_, b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                         buffers_[b].buffer, 0, VK_WHOLE_SIZE);
        vkt::write_buffer_descriptor(device_, set_, 4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     counters_.buffer, 0, VK_WHOLE_SIZE);
        vkt::write_buffer_descriptor(device_, set_, 5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     shown_.buffer, 0, VK_WHOLE_SIZE);
        const VkDescriptorSetLayout set_layout = set_layout_;
        const VkPushConstantRange push{kStages, 0, sizeof(Push)};
        layout_ = vkt::create_pipeline_layout(device_, {&set_layout, 1}, {&push, 1});

        depth_format_ = vkt::choose_depth_format(physical_);
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, context.extent);
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "model.frag");
        if (indirect_) {
            // Chapter 15's way: a vertex shader that pulls its vertex.
            vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "model.vert");
            pipeline_ =
                vkt::create_graphics_pipeline(device_, {.vertex = vertex,
                                                        .fragment = fragment,
                                                        .layout = layout_,
                                                        .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                        .color_formats = {context.color_format},
                                                        .depth_format = depth_format_});
        } else {
            vkt::ShaderModule task = vkt::load_shader(device_, context.chapter, "meshlets.task");
            vkt::ShaderModule mesh = vkt::load_shader(device_, context.chapter, "meshlets.mesh");
            pipeline_ = vkt::create_mesh_pipeline(device_, layout_, task, mesh, mesh_workgroup_,
                                                  fragment, context.color_format, depth_format_);
        }

        // [load-draw]
        // vkCmdDrawMeshTasksEXT belongs to an extension: the loader exports
        // only core commands, so the device gives its address.
        draw_mesh_tasks_ = reinterpret_cast<PFN_vkCmdDrawMeshTasksEXT>(
            vkGetDeviceProcAddr(device_, "vkCmdDrawMeshTasksEXT"));
        if (!draw_mesh_tasks_)
            throw vkt::Error("vkGetDeviceProcAddr(vkCmdDrawMeshTasksEXT) failed");
        // [/load-draw]
        std::fprintf(
            stderr, "26_mesh_shaders: %s, %s view, culling %s\n",
            indirect_ ? "one vkCmdDrawIndexedIndirect (vertex shader)" : "task and mesh shaders",
            kViews[view_], cull_ ? "on" : "off");
    }

    void resize(VkExtent2D extent) override {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent);
    }

    void record(const vkt::Frame& frame) override {
        last_ = camera(bounds_lo_, bounds_hi_, frame.extent, frame.time, turn_);
        last_slot_ = frame.slot;
        // [counters]
        // This slot's counters were last written two frames ago, and the
        // runner has waited for that frame: zero them for this one (host
        // writes before the submit are visible to the GPU).
        auto* counters =
            static_cast<uint32_t*>(counters_.mapped) + std::size_t(frame.slot) * kCounters;
        std::fill(counters, counters + kCounters, 0u);
        // [/counters]
        if (view_ == ch26::view_culled)  // the second camera's matrix (culled_view.hpp)
            ch26::show_from(
                shown_.mapped, frame.slot,
                camera(bounds_lo_, bounds_hi_, frame.extent, frame.time, 0, true).clip_from_world);

        vkt::begin_depth_frame(frame.cmd, depth_.image);
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.55f, 0.62f, 0.70f, 1.0f}}, depth_.view);
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                                nullptr);
        const Push push{last_.clip_from_world, glm::vec4(last_.eye, 1.0f), base_colour_, view_,
                        meshlet_count_,        frame.slot * kCounters,     cull_};
        vkCmdPushConstants(frame.cmd, layout_, kStages, 0, sizeof(Push), &push);
        {
            auto scope = frame.gpu_scope("draw");
            // [draw]
            if (indirect_) {
                vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT32);
                vkCmdDrawIndexedIndirect(frame.cmd, indirect_buffer_.buffer, 0, 1,
                                         sizeof(VkDrawIndexedIndirectCommand));
            } else {
                // One task workgroup per 32 meshlets; each launches its own
                // mesh workgroups.
                draw_mesh_tasks_(frame.cmd, task_groups_, 1, 1);
            }
            // [/draw]
        }
        vkCmdEndRendering(frame.cmd);
        // [counters-to-host]
        // The task shader's atomic adds, made visible to the host's read after
        // this frame's fence.
        vkt::buffer_barrier(frame.cmd, counters_.buffer, VK_PIPELINE_STAGE_2_TASK_SHADER_BIT_EXT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                            VK_ACCESS_2_HOST_READ_BIT);
        // [/counters-to-host]
    }

    // After the last frame, the GPU idle: what the task shader counted in it,
    // and what the CPU finds for the same view.
    void verify() override {
        if (indirect_) {
            std::fprintf(stderr, "26_mesh_shaders: submitted %u triangles (the whole model)\n",
                         triangle_count_);
            return;
        }
        // [report]
        const auto* counters =
            static_cast<const uint32_t*>(counters_.mapped) + std::size_t(last_slot_) * kCounters;
        std::fprintf(stderr,
                     "26_mesh_shaders: the last frame %s %u of %u meshlets (%u outside the "
                     "frustum, %u facing away), drew %u meshlets, submitted %u of %u triangles\n",
                     view_ == ch26::view_culled ? "would have culled" : "culled",
                     counters[0] + counters[1], meshlet_count_, counters[0], counters[1],
                     counters[3], counters[2], triangle_count_);
        // [/report]
        if (cull_) {
            const ch26::Culled cpu = ch26::cull_on_cpu(meshlets_, last_.clip_from_world, last_.eye);
            std::fprintf(stderr,
                         "26_mesh_shaders: the CPU culls %u for that view (%u outside the "
                         "frustum, %u facing away)\n",
                         cpu.frustum + cpu.cone, cpu.frustum, cpu.cone);
        }
    }

private:
    VkPhysicalDevice physical_;
    VkDevice device_;
    bool indirect_ = false;
    uint32_t view_ = 0, cull_ = 1;
    float turn_ = 0.0f;
    glm::vec3 bounds_lo_{0.0f}, bounds_hi_{0.0f};
    glm::vec4 base_colour_{1.0f};
    ch26::Meshlets meshlets_;
    uint32_t meshlet_count_ = 0, task_groups_ = 0, triangle_count_ = 0;
    uint32_t mesh_workgroup_ = ch26::kMeshWorkgroup;  // choose_mesh_workgroup
    View last_{};
    uint32_t last_slot_ = 0;
    std::vector<vkt::Buffer> buffers_;  // vertices, meshlets, their vertices, their triangles
    vkt::Buffer shown_, counters_, index_buffer_, indirect_buffer_;  // shown_: culled_view.hpp
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;  // freed with pool_
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image depth_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
    PFN_vkCmdDrawMeshTasksEXT draw_mesh_tasks_ = nullptr;
};

}  // namespace

int main(int argc, char** argv) {
    vkt::ChapterSpec spec{.name = "26_mesh_shaders", .title = "26 - mesh shaders"};
    // [device]
    // The extension, and its two features: turned on through the feature
    // struct of the extension, linked into vkCreateDevice's pNext chain.
    static VkPhysicalDeviceMeshShaderFeaturesEXT mesh_features{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT,
        .taskShader = VK_TRUE,
        .meshShader = VK_TRUE,
    };
    spec.requirements.extensions = {VK_EXT_MESH_SHADER_EXTENSION_NAME};
    spec.requirements.extension_features = &mesh_features;
    // The depth barrier's DEPTH_ATTACHMENT_OPTIMAL layout (chapter 08).
    // glslang gives task and mesh shaders their workgroup size as LocalSizeId,
    // which needs maintenance4 (core in Vulkan 1.3, but a feature to turn on).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts),
                                  VKT_FEATURE_13(maintenance4)};
    // [/device]
    spec.options = {
        {.name = "--draw",
         .type = vkt::OptionType::choice,
         .help = "task and mesh shaders, or chapter 15's one indirect draw (vertex shader)",
         .default_value = "mesh",
         .choices = {"mesh", "indirect"}},
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .help = "the lit model, each meshlet in its own colour, or what is culled (in colours)",
         .default_value = "lit",
         .choices = {"lit", "meshlets", "culled"}},
        {.name = "--cull",
         .type = vkt::OptionType::choice,
         .help = "cull meshlets in the task shader (frustum and normal cone)",
         .default_value = "on",
         .choices = {"on", "off"}},
        {.name = "--turn",
         .type = vkt::OptionType::number,
         .value_name = "DEGREES",
         .help = "turn the camera's gaze this far left of the model",
         .default_value = "0",
         .min = -180.0,
         .max = 180.0},
        {.name = "--model",
         .type = vkt::OptionType::text,
         .value_name = "FILE",
         .help = "a glTF 2.0 file, .gltf or .glb (default: assets/gltf/knot.glb)"},
        vkt::max_memory_option(),
    };
    spec.check_options = ch26::check_view;
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<MeshShaders>(context);
    });
}
