#pragma once
// Chapter 23's physically based shading on the CPU: glTF's metallic-roughness
// BRDF (Cook-Torrance with the GGX distribution, Smith's height-correlated
// masking-shadowing and Schlick's Fresnel, as glTF 2.0's appendix B writes
// it), the uniform environment the chapter integrates by a fixed set of
// samples, the split sum's BRDF table, and the ACES tone curve. shaders/23_materials/pbr.glsl is
// the same mathematics in GLSL, line for line; the chapter's --verify compares the two, and
// tests/unit/test_pbr.cpp checks the properties the page derives.

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>

namespace vkt::pbr {

inline constexpr float pi = std::numbers::pi_v<float>;

struct Material {
    glm::vec3 base_colour{1.0f};  // linear
    float metallic = 0.0f;
    float roughness = 1.0f;  // perceptual: alpha = roughness^2
};

// A directional light: `direction` points from the surface towards the light.
struct Light {
    glm::vec3 direction;
    glm::vec3 radiance;
};

// GGX (Trowbridge-Reitz) normal distribution, alpha = roughness^2.
inline float distribution_ggx(float n_dot_h, float alpha) {
    const float a2 = alpha * alpha;
    const float d = n_dot_h * n_dot_h * (a2 - 1.0f) + 1.0f;
    return a2 / (pi * d * d);
}

// Smith's height-correlated masking-shadowing, folded with the BRDF's
// 1 / (4 n.l n.v) into one visibility term V = G / (4 n.l n.v).
inline float visibility_smith(float n_dot_l, float n_dot_v, float alpha) {
    const float a2 = alpha * alpha;
    const float gv = n_dot_l * std::sqrt(n_dot_v * n_dot_v * (1.0f - a2) + a2);
    const float gl = n_dot_v * std::sqrt(n_dot_l * n_dot_l * (1.0f - a2) + a2);
    const float sum = gv + gl;
    return sum > 0.0f ? 0.5f / sum : 0.0f;
}

// Schlick's Fresnel: F0 at normal incidence, 1 at grazing.
inline glm::vec3 fresnel_schlick(glm::vec3 f0, float v_dot_h) {
    const float m = 1.0f - std::clamp(v_dot_h, 0.0f, 1.0f);
    return f0 + (glm::vec3(1.0f) - f0) * (m * m * m * m * m);
}

inline glm::vec3 f0_of(const Material& m) {
    return glm::mix(glm::vec3(0.04f), m.base_colour, m.metallic);
}
inline glm::vec3 diffuse_of(const Material& m) {
    return m.base_colour * (1.0f - m.metallic);
}

// The BRDF times n.l: what one unit of radiance arriving from `l` sends
// towards `v`. n, v and l are unit vectors.
inline glm::vec3 brdf_cos(glm::vec3 n, glm::vec3 v, glm::vec3 l, const Material& m) {
    const float n_dot_l = glm::dot(n, l), n_dot_v = std::max(glm::dot(n, v), 1e-4f);
    if (n_dot_l <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 h = glm::normalize(v + l);
    const float alpha = std::max(m.roughness * m.roughness, 1e-3f);
    const glm::vec3 f = fresnel_schlick(f0_of(m), glm::dot(v, h));
    const glm::vec3 diffuse = (glm::vec3(1.0f) - f) * diffuse_of(m) / pi;
    const glm::vec3 specular = f * distribution_ggx(std::max(glm::dot(n, h), 0.0f), alpha) *
                               visibility_smith(n_dot_l, n_dot_v, alpha);
    return (diffuse + specular) * n_dot_l;
}

// Point i of N of the Hammersley set: (i / N, i's bits reversed).
inline glm::vec2 hammersley(uint32_t i, uint32_t count) {
    uint32_t bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return {(float(i) + 0.5f) / float(count), float(bits) * 2.3283064365386963e-10f};
}

// A frame around n whose first axis lies towards v (any axis where v = n:
// then the BRDF is symmetric about n and the choice does not matter).
inline glm::mat3 frame_towards(glm::vec3 n, glm::vec3 v) {
    glm::vec3 t = v - n * glm::dot(n, v);
    if (glm::dot(t, t) < 1e-8f) t = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    t = glm::normalize(t - n * glm::dot(n, t));
    return glm::mat3(t, glm::cross(n, t), n);
}

// Uniform radiance `sky` from every direction, reflected towards v: the
// integral of brdf_cos over the hemisphere, estimated with `count` fixed
// samples for each lobe. The diffuse lobe is sampled by the cosine
// (pdf n.l / pi, so each sample weighs brdf_diffuse * pi); the specular
// lobe by GGX's half vectors (pdf D n.h / (4 v.h), so each weighs
// 4 F V n.l v.h / n.h).
inline glm::vec3 environment(glm::vec3 n, glm::vec3 v, const Material& m, glm::vec3 sky,
                             uint32_t count) {
    if (count == 0 || sky == glm::vec3(0.0f)) return glm::vec3(0.0f);
    const glm::mat3 frame = frame_towards(n, v);
    const float n_dot_v = std::max(glm::dot(n, v), 1e-4f);
    const float alpha = std::max(m.roughness * m.roughness, 1e-3f);
    glm::vec3 sum(0.0f);
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec2 u = hammersley(i, count);
        const float phi = 2.0f * pi * u.y;
        // Diffuse: a cosine-distributed direction.
        const float r = std::sqrt(u.x);
        const glm::vec3 l = frame * glm::vec3(r * std::cos(phi), r * std::sin(phi),
                                              std::sqrt(std::max(0.0f, 1.0f - u.x)));
        const glm::vec3 hd = glm::normalize(v + l);
        sum += (glm::vec3(1.0f) - fresnel_schlick(f0_of(m), glm::dot(v, hd))) * diffuse_of(m);
        // Specular: a GGX-distributed half vector, mirrored into l.
        const float cos_h = std::sqrt((1.0f - u.x) / (1.0f + (alpha * alpha - 1.0f) * u.x));
        const float sin_h = std::sqrt(std::max(0.0f, 1.0f - cos_h * cos_h));
        const glm::vec3 h = frame * glm::vec3(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
        const float v_dot_h = glm::dot(v, h);
        const glm::vec3 ls = 2.0f * v_dot_h * h - v;
        const float n_dot_l = glm::dot(n, ls);
        if (n_dot_l > 0.0f && v_dot_h > 0.0f)
            sum += fresnel_schlick(f0_of(m), v_dot_h) * visibility_smith(n_dot_l, n_dot_v, alpha) *
                   (4.0f * n_dot_l * v_dot_h / cos_h);
    }
    return sky * sum / float(count);
}

// The split sum's second factor (chapter 23's BRDF lookup table), for the
// view at n.v and a roughness: the specular lobe's integral of F V n.l / pdf
// with Schlick's F written as F0 (1 - Fc) + Fc, Fc = (1 - v.h)^5, so that
// F0 A + B is the share of the light the lobe reflects; `count` GGX half
// vectors, each weighing 4 V n.l v.h / n.h, as environment() above.
inline glm::vec2 split_sum_lut(float n_dot_v, float roughness, uint32_t count) {
    const glm::vec3 v(std::sqrt(1.0f - n_dot_v * n_dot_v), 0.0f, n_dot_v);  // n = (0, 0, 1)
    const float alpha = std::max(roughness * roughness, 1e-3f);
    glm::vec2 sum(0.0f);
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec2 u = hammersley(i, count);
        const float phi = 2.0f * pi * u.y;
        const float cos_h = std::sqrt((1.0f - u.x) / (1.0f + (alpha * alpha - 1.0f) * u.x));
        const float sin_h = std::sqrt(std::max(0.0f, 1.0f - cos_h * cos_h));
        const glm::vec3 h(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
        const float v_dot_h = glm::dot(v, h);
        const float n_dot_l = 2.0f * v_dot_h * cos_h - n_dot_v;  // l = 2 (v.h) h - v
        if (n_dot_l <= 0.0f || v_dot_h <= 0.0f) continue;
        const float g =
            visibility_smith(n_dot_l, n_dot_v, alpha) * (4.0f * n_dot_l * v_dot_h / cos_h);
        const float fc = std::pow(1.0f - v_dot_h, 5.0f);
        sum += glm::vec2(1.0f - fc, fc) * g;
    }
    return sum / float(count);
}

// The radiance leaving a surface point towards v: every light, and the sky.
inline glm::vec3 shade(glm::vec3 n, glm::vec3 v, const Material& m, std::span<const Light> lights,
                       glm::vec3 sky, uint32_t sky_samples) {
    glm::vec3 out = environment(n, v, m, sky, sky_samples);
    for (const Light& light : lights) out += light.radiance * brdf_cos(n, v, light.direction, m);
    return out;
}

// Krzysztof Narkowicz's fit of the ACES filmic curve (2015), for one channel
// of exposed linear radiance; 0..1 out.
inline float aces_narkowicz(float x) {
    x = std::max(x, 0.0f);
    return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

}  // namespace vkt::pbr
