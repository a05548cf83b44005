#version 450
// Chapter 23's bloom, going down: each texel of the next smaller level is the
// average of four bilinear taps of the level above (4x4 of its texels).
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D source;           // the level above, or the HDR image
layout(set = 0, binding = 1, rgba16f) uniform image2D target;    // this level

// [bloom-down]
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(target)))) return;
    vec2 uv = (vec2(p) + 0.5) / vec2(imageSize(target));
    vec2 texel = 1.0 / vec2(textureSize(source, 0));
    vec3 sum = texture(source, uv + texel * vec2(-1.0, -1.0)).rgb +
               texture(source, uv + texel * vec2(1.0, -1.0)).rgb +
               texture(source, uv + texel * vec2(-1.0, 1.0)).rgb +
               texture(source, uv + texel * vec2(1.0, 1.0)).rgb;
    imageStore(target, p, vec4(0.25 * sum, 1.0));
}
// [/bloom-down]
