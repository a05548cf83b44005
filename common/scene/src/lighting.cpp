// The CPU twin of shaders/common/lighting.glsl: keep the formulas identical.
#include "vkt/scene/lighting.hpp"

#include <algorithm>
#include <cmath>

namespace vkt {

float attenuation_classic(float distance, const Attenuation& k) {
    return 1.0f / (k.constant + k.linear * distance + k.quadratic * distance * distance);
}

float attenuation_windowed(float distance, float radius) {
    const float ratio = distance / radius;
    const float window = std::clamp(1.0f - ratio * ratio * ratio * ratio, 0.0f, 1.0f);
    return window * window / (distance * distance + 1.0f);
}

float lambert(glm::vec3 normal, glm::vec3 to_light) {
    return std::max(glm::dot(normal, to_light), 0.0f);
}

float blinn_phong(glm::vec3 normal, glm::vec3 to_light, glm::vec3 to_viewer, float shininess) {
    if (glm::dot(normal, to_light) <= 0.0f) return 0.0f;
    const glm::vec3 half = glm::normalize(to_light + to_viewer);
    return std::pow(std::max(glm::dot(normal, half), 0.0f), shininess);
}

glm::mat3 normal_matrix(const glm::mat4& model) {
    return glm::transpose(glm::inverse(glm::mat3(model)));
}

glm::vec3 shade_point_light(glm::vec3 position, glm::vec3 n, glm::vec3 v, glm::vec3 albedo,
                            const PointLight& light, const LightingParams& params) {
    const glm::vec3 to_light = light.position - position;
    const float distance = glm::length(to_light);
    // A light exactly at the surface has no direction: max() keeps l finite.
    const glm::vec3 l = to_light / std::max(distance, 1e-6f);
    const float attenuation = params.falloff == Falloff::windowed
                                  ? attenuation_windowed(distance, light.radius)
                                  : attenuation_classic(distance, params.classic);
    const glm::vec3 diffuse = albedo * lambert(n, l);
    const glm::vec3 specular = glm::vec3(params.specular * blinn_phong(n, l, v, params.shininess));
    return attenuation * light.intensity * light.colour * (diffuse + specular);
}

glm::vec3 shade(glm::vec3 position, glm::vec3 normal, glm::vec3 albedo, glm::vec3 view_pos,
                std::span<const PointLight> lights, const LightingParams& params) {
    const glm::vec3 n = glm::normalize(normal);
    const glm::vec3 v = glm::normalize(view_pos - position);
    glm::vec3 colour = params.ambient * albedo;
    for (const PointLight& light : lights)
        colour += shade_point_light(position, n, v, albedo, light, params);
    return colour;
}

}  // namespace vkt
