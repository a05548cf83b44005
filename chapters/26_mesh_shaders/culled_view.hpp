#pragma once
// Chapter 26's --view culled: every meshlet is launched, and coloured by the
// task shader's verdict for the chapter's camera (kept, outside the frustum,
// facing away); the picture is drawn from a second camera, opposite the
// first across the model, since from the first a culled meshlet shows
// nothing. Its matrix goes in a small buffer: the push constants are full.

#include "vkt/frame/args.hpp"
#include "vkt/resources/compute.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace ch26 {

enum View : uint32_t { view_lit = 0, view_meshlets = 1, view_culled = 2 };  // push.view

inline View parse_view(const std::string& view) {
    return view == "meshlets" ? view_meshlets : view == "culled" ? view_culled : view_lit;
}

// The views that need the task shader's work, refused without it (exit 2).
inline void check_view(const vkt::Options& options) {
    const std::string& view = options.text("--view");
    if (options.text("--draw") == "indirect" && view != "lit")
        throw vkt::UsageError("--view " + view +
                              " needs --draw mesh: the indirect draw has no meshlets");
    if (view == "culled" && options.text("--cull") == "off")
        throw vkt::UsageError(
            "--view culled shows what the task shader's tests cull: it needs --cull on");
}

// Before the frame's draw: the second camera's matrix into `shown` (binding
// 5), once the last frame's mesh shaders are done reading it and the last
// frame's write is done (a write after a write needs the first made
// available, not only finished), and visible to this frame's mesh shaders.
inline void show_from(VkCommandBuffer cmd, VkBuffer shown, const glm::mat4& clip_from_world) {
    vkt::buffer_barrier(
        cmd, shown, VK_PIPELINE_STAGE_2_MESH_SHADER_BIT_EXT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
        VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
        VK_ACCESS_2_TRANSFER_WRITE_BIT);
    vkCmdUpdateBuffer(cmd, shown, 0, sizeof(clip_from_world), &clip_from_world);
    vkt::buffer_barrier(cmd, shown, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_MESH_SHADER_BIT_EXT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

}  // namespace ch26
