#pragma once
// The runner's overlay (vkt/frame/overlay.hpp, chapter 21), private to
// common/frame. Dear ImGui turns the chapter's widgets into triangles each
// frame; this class owns what draws them: the font atlas as a texture, one
// pipeline (alpha-blended, scissored per command, into the frame's target
// with its contents kept), and per frame in flight a host-visible vertex and
// index buffer that grows when the panel does.

#include "vkt/frame/input.hpp"
#include "vkt/frame/overlay.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/texture.hpp"
#include "vkt/resources/upload.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

struct ImGuiContext;  // Dear ImGui's, declared at global scope as imgui.h does

namespace vkt::detail {

class Overlay {
public:
    explicit Overlay(const Context& context);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // This frame's panel: the reader's pointer in, then fill() adds the
    // chapter's widgets (Renderer::overlay).
    void build(const Input& input, VkExtent2D extent, double seconds,
               const std::function<void(OverlayPanel&)>& fill);
    // Draws the panel over `target` (in COLOR_ATTACHMENT_OPTIMAL, its
    // contents kept) with `slot`'s buffers.
    void record(VkCommandBuffer cmd, uint32_t slot, VkImageView target, VkExtent2D extent);

private:
    struct SlotBuffers {
        Buffer vertices, indices;
    };
    void upload(SlotBuffers& buffers, VkDeviceSize vertex_bytes, VkDeviceSize index_bytes);

    Gpu gpu_;
    std::string chapter_;
    ::ImGuiContext* imgui_ = nullptr;
    Texture font_;
    DescriptorSetLayout set_layout_;
    DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    PipelineLayout layout_;
    Pipeline pipeline_;
    std::vector<SlotBuffers> slots_;
    double last_seconds_ = -1;
    std::unique_ptr<OverlayPanel> panel_;
};

}  // namespace vkt::detail
