// Chapter 20: what the compute passes and the line shaders share.

// [push]
// One block for every stage: the view, the projection and the counts.
layout(push_constant) uniform Push {
    vec2 to_clip;       // projected units to clip space (x, y)
    float eye;          // the eye distance d on each last axis
    uint orthographic;  // 1: drop the coordinates, no perspective
    uint object_count;  // the transform pass: objects in the scene
    uint line_count;    // the compute rasteriser: lines in the scene
    uvec2 size;         // the compute rasteriser: the target in pixels
} push;
// [/push]

// [projected]
// One vertex after the transform pass, 16 bytes: where it lands in clip
// space, its colour (R, G, B, A bytes, lowest first; alpha 0 marks a vertex
// at or behind the eye) and its depth t in -1..1 along the last axis.
struct Projected {
    vec2 xy;
    uint colour;
    float depth;
};
// [/projected]

// The colour of chapter 18: depth t = -1 (far along the last axis) blue,
// t = 1 (near the eye) orange; linear values the _SRGB target encodes.
vec3 depth_colour(float t) {
    t = clamp(0.5 + 0.5 * t, 0.0, 1.0);
    return vec3(0.10 + 0.90 * t, 0.30 + 0.15 * t, 1.00 - 0.90 * t);
}
