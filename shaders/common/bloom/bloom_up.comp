#version 450
// Chapter 23's bloom, coming back up: each level adds the level below it,
// spread by a 3x3 tent, to what it already holds.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D source;         // the level below (smaller)
layout(set = 0, binding = 1, rgba16f) uniform image2D target;  // this level: read, added to, written

// [bloom-up]
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(target)))) return;
    vec2 uv = (vec2(p) + 0.5) / vec2(imageSize(target));
    vec2 texel = 1.0 / vec2(textureSize(source, 0));
    vec3 sum = vec3(0.0);
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            sum += float((2 - abs(x)) * (2 - abs(y))) * texture(source, uv + texel * vec2(x, y)).rgb;
    imageStore(target, p, imageLoad(target, p) + vec4(sum / 16.0, 0.0));
}
// [/bloom-up]
