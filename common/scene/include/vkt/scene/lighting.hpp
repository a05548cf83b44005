#pragma once
// The lighting model of chapter 12 on the CPU: ambient, Lambert diffuse,
// Blinn-Phong specular, and point lights whose light falls off with distance
// in one of two ways (the classic 1 / (c + l d + q d^2), or an inverse square
// that a window brings to exactly zero at the light's radius). The tests use it
// as the reference for the shaders, and the deferred chapters (16, 17) check
// their lighting passes against it.
//
// The GLSL twin is shaders/common/lighting.glsl: the SAME formulas, line for
// line. Change one, change the other (tests/unit/test_lighting.cpp and the
// chapter 12 pixel tests notice when they differ).

#include <glm/glm.hpp>

#include <cstddef>
#include <span>

namespace vkt {

// One point light, laid out as the shaders' `PointLight` struct in a std140
// or std430 block: two 16-byte rows, 32 bytes, the same in both layouts (a
// vec3 is 16-byte aligned and a float fills its fourth word).
struct PointLight {
    glm::vec3 position{0.0f};  // offset 0: world space
    float radius = 10.0f;      // offset 12: the windowed falloff is 0 from here on
    glm::vec3 colour{1.0f};    // offset 16: linear RGB
    float intensity = 1.0f;    // offset 28: multiplies colour
};
static_assert(sizeof(PointLight) == 32 && offsetof(PointLight, radius) == 12);
static_assert(offsetof(PointLight, colour) == 16 && offsetof(PointLight, intensity) == 28);

// The classic attenuation's three coefficients (OpenGL 1.0's fixed-function
// point lights had exactly these).
struct Attenuation {
    float constant = 1.0f;
    float linear = 0.0f;
    float quadratic = 0.0f;
};

// 1 / (c + l d + q d^2). Never reaches zero: every light touches everything.
float attenuation_classic(float distance, const Attenuation& k);

// The windowed inverse square of Karis, "Real Shading in Unreal Engine 4"
// (SIGGRAPH 2013):  clamp(1 - (d/r)^4, 0, 1)^2 / (d^2 + 1).
// The 1/(d^2 + 1) is the physical inverse square, kept finite at d = 0; the
// window is 1 at the light, falls smoothly, and is exactly 0 (with a zero
// slope) at d = r and beyond, so a light can be skipped outside its radius.
float attenuation_windowed(float distance, float radius);

// Lambert's cosine law: max(dot(n, l), 0), n and l unit vectors (l points from
// the surface to the light). 0 for a light behind the surface.
float lambert(glm::vec3 normal, glm::vec3 to_light);

// Blinn-Phong: max(dot(n, h), 0)^shininess with h = normalize(l + v), the
// half vector between the directions to the light and to the viewer. 0 when
// the light is behind the surface (dot(n, l) <= 0), so back faces never shine.
float blinn_phong(glm::vec3 normal, glm::vec3 to_light, glm::vec3 to_viewer, float shininess);

// The matrix that carries normals: the inverse transpose of the upper 3x3 of
// the model matrix. Equal to that 3x3 (up to scale) only for rotations and
// uniform scales; the normalised result is what the shaders use.
glm::mat3 normal_matrix(const glm::mat4& model);

enum class Falloff : int { classic = 0, windowed = 1 };  // the shaders' `falloff` values

// Everything shade() needs besides the surface and the lights.
struct LightingParams {
    glm::vec3 ambient{0.03f};  // light that comes from everywhere, times albedo
    Falloff falloff = Falloff::windowed;
    Attenuation classic{};    // used when falloff == classic
    float specular = 0.5f;    // strength of the (white) specular highlight
    float shininess = 32.0f;  // Blinn-Phong exponent: larger, smaller highlight
};

// One light's contribution at a surface point: attenuation times the light's
// colour and intensity, times (albedo * lambert + specular * blinn_phong).
// n and v are unit vectors (the normal, and the direction to the viewer).
glm::vec3 shade_point_light(glm::vec3 position, glm::vec3 n, glm::vec3 v, glm::vec3 albedo,
                            const PointLight& light, const LightingParams& params);

// The colour of a surface point in linear RGB: ambient * albedo plus every
// light's shade_point_light. normal need not be unit length.
glm::vec3 shade(glm::vec3 position, glm::vec3 normal, glm::vec3 albedo, glm::vec3 view_pos,
                std::span<const PointLight> lights, const LightingParams& params = {});

}  // namespace vkt
