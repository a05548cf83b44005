#pragma once
// The matrices of chapter 08: object transforms (scale, then rotate, then
// translate) and a perspective projection that matches Vulkan's clip space
// (depth 0 at the near plane to 1 at the far plane; y down in framebuffer
// space). The build defines GLM_FORCE_DEPTH_ZERO_TO_ONE and GLM_FORCE_RADIANS;
// see the conventions appendix.

#include <glm/glm.hpp>

namespace vkt {

// glm::perspective (right-handed, looking down -z, depth 0..1) with
// proj[1][1] negated, so that +y in the world goes up on the screen although
// Vulkan's framebuffer y points down. With it, a triangle that the viewer sees
// counter-clockwise is counter-clockwise by Vulkan's rule too: keep
// VK_FRONT_FACE_COUNTER_CLOCKWISE for meshes wound counter-clockwise seen from
// outside (chapter 07's cubes, glTF).
glm::mat4 vulkan_perspective(float fovy_radians, float aspect, float z_near, float z_far);

// The world-from-object matrix T * R * S: scale by `scale`, rotate by
// `angle_radians` about `axis` (a unit vector), then translate by
// `translation`.
glm::mat4 transform(glm::vec3 translation, float angle_radians, glm::vec3 axis, glm::vec3 scale);

// Where a world point lands: clip = clip_from_world * (p, 1), then the
// perspective divide. Returns (x, y, depth) in normalised device coordinates.
glm::vec3 project_to_ndc(const glm::mat4& clip_from_world, glm::vec3 p);

}  // namespace vkt
