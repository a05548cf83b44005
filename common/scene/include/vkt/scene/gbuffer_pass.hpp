#pragma once
// The G-buffer pass, taught in chapter 16 and reused by chapter 17: the
// scene's meshes on the GPU, the G-buffer's four images, pass 1 that draws the
// scene into them, and the two barriers around it. Chapter 16's page shows
// every line. The shaders are the shared shaders/common/deferred/scene.vert
// and gbuffer.frag, which each chapter compiles into its own folder, so they
// are loaded under the chapter's own name (Context::chapter).
//
// Also here, because chapter 17 reads the G-buffer as chapter 16 does: the
// descriptors that point a set at the images, and the start of chapter 16's
// full-screen lighting pass.

#include "vkt/core/memory.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/scene/deferred_scene.hpp"

#include <array>
#include <span>
#include <vector>

namespace vkt::deferred {

// [formats]
// The G-buffer: 16 bytes per pixel in all.
constexpr VkFormat base_colour_format = VK_FORMAT_R8G8B8A8_SRGB;  // 4 B: albedo, sRGB-encoded
constexpr VkFormat normal_format = VK_FORMAT_R16G16_SNORM;        // 4 B: octahedral normal
constexpr VkFormat material_format = VK_FORMAT_R8G8B8A8_UNORM;    // 4 B: specular, shininess
constexpr VkFormat depth_format = VK_FORMAT_D32_SFLOAT;           // 4 B: depth, sampled later
// [/formats]
constexpr VkFormat gbuffer_formats[] = {base_colour_format, normal_format, material_format};

// The scene's shapes (deferred_scene.hpp) in one vertex and one index buffer,
// and the pipeline layout that draws them: set 0 is the frame's set, the push
// constants an ObjectPush. Pass 1 draws them, and so does chapter 16's
// forward path, with the same vertex shader.
class SceneMeshes {
public:
    SceneMeshes(const Gpu& gpu, VkDescriptorSetLayout frame_layout);

    VkPipelineLayout layout() const { return layout_; }
    // scene.vert's input: binding 0, position and normal of vkt::shapes::Vertex.
    static const VkVertexInputBindingDescription vertex_binding;
    static const std::array<VkVertexInputAttributeDescription, 2> vertex_attributes;

    // Binds the buffers and set 0, then draws each object with its push constants.
    void draw(VkCommandBuffer cmd, VkDescriptorSet frame_set,
              std::span<const Object> objects) const;

private:
    vkt::shapes::MeshRange meshes_[mesh_count];
    Buffer vertex_buffer_, index_buffer_;
    PipelineLayout layout_;
};

// One G-buffer: its four images.
struct GBuffer {
    Image base_colour, normal, material, depth;
};

class GBufferPass {
public:
    // `readers`: the shader stages that read the G-buffer after the pass
    // (chapter 16: the lighting pass's FRAGMENT_SHADER; 17 adds COMPUTE_SHADER).
    // Throws when the device cannot use the formats as the pass needs.
    GBufferPass(const Context& context, const SceneMeshes& scene, VkPipelineStageFlags2 readers);

    // (Re)creates the images at the target's size; rewrite the descriptors after.
    void resize(VkExtent2D extent);
    const GBuffer& images() const { return gbuffer_; }

    // Bindings 0..3 of a set: the four images as combined image samplers, seen
    // by `stages`; write_descriptors points a set's bindings 0..3 at them, in
    // the layouts that to_read leaves them in.
    static std::array<VkDescriptorSetLayoutBinding, 4> bindings(VkShaderStageFlags stages);
    void write_descriptors(VkDescriptorSet set) const;

    // The barrier before pass 1, pass 1, and the barrier after it; record()
    // is the three in order.
    void to_write(VkCommandBuffer cmd) const;
    void draw(VkCommandBuffer cmd, VkDescriptorSet frame_set, VkExtent2D extent,
              std::span<const Object> objects) const;
    void to_read(VkCommandBuffer cmd) const;
    void record(VkCommandBuffer cmd, VkDescriptorSet frame_set, VkExtent2D extent,
                std::span<const Object> objects) const;

private:
    struct Transition;
    void transition(VkCommandBuffer cmd, const Transition& colour, const Transition& depth) const;

    VkPhysicalDevice physical_;
    VkDevice device_;
    const SceneMeshes* scene_;
    VkPipelineStageFlags2 readers_;
    Pipeline pipeline_;
    Sampler sampler_;
    GBuffer gbuffer_;
};

// How chapter 16's lighting pass begins: dynamic rendering into the one colour
// target, no depth, every pixel written; viewport and scissor set. End it with
// vkCmdEndRendering.
void begin_full_screen(VkCommandBuffer cmd, VkImageView target, VkExtent2D extent);

}  // namespace vkt::deferred
