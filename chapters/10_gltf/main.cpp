// Chapter 10: glTF.
//
// A whole scene from a file: meshes, materials, textures and a node tree,
// read by vkt::load_gltf (common/scene/src/gltf.cpp, which the book walks through)
// into plain arrays. This file turns those arrays into GPU objects: one vertex
// and one index buffer for every mesh, one texture per image, one descriptor
// set per material, and one draw per (node, primitive) with its world matrix
// in push constants. The camera frames the scene from its bounding box, so any
// model the reader passes with --model fills the picture.

#include "vkt/core/files.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/align.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/texture.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/gltf.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace {

// [push-constants]
// Per draw: where the primitive lands on screen, and how its normals turn
// into the world (the inverse transpose of the world matrix, so that a
// non-uniform scale keeps them perpendicular to the surface; chapter 12 says
// more). 128 bytes: the least maxPushConstantsSize a device may have.
struct DrawConstants {
    glm::mat4 clip_from_object;
    glm::mat4 normal_matrix;
};
// [/push-constants]

// [material-block]
// What a material's uniform block holds (set 0, binding 0 in gltf.frag).
struct MaterialBlock {
    glm::vec4 base_color_factor;
};
// [/material-block]

// [camera]
// The camera looks at the centre of the scene's bounding box from outside its
// bounding sphere (radius: half the box's diagonal). A sphere of radius r
// just fits a cone of half-angle a seen from distance r / sin(a), where a is
// half the narrower of the two fields of view. Near and far hug the sphere,
// which keeps depth precise at any scale, from millimetres to kilometres.
// The camera orbits at 0.25 rad/s, 25 degrees above the horizon: a function
// of frame.time only, so headless frames are reproducible.
glm::mat4 camera(const vkt::GltfScene& scene, VkExtent2D extent, double time) {
    const glm::vec3 centre = 0.5f * (scene.bounds_min + scene.bounds_max);
    const float radius = std::max(0.5f * glm::length(scene.bounds_max - scene.bounds_min), 1e-4f);
    const float fov_y = glm::radians(45.0f);
    const float aspect = float(extent.width) / float(extent.height);
    const float fov_x = 2.0f * std::atan(std::tan(fov_y / 2.0f) * aspect);
    const float distance = radius / std::sin(std::min(fov_x, fov_y) / 2.0f);
    const float azimuth = 0.6f + 0.25f * float(time), elevation = glm::radians(25.0f);
    const glm::vec3 eye =
        centre + distance * glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                      std::cos(elevation) * std::cos(azimuth));
    const glm::mat4 view = glm::lookAt(eye, centre, glm::vec3(0.0f, 1.0f, 0.0f));
    const float z_near = 0.9f * (distance - radius), z_far = 1.1f * (distance + radius);
    return vkt::vulkan_perspective(fov_y, aspect, z_near, z_far) * view;
}
// [/camera]

class GltfViewer : public vkt::Renderer {
public:
    explicit GltfViewer(const vkt::Context& context)
        : physical_(context.physical), device_(context.device) {
        // [load]
        // The default asset, or the reader's own file. load_gltf checks every
        // index and size and throws one line naming the file and the fault;
        // what it skipped, it reports in `warnings`.
        const std::string model = context.options.has("--model")
                                      ? context.options.text("--model")
                                      : vkt::asset_path("gltf/scene.gltf").string();
        scene_ = vkt::load_gltf(model, uint64_t(context.options.integer("--max-memory")));
        for (const std::string& warning : scene_.warnings)
            std::fprintf(stderr, "10_gltf: %s: warning: %s\n", vkt::shown_path(model).c_str(),
                         warning.c_str());
        std::fprintf(stderr,
                     "10_gltf: %s: draws %zu, primitives %zu, materials %zu, images %zu, "
                     "vertices %zu, indices %zu\n",
                     vkt::shown_path(model).c_str(), scene_.draws.size(), scene_.primitives.size(),
                     scene_.materials.size(), scene_.images.size(), scene_.vertices.size(),
                     scene_.indices.size());
        // [/load]

        // [buffers]
        // Every primitive's vertices in one buffer, every index in another:
        // one bind for the whole scene, and each draw names its index range.
        const vkt::Gpu gpu = context.gpu();
        vertex_buffer_ = vkt::create_device_buffer(gpu, scene_.vertices.data(),
                                                   scene_.vertices.size() * sizeof(vkt::GltfVertex),
                                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ = vkt::create_device_buffer(gpu, scene_.indices.data(),
                                                  scene_.indices.size() * sizeof(uint32_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        // [/buffers]

        // [textures]
        // One texture per image (sRGB: base colours are stored sRGB-encoded),
        // and a 1x1 white one for materials without an image, so that every
        // material can be drawn by the same shader: white * factor = factor.
        // Anisotropic filtering stays off: on lavapipe 25 it samples black
        // where a triangle's texture coordinates are constant (zero
        // derivatives), as on a primitive without TEXCOORD_0.
        const float anisotropy = 0.0f;
        for (const vkt::RgbaImage& image : scene_.images)
            textures_.push_back(vkt::create_texture(gpu, image, true, anisotropy));
        const vkt::RgbaImage white{1, 1, std::vector<uint8_t>{255, 255, 255, 255}};
        white_ = vkt::create_texture(gpu, white, true, anisotropy);
        // [/textures]

        // [materials]
        // Each material's factor in a slice of one uniform buffer, each slice
        // aligned as the device wants; a descriptor set per material points at
        // its slice (binding 0) and its texture (binding 1).
        const VkDeviceSize stride = vkt::align_up(
            sizeof(MaterialBlock), context.properties.limits.minUniformBufferOffsetAlignment);
        const uint32_t material_count = uint32_t(scene_.materials.size());
        std::vector<std::byte> blocks(material_count * stride);
        for (uint32_t m = 0; m < material_count; ++m) {
            const MaterialBlock block{scene_.materials[m].base_color_factor};
            std::memcpy(blocks.data() + m * stride, &block, sizeof block);
        }
        material_buffer_ = vkt::create_device_buffer(gpu, blocks.data(), blocks.size(),
                                                     VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr},
        };
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize sizes[] = {
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, material_count},
            {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, material_count},
        };
        pool_ = vkt::create_descriptor_pool(device_, material_count, sizes);
        for (uint32_t m = 0; m < material_count; ++m) {
            const VkDescriptorSet set = vkt::allocate_descriptor_set(device_, pool_, set_layout_);
            vkt::write_buffer_descriptor(device_, set, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                         material_buffer_.buffer, m * stride,
                                         sizeof(MaterialBlock));
            const int32_t image = scene_.materials[m].base_color_image;
            const vkt::Texture& texture = image >= 0 ? textures_[size_t(image)] : white_;
            vkt::write_image_descriptor(device_, set, 1, texture.image.view, texture.sampler,
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            material_sets_.push_back(set);
        }
        // [/materials]

        // [pipeline]
        // The loader's vertex layout, as vertex input: 32 bytes per vertex.
        const VkVertexInputBindingDescription binding{0, sizeof(vkt::GltfVertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::GltfVertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::GltfVertex, normal)},
            {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(vkt::GltfVertex, uv)},
        };
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(DrawConstants)};
        const VkDescriptorSetLayout set_layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(device_, set_layouts, {&push, 1});
        depth_format_ = vkt::choose_depth_format(physical_);
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, context.extent);
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "gltf.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "gltf.frag");
        // No culling: glTF materials may be double-sided, and a model that is
        // not closed shows its inside; the fragment shader lights back faces
        // with their normal turned round.
        pipeline_ =
            vkt::create_graphics_pipeline(device_, {
                                                       .vertex = vertex,
                                                       .fragment = fragment,
                                                       .layout = layout_,
                                                       .bindings = {&binding, 1},
                                                       .attributes = attributes,
                                                       .cull_mode = VK_CULL_MODE_NONE,
                                                       .color_formats = {context.color_format},
                                                       .depth_format = depth_format_,
                                                   });
        // [/pipeline]
    }

    void resize(VkExtent2D extent) override {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent);
    }

    void record(const vkt::Frame& frame) override {
        vkt::begin_depth_frame(frame.cmd, depth_.image);
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.02f, 0.02f, 0.04f, 1.0f}}, depth_.view);

        // [draw]
        // One bind of the pipeline and the two buffers for the whole scene;
        // per draw, the material's set (only when it changes) and the
        // matrices, then the primitive's range of the index buffer.
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        const VkBuffer vertex_buffer = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT32);
        const glm::mat4 clip_from_world = camera(scene_, frame.extent, frame.time);
        uint32_t bound_material = UINT32_MAX;
        for (const vkt::GltfDraw& draw : scene_.draws) {
            const vkt::GltfPrimitive& primitive = scene_.primitives[draw.primitive];
            if (primitive.material != bound_material) {
                bound_material = primitive.material;
                vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1,
                                        &material_sets_[bound_material], 0, nullptr);
            }
            const DrawConstants constants{clip_from_world * draw.world,
                                          glm::transpose(glm::inverse(draw.world))};
            vkCmdPushConstants(frame.cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof constants,
                               &constants);
            // The indices already count from the start of the vertex buffer.
            vkCmdDrawIndexed(frame.cmd, primitive.index_count, 1, primitive.first_index, 0, 0);
        }
        vkCmdEndRendering(frame.cmd);
        // [/draw]
    }

private:
    VkPhysicalDevice physical_;
    VkDevice device_;
    vkt::GltfScene scene_;
    vkt::Buffer vertex_buffer_;
    vkt::Buffer index_buffer_;
    std::vector<vkt::Texture> textures_;
    vkt::Texture white_;
    vkt::Buffer material_buffer_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> material_sets_;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image depth_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "10_gltf", .title = "10 - glTF"};
    // Chapter 08's depth layouts (vkt::begin_depth_frame).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.options = {{.name = "--model",
                     .type = vkt::OptionType::text,
                     .value_name = "FILE",
                     .help = "a glTF 2.0 file, .gltf or .glb (default: assets/gltf/scene.gltf)"},
                    vkt::max_memory_option()};
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<GltfViewer>(context);
    });
}
