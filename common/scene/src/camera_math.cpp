#include "vkt/scene/camera_math.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace vkt {

glm::mat4 vulkan_perspective(float fovy_radians, float aspect, float z_near, float z_far) {
    glm::mat4 proj = glm::perspective(fovy_radians, aspect, z_near, z_far);
    proj[1][1] = -proj[1][1];  // world +y up on screen: framebuffer y points down
    return proj;
}

glm::mat4 transform(glm::vec3 translation, float angle_radians, glm::vec3 axis, glm::vec3 scale) {
    const glm::mat4 t = glm::translate(glm::mat4(1.0f), translation);
    const glm::mat4 r = glm::rotate(glm::mat4(1.0f), angle_radians, axis);
    const glm::mat4 s = glm::scale(glm::mat4(1.0f), scale);
    return t * r * s;  // applied right to left: scale, rotate, translate
}

glm::vec3 project_to_ndc(const glm::mat4& clip_from_world, glm::vec3 p) {
    const glm::vec4 clip = clip_from_world * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

}  // namespace vkt
