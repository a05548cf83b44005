#version 450
// Chapter 23's bloom, going down: each texel of the next smaller level is the
// average of four bilinear taps of the level above (4x4 of its texels). With
// `karis` (--bloom-average karis, the first halving only) the four taps are
// weighed by 1 / (1 + luma) each, Karis's average: a lone pixel far brighter
// than its neighbours can no longer outweigh them.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D source;           // the level above, or the HDR image
layout(set = 0, binding = 1, rgba16f) uniform image2D target;    // this level
layout(constant_id = 0) const bool karis = false;

// [bloom-down]
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(target)))) return;
    vec2 uv = (vec2(p) + 0.5) / vec2(imageSize(target));
    vec2 texel = 1.0 / vec2(textureSize(source, 0));
    // Each tap sits on the corner of four texels: their mean, a 2x2 block.
    vec3 a = texture(source, uv + texel * vec2(-1.0, -1.0)).rgb;
    vec3 b = texture(source, uv + texel * vec2(1.0, -1.0)).rgb;
    vec3 c = texture(source, uv + texel * vec2(-1.0, 1.0)).rgb;
    vec3 d = texture(source, uv + texel * vec2(1.0, 1.0)).rgb;
    if (!karis) {
        imageStore(target, p, vec4(0.25 * (a + b + c + d), 1.0));
        return;
    }
    // A block's weight falls as its luma (Rec. 709) rises: a block of luma
    // L brings L / (1 + L) < 1 of it, however bright its one pixel.
    const vec3 rec709 = vec3(0.2126, 0.7152, 0.0722);
    vec4 w = 1.0 / (1.0 + vec4(dot(a, rec709), dot(b, rec709), dot(c, rec709), dot(d, rec709)));
    vec3 sum = w.x * a + w.y * b + w.z * c + w.w * d;
    imageStore(target, p, vec4(sum / (w.x + w.y + w.z + w.w), 1.0));
}
// [/bloom-down]
