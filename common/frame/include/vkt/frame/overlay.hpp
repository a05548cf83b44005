#pragma once
// The on-screen overlay, taught in chapter 21: a small panel of a chapter's
// settings that the reader changes live with the mouse. Dear ImGui lays the
// widgets out; the runner draws them with a pipeline of its own
// (common/frame/src/overlay.cpp) over the finished frame. In an open-ended
// window run (no --frames); headless, offscreen and scripted pictures show
// it only when --overlay on asks (chapter 21's overlay golden test).

#include <span>
#include <string>

namespace vkt {

// What a chapter puts in its panel (Renderer::overlay), each widget bound to
// a value the chapter owns. Each returns true in the frame the reader changed
// it; the runner also says so on standard error ("overlay: Samples = 4"),
// which is what the window tests wait for.
class OverlayPanel {
public:
    virtual ~OverlayPanel() = default;
    virtual bool checkbox(const char* label, bool& value) = 0;
    virtual bool slider(const char* label, float& value, float min, float max) = 0;
    // One of `names`, as a row of radio buttons; index is the chosen one.
    virtual bool choice(const char* label, int& index, std::span<const char* const> names) = 0;
    virtual void text(const std::string& line) = 0;
};

// Whether this build has the overlay (Dear ImGui was found when it was configured).
bool overlay_available();

}  // namespace vkt
