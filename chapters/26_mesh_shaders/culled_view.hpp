#pragma once
// Chapter 26's --view culled: every meshlet is launched, and coloured by the
// task shader's verdict for the chapter's camera (kept, outside the frustum,
// facing away); the picture is drawn from a second camera, opposite the
// first across the model, since from the first a culled meshlet shows
// nothing. Its matrix goes in a small host-visible buffer, one per frame in
// flight as the counters are: the push constants are full.

#include "vkt/frame/args.hpp"

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

// The second camera's matrix into this frame's slot of `shown` (binding 5),
// as record() zeroes the counters: the runner has waited for the frame that
// last read this slot, and host writes before the submit are visible to the
// GPU, so no barrier is needed.
inline void show_from(void* shown_mapped, uint32_t slot, const glm::mat4& clip_from_world) {
    static_cast<glm::mat4*>(shown_mapped)[slot] = clip_from_world;
}

}  // namespace ch26
