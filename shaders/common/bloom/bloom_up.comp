#version 450
// Chapter 23's bloom, coming back up: each level adds the level below it,
// spread by a tent of `radius` texels of that level, to what it already holds.
// Chapter 23 uses radius 1, a 3x3 tent; chapter 29's --bloom-radius widens it,
// a wider glow for (2 radius + 1)^2 taps a texel.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D source;         // the level below (smaller)
layout(set = 0, binding = 1, rgba16f) uniform image2D target;  // this level: read, added to, written
layout(push_constant) uniform Tent {
    int radius;  // 1: weights (1, 2, 1) by (1, 2, 1)
} tent;

// [bloom-up]
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(target)))) return;
    vec2 uv = (vec2(p) + 0.5) / vec2(imageSize(target));
    vec2 texel = 1.0 / vec2(textureSize(source, 0));
    int r = tent.radius;
    vec3 sum = vec3(0.0);
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x)
            sum += float((r + 1 - abs(x)) * (r + 1 - abs(y))) *
                   texture(source, uv + texel * vec2(x, y)).rgb;
    // The weights add up to (r + 1)^4 (16 for the 3x3 tent): the level's mean is kept.
    float total = float((r + 1) * (r + 1));
    imageStore(target, p, imageLoad(target, p) + vec4(sum / (total * total), 0.0));
}
// [/bloom-up]
