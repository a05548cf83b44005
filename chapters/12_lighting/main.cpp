// Chapter 12: lighting.
//
// A floor and a few shapes (cubes, low-poly spheres, tori, cylinders and a
// squashed sphere) under coloured point lights that move with time. Each
// surface point gets ambient light, Lambert diffuse light and a Blinn-Phong
// highlight from every light, dimmed with distance (vkt/scene/lighting.hpp on the
// CPU, shaders/common/lighting.glsl on the GPU: the same formulas).
//
// The scene is mirror-symmetric about x = 0, and so are the lights: the left
// half of the picture is lit per vertex, the right half per fragment, so each
// object on the left can be compared with its mirror image on the right. The
// two modes are two pipelines made from the same shaders with a
// specialization constant. New here besides the lighting: the normal matrix,
// and specialization constants.

#include "blocks.hpp"
#include "scene.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/lighting.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace ch12;  // the scene (scene.hpp) and the blocks (blocks.hpp)
using vkt::shapes::MeshRange;
using vkt::shapes::Vertex;

// [normal-matrix]
// Positions go through the model matrix; normals through the inverse
// transpose of its upper 3x3 (vkt::normal_matrix), which keeps them
// perpendicular to the surface under a non-uniform scale. --normal-matrix
// model uses the model matrix for normals too, to show what goes wrong.
ObjectPush object_push(const Object& object, bool inverse_transpose) {
    const glm::mat3 normals =
        inverse_transpose ? vkt::normal_matrix(object.model) : glm::mat3(object.model);
    ObjectPush push{};
    push.model = object.model;
    for (int column = 0; column < 3; ++column)
        push.normal_matrix[column] = glm::vec4(normals[column], 0.0f);
    push.albedo = object.albedo;
    push.emissive = object.emissive;
    return push;
}
// [/normal-matrix]

class Lighting : public vkt::Renderer {
public:
    explicit Lighting(const vkt::Context& context)
        : physical_(context.physical), device_(context.device) {
        const vkt::Options& options = context.options;
        shading_ = options.text("--shading");
        light_count_ = uint32_t(options.integer("--lights"));
        falloff_ =
            options.text("--falloff") == "classic" ? vkt::Falloff::classic : vkt::Falloff::windowed;
        inverse_transpose_ = options.text("--normal-matrix") == "inverse-transpose";
        std::fprintf(stderr, "12_lighting: %u light%s, shading %s, %s falloff, normals by %s\n",
                     light_count_, light_count_ == 1 ? "" : "s", shading_.c_str(),
                     options.text("--falloff").c_str(), options.text("--normal-matrix").c_str());

        depth_format_ = vkt::choose_depth_format(physical_);
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, context.extent);

        // Every shape in one vertex and one index buffer (scene.hpp).
        vkt::shapes::MeshBuilder builder;
        build_meshes(builder, meshes_);
        const vkt::Gpu gpu = context.gpu();
        vertex_buffer_ = vkt::create_device_buffer(gpu, builder.vertices.data(),
                                                   builder.vertices.size() * sizeof(Vertex),
                                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ = vkt::create_device_buffer(gpu, builder.indices.data(),
                                                  builder.indices.size() * sizeof(uint16_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

        // The scene block, one per frame in flight, read by both shaders.
        const VkDescriptorSetLayoutBinding binding{
            0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
            VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
        set_layout_ = vkt::create_descriptor_set_layout(device_, {&binding, 1});
        const uint32_t sets = context.frames_in_flight;
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets};
        pool_ = vkt::create_descriptor_pool(device_, sets, {&size, 1});
        for (uint32_t i = 0; i < sets; ++i) {
            scene_buffers_.push_back(vkt::create_host_buffer(gpu, sizeof(SceneUniforms),
                                                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
            sets_.push_back(vkt::allocate_descriptor_set(device_, pool_, set_layout_));
            vkt::write_buffer_descriptor(device_, sets_[i], 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                         scene_buffers_[i].buffer, 0, sizeof(SceneUniforms));
        }
        const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                        0, sizeof(ObjectPush)};
        const VkDescriptorSetLayout set_layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(device_, set_layouts, {&range, 1});

        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "lit.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "lit.frag");
        const VkVertexInputBindingDescription input{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
        };
        // [specialization]
        // constant_id 0 is PER_FRAGMENT in both shaders. A specialization
        // constant is fixed when the pipeline is made, so the compiler drops
        // the branch not taken: two pipelines, each as fast as if written
        // alone. A bool constant takes 4 bytes (a VkBool32).
        const VkSpecializationMapEntry entry{
            .constantID = 0,
            .offset = 0,
            .size = sizeof(VkBool32),
        };
        for (VkBool32 per_fragment : {VK_FALSE, VK_TRUE}) {
            const VkSpecializationInfo specialization{
                .mapEntryCount = 1,
                .pMapEntries = &entry,
                .dataSize = sizeof per_fragment,
                .pData = &per_fragment,
            };
            pipelines_[per_fragment] = vkt::create_graphics_pipeline(
                device_, {
                             .vertex = vertex,
                             .fragment = fragment,
                             .layout = layout_,
                             .bindings = {&input, 1},
                             .attributes = attributes,
                             .cull_mode = VK_CULL_MODE_BACK_BIT,
                             .color_formats = {context.color_format},
                             .depth_format = depth_format_,
                             .vertex_specialization = &specialization,
                             .fragment_specialization = &specialization,
                         });
        }
        // [/specialization]
    }

    void resize(VkExtent2D extent) override {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent);
    }

    void record(const vkt::Frame& frame) override {
        const float t = float(frame.time);
        // [update]
        // The camera, the lighting constants and the lights, once per frame.
        SceneUniforms scene{};
        scene.view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
        scene.proj = vkt::vulkan_perspective(glm::radians(45.0f),
                                             float(frame.extent.width) / float(frame.extent.height),
                                             0.1f, 100.0f);
        scene.camera_position = eye;
        const vkt::LightingParams params{.falloff = falloff_, .classic = {1.0f, 0.35f, 0.44f}};
        scene.ambient = params.ambient;
        scene.falloff = int32_t(params.falloff);
        scene.classic = {params.classic.constant, params.classic.linear, params.classic.quadratic};
        scene.specular = params.specular;
        scene.shininess = params.shininess;
        const std::vector<vkt::PointLight> lights = make_lights(light_count_, t);
        scene.light_count = int32_t(lights.size());
        std::memcpy(scene.lights, lights.data(), lights.size() * sizeof(vkt::PointLight));
        std::memcpy(scene_buffers_[frame.slot].mapped, &scene, sizeof scene);
        // [/update]

        vkt::begin_depth_frame(frame.cmd, depth_.image);
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.02f, 0.02f, 0.04f, 1.0f}}, depth_.view);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        const VkBuffer vertex_buffer = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1,
                                &sets_[frame.slot], 0, nullptr);

        // [split]
        // Split: the whole scene twice, through the same full-size viewport,
        // but each time the scissor lets only one half through: the left half
        // per vertex (pipelines_[0]), the right half per fragment
        // (pipelines_[1]), with a thin gap of background between them.
        const uint32_t w = frame.extent.width, h = frame.extent.height;
        const uint32_t gap = std::max(1u, w / 320);
        struct Pass {
            VkPipeline pipeline;
            VkRect2D scissor;
        };
        std::vector<Pass> passes;
        if (shading_ == "split") {
            passes.push_back({pipelines_[0], {{0, 0}, {w / 2 - gap, h}}});
            passes.push_back({pipelines_[1], {{int32_t(w / 2 + gap), 0}, {w - w / 2 - gap, h}}});
        } else {
            passes.push_back({pipelines_[shading_ == "fragment"], {{0, 0}, frame.extent}});
        }
        std::vector<Object> objects = make_objects(t);
        // A small glowing sphere at each light, in its colour.
        for (const vkt::PointLight& light : lights)
            objects.push_back({sphere_mesh,
                               vkt::transform(light.position, 0.0f, {0, 1, 0}, glm::vec3(0.25f)),
                               light.colour, 1.0f});
        for (const Pass& pass : passes) {
            vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.pipeline);
            vkCmdSetScissor(frame.cmd, 0, 1, &pass.scissor);
            for (const Object& object : objects) {
                const ObjectPush push = object_push(object, inverse_transpose_);
                vkCmdPushConstants(frame.cmd, layout_,
                                   VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                   sizeof push, &push);
                const MeshRange& mesh = meshes_[object.mesh];
                vkCmdDrawIndexed(frame.cmd, mesh.index_count, 1, mesh.first_index, 0, 0);
            }
        }
        // [/split]
        vkCmdEndRendering(frame.cmd);
    }

private:
    VkPhysicalDevice physical_;
    VkDevice device_;
    std::string shading_;
    uint32_t light_count_ = 1;
    vkt::Falloff falloff_ = vkt::Falloff::windowed;
    bool inverse_transpose_ = true;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image depth_;
    MeshRange meshes_[mesh_count];
    vkt::Buffer vertex_buffer_;
    vkt::Buffer index_buffer_;
    std::vector<vkt::Buffer> scene_buffers_;  // [slot]: SceneUniforms
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;  // [slot]
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipelines_[2];  // [0] per vertex, [1] per fragment
};

}  // namespace

int main(int argc, char** argv) {
    vkt::ChapterSpec spec{.name = "12_lighting", .title = "12 - lighting"};
    // The depth image's DEPTH_ATTACHMENT_OPTIMAL layout (vkt::begin_depth_frame).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.options = {
        {.name = "--shading",
         .type = vkt::OptionType::choice,
         .value_name = "MODE",
         .help = "split (left per vertex, right per fragment), vertex or fragment",
         .default_value = "split",
         .choices = {"split", "vertex", "fragment"}},
        {.name = "--lights",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many point lights, 1 to 16",
         .default_value = "5",
         .min = 1,
         .max = double(ch12::max_lights)},
        {.name = "--falloff",
         .type = vkt::OptionType::choice,
         .value_name = "KIND",
         .help = "windowed (zero at each light's radius) or classic 1/(c + l d + q d^2)",
         .default_value = "windowed",
         .choices = {"windowed", "classic"}},
        {.name = "--normal-matrix",
         .type = vkt::OptionType::choice,
         .value_name = "KIND",
         .help = "inverse-transpose (right), or model (wrong under non-uniform scale)",
         .default_value = "inverse-transpose",
         .choices = {"inverse-transpose", "model"}},
    };
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Lighting>(context);
    });
}
