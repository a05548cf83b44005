// Chapter 23: glTF's metallic-roughness BRDF, the uniform sky integrated by
// fixed samples, and the ACES tone curve. common/scene/include/vkt/scene/pbr.hpp
// is the same mathematics in C++, line for line: --verify compares the two.
const float PI = 3.14159265358979;

// [brdf]
// GGX (Trowbridge-Reitz) normal distribution, alpha = roughness^2.
float distribution_ggx(float n_dot_h, float alpha) {
    float a2 = alpha * alpha;
    float d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

// Smith's height-correlated masking-shadowing with the BRDF's 1 / (4 n.l n.v):
// V = G / (4 n.l n.v).
float visibility_smith(float n_dot_l, float n_dot_v, float alpha) {
    float a2 = alpha * alpha;
    float gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
    float gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
    float sum = gv + gl;
    return sum > 0.0 ? 0.5 / sum : 0.0;
}

// Schlick's Fresnel: f0 at normal incidence, 1 at grazing.
vec3 fresnel_schlick(vec3 f0, float v_dot_h) {
    float m = 1.0 - clamp(v_dot_h, 0.0, 1.0);
    return f0 + (1.0 - f0) * (m * m * m * m * m);
}

struct Material {
    vec3 base_colour;  // linear
    float metallic;
    float roughness;   // perceptual: alpha = roughness^2
};

vec3 f0_of(Material m) { return mix(vec3(0.04), m.base_colour, m.metallic); }
vec3 diffuse_of(Material m) { return m.base_colour * (1.0 - m.metallic); }

// The BRDF times n.l: what one unit of radiance from l sends towards v.
vec3 brdf_cos(vec3 n, vec3 v, vec3 l, Material m) {
    float n_dot_l = dot(n, l), n_dot_v = max(dot(n, v), 1e-4);
    if (n_dot_l <= 0.0) return vec3(0.0);
    vec3 h = normalize(v + l);
    float alpha = max(m.roughness * m.roughness, 1e-3);
    vec3 f = fresnel_schlick(f0_of(m), dot(v, h));
    vec3 diffuse = (1.0 - f) * diffuse_of(m) / PI;
    vec3 specular = f * distribution_ggx(max(dot(n, h), 0.0), alpha) *
                    visibility_smith(n_dot_l, n_dot_v, alpha);
    return (diffuse + specular) * n_dot_l;
}
// [/brdf]

vec2 hammersley(uint i, uint count) {
    return vec2((float(i) + 0.5) / float(count), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
}

// A frame around n whose first axis lies towards v.
mat3 frame_towards(vec3 n, vec3 v) {
    vec3 t = v - n * dot(n, v);
    if (dot(t, t) < 1e-8) t = abs(n.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0);
    t = normalize(t - n * dot(n, t));
    return mat3(t, cross(n, t), n);
}

// [environment]
// Uniform radiance `sky` from every direction: the hemisphere's integral of
// brdf_cos, by `count` fixed samples per lobe. Diffuse: cosine-distributed
// directions, each weighing (1 - F) c. Specular: GGX half vectors mirrored
// into l, each weighing 4 F V n.l v.h / n.h.
vec3 environment(vec3 n, vec3 v, Material m, vec3 sky, uint count) {
    if (count == 0u || sky == vec3(0.0)) return vec3(0.0);
    mat3 frame = frame_towards(n, v);
    float n_dot_v = max(dot(n, v), 1e-4);
    float alpha = max(m.roughness * m.roughness, 1e-3);
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < count; ++i) {
        vec2 u = hammersley(i, count);
        float phi = 2.0 * PI * u.y;
        float r = sqrt(u.x);
        vec3 l = frame * vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
        vec3 hd = normalize(v + l);
        sum += (1.0 - fresnel_schlick(f0_of(m), dot(v, hd))) * diffuse_of(m);
        float cos_h = sqrt((1.0 - u.x) / (1.0 + (alpha * alpha - 1.0) * u.x));
        float sin_h = sqrt(max(0.0, 1.0 - cos_h * cos_h));
        vec3 h = frame * vec3(sin_h * cos(phi), sin_h * sin(phi), cos_h);
        float v_dot_h = dot(v, h);
        vec3 ls = 2.0 * v_dot_h * h - v;
        float n_dot_l = dot(n, ls);
        if (n_dot_l > 0.0 && v_dot_h > 0.0)
            sum += fresnel_schlick(f0_of(m), v_dot_h) * visibility_smith(n_dot_l, n_dot_v, alpha) *
                   (4.0 * n_dot_l * v_dot_h / cos_h);
    }
    return sky * sum / float(count);
}
// [/environment]

// [split-sum-lut]
// The split sum's second factor, for the view at n.v and a roughness: the
// specular lobe's integral of F V n.l / pdf with Schlick's F written as
// F0 (1 - Fc) + Fc, Fc = (1 - v.h)^5, so that F0 comes out of it:
// F0 A + B is the share of the light the lobe reflects (GGX half vectors,
// each weighing 4 V n.l v.h / n.h, as environment() above).
vec2 split_sum_lut(float n_dot_v, float roughness, uint count) {
    vec3 v = vec3(sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);  // n = (0, 0, 1)
    float alpha = max(roughness * roughness, 1e-3);
    vec2 sum = vec2(0.0);
    for (uint i = 0u; i < count; ++i) {
        vec2 u = hammersley(i, count);
        float phi = 2.0 * PI * u.y;
        float cos_h = sqrt((1.0 - u.x) / (1.0 + (alpha * alpha - 1.0) * u.x));
        float sin_h = sqrt(max(0.0, 1.0 - cos_h * cos_h));
        vec3 h = vec3(sin_h * cos(phi), sin_h * sin(phi), cos_h);
        float v_dot_h = dot(v, h);
        float n_dot_l = 2.0 * v_dot_h * cos_h - n_dot_v;  // l = 2 (v.h) h - v
        if (n_dot_l <= 0.0 || v_dot_h <= 0.0) continue;
        float g = visibility_smith(n_dot_l, n_dot_v, alpha) * (4.0 * n_dot_l * v_dot_h / cos_h);
        float fc = pow(1.0 - v_dot_h, 5.0);
        sum += vec2(1.0 - fc, fc) * g;
    }
    return sum / float(count);
}
// [/split-sum-lut]

// [aces]
// Krzysztof Narkowicz's fit of the ACES filmic curve (2016-01-06): fitted to
// luminance, applied here to each channel (the page says what that costs).
vec3 aces_narkowicz(vec3 x) {
    x = max(x, vec3(0.0));
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
// [/aces]
