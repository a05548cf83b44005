#pragma once
// Chapter 02's device checks, as the tests play them: names a run treats as
// missing on every device.

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace vkt {

// Names treated as missing whatever the device says: features and extensions
// as the Vulkan structs and extension strings spell them (bufferDeviceAddress,
// VK_KHR_swapchain), and, for a chapter that checks a property itself, the
// flag's name. Lavapipe has nearly everything, so this is how the tests see
// the message a reader with a smaller device would get; the harness fills it
// from VKT_HIDE_FEATURES, and nothing in core reads the environment.
struct HiddenNames {
    std::vector<std::string> names;
    bool hides(std::string_view name) const {
        return std::find(names.begin(), names.end(), name) != names.end();
    }
};

}  // namespace vkt
