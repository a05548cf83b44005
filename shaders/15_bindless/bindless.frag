#version 460
#extension GL_EXT_nonuniform_qualifier : require

// [texture-array]
// Binding 0: one sampler for every texture (an immutable sampler, baked into
// the layout). Binding 1: a runtime-sized array of images: its length is not
// written here; the descriptor set has as many as the C++ code allocated.
layout(set = 0, binding = 0) uniform sampler shared_sampler;
layout(set = 0, binding = 1) uniform texture2D textures[];
// [/texture-array]

layout(push_constant) uniform Push {
    layout(offset = 80) uint resident_textures;  // slots 0 .. resident - 1 are written
} push;

layout(location = 0) in vec3 normal;
layout(location = 1) in vec2 uv;
layout(location = 2) flat in uint side_texture;
layout(location = 3) flat in uint top_texture;
layout(location = 4) in vec3 tint;
layout(location = 0) out vec4 target;

const vec3 to_light = normalize(vec3(0.4, 1.0, 0.3));
const float ambient = 0.3;

void main() {
    vec3 n = normalize(normal);
    // [sample]
    // Lids and sides have different textures, so the index differs between
    // fragments of ONE draw, and fragments of neighbouring draws may share a
    // subgroup: the index is not dynamically uniform. nonuniformEXT tells the
    // compiler so (it then handles each distinct index in a subgroup). A slot
    // not written yet (still "loading") falls back to slot 0, which always is.
    uint index = n.y > 0.7 ? top_texture : side_texture;
    if (index >= push.resident_textures) index = 0u;
    vec3 albedo = texture(sampler2D(textures[nonuniformEXT(index)], shared_sampler), uv).rgb;
    // [/sample]
    float lambert = max(dot(n, to_light), 0.0);
    target = vec4(albedo * tint * (ambient + (1.0 - ambient) * lambert), 1.0);
}
