// The overlay (vkt/frame/overlay.hpp, chapter 21): Dear ImGui for the layout,
// our own pipeline for the drawing. Debian 12's Dear ImGui (1.86) ships a
// Vulkan backend, but one that draws only inside a VkRenderPass, which this
// tutorial never makes (dynamic rendering throughout); and the drawing is
// small: ImGui hands over triangles, a texture and scissor rectangles.

#include "overlay.hpp"

#include "vkt/core/check.hpp"

#if !VKT_HAVE_IMGUI
// Built without Dear ImGui: no chapter gets an overlay (the runner asks
// overlay_available() before it makes one), and a window says so.
namespace vkt {
bool overlay_available() {
    return false;
}
namespace detail {
Overlay::Overlay(const Context&) {
    throw Error("this build has no overlay (Dear ImGui was not found)");
}
Overlay::~Overlay() = default;
void Overlay::build(const Input&, VkExtent2D, double, const std::function<void(OverlayPanel&)>&) {}
void Overlay::record(VkCommandBuffer, uint32_t, VkImageView, VkExtent2D) {}
}  // namespace detail
}  // namespace vkt
#else
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <map>

namespace vkt {

bool overlay_available() {
    return true;
}

namespace detail {
namespace {

// The panel a chapter fills, on Dear ImGui's widgets. It says on standard
// error where each widget is (once, and again if it moves) and every change
// the reader makes: the events the window test waits for and clicks by.
class ImGuiPanel final : public OverlayPanel {
public:
    explicit ImGuiPanel(std::string chapter) : chapter_(std::move(chapter)) {}

    bool checkbox(const char* label, bool& value) override {
        const bool changed = ImGui::Checkbox(label, &value);
        where(label);
        if (changed) said(label, value ? "on" : "off");
        return changed;
    }
    bool slider(const char* label, float& value, float min, float max) override {
        const bool changed = ImGui::SliderFloat(label, &value, min, max);
        where(label);
        if (changed) said(label, std::to_string(value));
        return changed;
    }
    bool choice(const char* label, int& index, std::span<const char* const> names) override {
        ImGui::TextUnformatted(label);
        bool changed = false;
        for (size_t i = 0; i < names.size(); ++i) {
            if (i > 0) ImGui::SameLine();
            ImGui::PushID(int(i));
            changed = ImGui::RadioButton(names[i], &index, int(i)) || changed;
            ImGui::PopID();
            where(std::string(label) + ": " + names[i]);
        }
        if (changed) said(label, names[size_t(index)]);
        return changed;
    }
    void text(const std::string& line) override {
        // Wrapped at 24 em, or sooner in a narrow window: a long line
        // (chapter 21's memory note) would widen the panel past its edge.
        const float room = ImGui::GetIO().DisplaySize.x - 30.0f;  // less the margins
        ImGui::PushTextWrapPos(std::max(std::min(ImGui::GetFontSize() * 24.0f, room), 100.0f));
        ImGui::TextUnformatted(line.c_str());
        ImGui::PopTextWrapPos();
    }

private:
    void where(const std::string& name) {
        const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
        const int box[4] = {int(min.x), int(min.y), int(max.x - min.x), int(max.y - min.y)};
        auto [known, added] = shown_.try_emplace(name);
        if (!added && std::equal(box, box + 4, known->second.begin())) return;
        std::copy(box, box + 4, known->second.begin());
        std::fprintf(stderr, "%s: overlay: '%s' at %d,%d %dx%d\n", chapter_.c_str(), name.c_str(),
                     box[0], box[1], box[2], box[3]);
    }
    void said(const char* label, const std::string& value) const {
        std::fprintf(stderr, "%s: overlay: %s = %s\n", chapter_.c_str(), label, value.c_str());
    }

    std::string chapter_;
    std::map<std::string, std::array<int, 4> > shown_;
};

// overlay.vert's push constants: window pixels to clip space.
struct Push {
    float scale[2];
    float translate[2];
};

}  // namespace

Overlay::Overlay(const Context& context)
    : gpu_(context.gpu()),
      chapter_(context.chapter),
      panel_(std::make_unique<ImGuiPanel>(chapter_)) {
    IMGUI_CHECKVERSION();
    imgui_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini: the panel is the same on every run
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();

    // The font atlas: white glyphs whose alpha is their coverage, so UNORM
    // (it holds no colours) and one mip level (it is drawn at its own size).
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    RgbaImage atlas{uint32_t(width), uint32_t(height), {}};
    atlas.pixels.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
    font_ = create_texture(gpu_, atlas, false, 0.0f, MipGeneration::none);

    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                               VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    set_layout_ = create_descriptor_set_layout(gpu_.device, {&binding, 1});
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    pool_ = create_descriptor_pool(gpu_.device, 1, {&size, 1});
    set_ = allocate_descriptor_set(gpu_.device, pool_, set_layout_);
    write_image_descriptor(gpu_.device, set_, 0, font_.image.view, font_.sampler,
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);

    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push)};
    const VkDescriptorSetLayout set_layout = set_layout_;
    layout_ = create_pipeline_layout(gpu_.device, {&set_layout, 1}, {&push, 1});
    // ImGui's vertex: position and texture coordinate in window pixels, and
    // a colour of four bytes (sRGB-encoded: overlay.vert decodes it, since
    // our target is an _SRGB image that encodes what we write).
    const VkVertexInputBindingDescription vertex{0, sizeof(ImDrawVert),
                                                 VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[] = {
        {0, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(ImDrawVert, pos))},
        {1, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(ImDrawVert, uv))},
        {2, 0, VK_FORMAT_R8G8B8A8_UNORM, uint32_t(offsetof(ImDrawVert, col))},
    };
    const ShaderModule vert = load_shader(gpu_.device, chapter_, "overlay.vert");
    const ShaderModule frag = load_shader(gpu_.device, chapter_, "overlay.frag");
    pipeline_ = create_graphics_pipeline(gpu_.device, {.vertex = vert,
                                                       .fragment = frag,
                                                       .layout = layout_,
                                                       .bindings = {&vertex, 1},
                                                       .attributes = attributes,
                                                       .color_formats = {context.color_format},
                                                       .alpha_blend = true});
    slots_.resize(context.frames_in_flight);
}

Overlay::~Overlay() {
    ImGui::DestroyContext(imgui_);
}

void Overlay::build(const Input& input, VkExtent2D extent, double seconds,
                    const std::function<void(OverlayPanel&)>& fill) {
    ImGui::SetCurrentContext(imgui_);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(extent.width), float(extent.height));
    io.DeltaTime =
        last_seconds_ < 0 ? 1.0f / 60.0f : float(std::max(seconds - last_seconds_, 1e-4));
    last_seconds_ = seconds;
    // The pointer. A click that went down and up between two frames still
    // counts: the button is down in this frame, up in the next.
    const bool left = input.buttons[0] || input.buttons_pressed[0];
    const ImVec2 at = input.cursor_inside ? ImVec2(float(input.cursor_x), float(input.cursor_y))
                                          : ImVec2(-FLT_MAX, -FLT_MAX);
#if IMGUI_VERSION_NUM >= 18700
    io.AddMousePosEvent(at.x, at.y);
    io.AddMouseButtonEvent(0, left);
#else
    io.MousePos = at;
    io.MouseDown[0] = left;
#endif
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Settings", nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    fill(*panel_);
    ImGui::End();
    ImGui::Render();
}

// [overlay-upload]
void Overlay::upload(SlotBuffers& buffers, VkDeviceSize vertex_bytes, VkDeviceSize index_bytes) {
    // Grown to the next power of two when too small: the slot's last frame
    // is finished (the runner waited for its fence), so the old ones may go.
    auto fit = [&](Buffer& buffer, VkDeviceSize bytes, VkBufferUsageFlags usage) {
        if (buffer.size >= bytes) return;
        VkDeviceSize size = 4096;
        while (size < bytes) size *= 2;
        buffer = create_host_buffer(gpu_, size, usage);
    };
    fit(buffers.vertices, vertex_bytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    fit(buffers.indices, index_bytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    const ImDrawData* data = ImGui::GetDrawData();
    auto* vertex = static_cast<ImDrawVert*>(buffers.vertices.mapped);
    auto* index = static_cast<ImDrawIdx*>(buffers.indices.mapped);
    for (int i = 0; i < data->CmdListsCount; ++i) {  // host-coherent: no flush
        const ImDrawList* list = data->CmdLists[i];
        std::memcpy(vertex, list->VtxBuffer.Data, size_t(list->VtxBuffer.Size) * sizeof *vertex);
        std::memcpy(index, list->IdxBuffer.Data, size_t(list->IdxBuffer.Size) * sizeof *index);
        vertex += list->VtxBuffer.Size;
        index += list->IdxBuffer.Size;
    }
}
// [/overlay-upload]

void Overlay::record(VkCommandBuffer cmd, uint32_t slot, VkImageView target, VkExtent2D extent) {
    ImGui::SetCurrentContext(imgui_);
    const ImDrawData* data = ImGui::GetDrawData();
    if (!data || data->TotalVtxCount == 0) return;
    // [overlay-begin]
    SlotBuffers& buffers = slots_[slot];
    upload(buffers, VkDeviceSize(data->TotalVtxCount) * sizeof(ImDrawVert),
           VkDeviceSize(data->TotalIdxCount) * sizeof(ImDrawIdx));

    begin_colour_rendering(cmd, target, extent, VK_ATTACHMENT_LOAD_OP_LOAD);  // over the frame
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0, nullptr);
    set_viewport_and_scissor(cmd, extent);
    const Push push{{2.0f / data->DisplaySize.x, 2.0f / data->DisplaySize.y},
                    {-1.0f - data->DisplayPos.x * 2.0f / data->DisplaySize.x,
                     -1.0f - data->DisplayPos.y * 2.0f / data->DisplaySize.y}};
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
    // [/overlay-begin]
    // [overlay-commands]
    const VkBuffer vertices = buffers.vertices.buffer;
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
    vkCmdBindIndexBuffer(cmd, buffers.indices.buffer, 0,
                         sizeof(ImDrawIdx) == 2 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32);
    // Each command: its scissor (the widget's clip rectangle, within the
    // target), then its triangles, offset by the lists before it.
    uint32_t first_index = 0;
    int32_t first_vertex = 0;
    for (int i = 0; i < data->CmdListsCount; ++i) {
        const ImDrawList* list = data->CmdLists[i];
        for (const ImDrawCmd& draw : list->CmdBuffer) {
            const float x0 = std::max(draw.ClipRect.x - data->DisplayPos.x, 0.0f);
            const float y0 = std::max(draw.ClipRect.y - data->DisplayPos.y, 0.0f);
            const float x1 = std::min(draw.ClipRect.z - data->DisplayPos.x, float(extent.width));
            const float y1 = std::min(draw.ClipRect.w - data->DisplayPos.y, float(extent.height));
            if (draw.UserCallback || x1 <= x0 || y1 <= y0) continue;  // no callbacks are used
            const VkRect2D scissor{{int32_t(x0), int32_t(y0)},
                                   {uint32_t(x1 - x0), uint32_t(y1 - y0)}};
            vkCmdSetScissor(cmd, 0, 1, &scissor);
            vkCmdDrawIndexed(cmd, draw.ElemCount, 1, first_index + draw.IdxOffset,
                             first_vertex + int32_t(draw.VtxOffset), 0);
        }
        first_index += uint32_t(list->IdxBuffer.Size);
        first_vertex += list->VtxBuffer.Size;
    }
    vkCmdEndRendering(cmd);
    // [/overlay-commands]
}

}  // namespace detail
}  // namespace vkt
#endif  // VKT_HAVE_IMGUI
