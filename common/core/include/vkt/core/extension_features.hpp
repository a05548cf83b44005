#pragma once
// Feature structs of device extensions, as chapters 24-26 ask for them (ray
// queries, acceleration structures, the ray-tracing pipeline, mesh shaders):
// a chapter links the structs into DeviceRequirements::extension_features,
// the members it needs set to VK_TRUE. A device that offers an extension may
// still lack one of its features (VK_EXT_mesh_shader with meshShader but not
// taskShader), and vkCreateDevice would then fail with
// VK_ERROR_FEATURE_NOT_PRESENT, naming nothing. Device selection asks first,
// with this, so that the reader reads which feature is missing.

#include "vkt/core/check.hpp"
#include "vkt/core/hidden_names.hpp"

#include <string>

namespace vkt {

// "" when the device has every feature that the chain `wanted` sets to
// VK_TRUE, else "lacks the taskShader feature of VK_EXT_mesh_shader". Ask only
// once the device is known to offer the structs' extensions. A struct of a
// kind this file does not list throws Error: the table in
// extension_features.cpp needs its members first.
std::string extension_feature_shortfall(VkPhysicalDevice device, const void* wanted,
                                        const HiddenNames& hidden = {});

}  // namespace vkt
