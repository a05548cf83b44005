#version 450
// Chapter 20: the compute rasterisers' pixel buffer onto the colour target,
// one invocation per pixel, in place of a fill and a copy. Each word is the
// pixel as the target stores it (raster.comp): its four bytes, lowest first,
// are the target's bytes in memory order, sRGB-encoded already. The target
// is _SRGB, which few devices can store to; the runner's storage view of it
// is the _UNORM format with the same bytes, through which a byte b goes in
// as b / 255 and lands as b again, unchanged.

// [resolve]
layout(local_size_x = 16, local_size_y = 16) in;
// The storage view's components in memory order: R, G, B, A, or B, G, R, A.
layout(constant_id = 0) const bool BGRA = false;
layout(std430, set = 0, binding = 0) buffer Pixels { uint pixels[]; };
// No format qualifier: the view is R8G8B8A8_UNORM or B8G8R8A8_UNORM
// (shaderStorageImageWriteWithoutFormat).
layout(set = 0, binding = 1) uniform writeonly image2D target;
layout(push_constant) uniform Push {
    uvec2 size;       // the target in pixels
    uint background;  // the word every pixel starts the next frame with
} push;

void main() {
    const uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= push.size.x || p.y >= push.size.y) return;
    const uint at = p.y * push.size.x + p.x;
    // Byte 0 of the word in .x, byte 3 in .w: the bytes in memory order.
    // imageStore takes components (r, g, b, a), which a BGRA view stores
    // as b, g, r, a: so there byte 0 goes in as the blue component.
    const vec4 bytes = unpackUnorm4x8(pixels[at]);
    imageStore(target, ivec2(p), BGRA ? bytes.zyxw : bytes);
    pixels[at] = push.background;
}
// [/resolve]
