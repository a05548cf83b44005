// The lighting model of chapter 12, for any shader that #includes it (the
// build passes -I shaders/common). The CPU twin is common/src/lighting.cpp
// (vkt/lighting.hpp): the SAME formulas, line for line; the unit tests and
// chapter 12's pixel tests compare the two.
#ifndef VKT_LIGHTING_GLSL
#define VKT_LIGHTING_GLSL

// [point-light]
// One point light: 32 bytes, the same in std140 and std430 (vkt::PointLight).
struct PointLight {
    vec3 position;    // offset 0, world space
    float radius;     // offset 12: the windowed falloff is 0 from here on
    vec3 colour;      // offset 16, linear RGB
    float intensity;  // offset 28
};
// [/point-light]

const int FALLOFF_CLASSIC = 0;
const int FALLOFF_WINDOWED = 1;

// [attenuation]
// Classic: 1 / (c + l d + q d^2), k = (c, l, q). Never reaches zero.
float attenuation_classic(float d, vec3 k) {
    return 1.0 / (k.x + k.y * d + k.z * d * d);
}

// Windowed inverse square (Karis 2013): the inverse square 1 / (d^2 + 1),
// times a window that is 1 at the light and exactly 0 from d = radius on.
float attenuation_windowed(float d, float radius) {
    float ratio = d / radius;
    float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window / (d * d + 1.0);
}
// [/attenuation]

// [diffuse-specular]
// Lambert: the cosine of the angle between the normal and the light.
float lambert(vec3 n, vec3 l) {
    return max(dot(n, l), 0.0);
}

// Blinn-Phong: how close the half vector between light and viewer is to the
// normal. No highlight from a light behind the surface.
float blinn_phong(vec3 n, vec3 l, vec3 v, float shininess) {
    if (dot(n, l) <= 0.0) return 0.0;
    vec3 h = normalize(l + v);
    return pow(max(dot(n, h), 0.0), shininess);
}
// [/diffuse-specular]

// [shade-point-light]
// One light's contribution at a surface point; n and v are unit vectors.
vec3 shade_point_light(vec3 position, vec3 n, vec3 v, vec3 albedo, PointLight light,
                       int falloff, vec3 classic, float specular, float shininess) {
    vec3 to_light = light.position - position;
    float d = length(to_light);
    vec3 l = to_light / max(d, 1e-6);
    float attenuation = falloff == FALLOFF_WINDOWED ? attenuation_windowed(d, light.radius)
                                                    : attenuation_classic(d, classic);
    vec3 diffuse = albedo * lambert(n, l);
    vec3 highlight = vec3(specular * blinn_phong(n, l, v, shininess));
    return attenuation * light.intensity * light.colour * (diffuse + highlight);
}
// [/shade-point-light]

#endif
