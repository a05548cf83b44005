// Chapter 23's surface, as both scene shaders read it (scene.frag under the
// uniform sky, scene_ibl.frag under the environment): the material's five
// textures (set 1), what the vertex shader hands on, and the normal map.
layout(set = 1, binding = 0) uniform sampler2D base_colour_map;         // sRGB
layout(set = 1, binding = 1) uniform sampler2D metallic_roughness_map;  // G roughness, B metallic
layout(set = 1, binding = 2) uniform sampler2D normal_map;              // tangent space
layout(set = 1, binding = 3) uniform sampler2D occlusion_map;           // R
layout(set = 1, binding = 4) uniform sampler2D emissive_map;            // sRGB

layout(location = 0) in vec3 world;
layout(location = 1) in vec3 world_normal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec4 world_tangent;

// [normal-map]
// The normal map's vector is in the surface's tangent frame: x along the
// texture's u, y up the image (where v decreases), z the interpolated normal. The frame is the
// file's TANGENT where it has one; else it is made here, per pixel, from how
// the position and the texture coordinates change across the screen.
vec3 shading_normal() {
    vec3 n = normalize(world_normal);
    if (draw.emissive.w == 0.0) return n;
    vec3 t, b;
    if (world_tangent.w != 0.0) {
        t = normalize(world_tangent.xyz - n * dot(n, world_tangent.xyz));
        b = cross(n, t) * world_tangent.w;
    } else {
        vec3 dp1 = dFdx(world), dp2 = dFdy(world);
        vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
        vec3 dp2perp = cross(dp2, n), dp1perp = cross(n, dp1);
        t = dp2perp * duv1.x + dp1perp * duv2.x;
        // [det-sign]
        // glTF's bitangent points up the image, where v decreases.
        b = -(dp2perp * duv1.y + dp1perp * duv2.y);
        // t and b are u's and v's gradients on the surface times det, so
        // det's sign must be kept. The formula, Christian Schueler's, was
        // written for OpenGL, whose window y runs up: there a front face has
        // det > 0. Vulkan's runs down, dFdy steps down the screen, and a
        // front face has det < 0:
        // without sign(det), T would point where u falls and B where v grows.
        float det = dot(n, cross(dp1, dp2));
        float det_sign = det < 0.0 ? -1.0 : 1.0;  // sign(det), but never 0
        float scale = det_sign * inversesqrt(max(max(dot(t, t), dot(b, b)), 1e-20));
        // [/det-sign]
        t *= scale;
        b *= scale;
    }
    // [normal-apply]
    vec3 m = texture(normal_map, uv).xyz * 2.0 - 1.0;
    m.xy *= draw.factors.z;  // the material's normal_scale
    return normalize(mat3(t, b, n) * m);
    // [/normal-apply]
}
// [/normal-map]

// The material at this pixel: the factors times the textures; the occlusion
// and the emitted radiance on the side.
Material surface_material(out float occlusion, out vec3 emitted) {
    // [material]
    vec4 base = texture(base_colour_map, uv) * draw.base_colour;
    vec4 mr = texture(metallic_roughness_map, uv);
    Material m;
    m.base_colour = base.rgb;
    m.metallic = clamp(mr.b * draw.factors.x, 0.0, 1.0);
    m.roughness = clamp(mr.g * draw.factors.y, 0.0, 1.0);
    occlusion = 1.0 + draw.factors.w * (texture(occlusion_map, uv).r - 1.0);
    emitted = texture(emissive_map, uv).rgb * draw.emissive.rgb;
    // [/material]
    return m;
}
