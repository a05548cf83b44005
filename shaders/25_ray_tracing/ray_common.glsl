// Chapter 25: what the ray-tracing shaders share.

// [payload]
// What a ray carries: in, how deep in the recursion it was traced (the ray
// generation shader's rays are depth 1); out, the colour it found.
struct Hit {
    vec3 colour;
    uint depth;
};
// [/payload]

// The camera, the light and the recursion budget, one push-constant block
// for every stage (main.cpp's Push).
layout(push_constant) uniform Push {
    vec4 eye;
    vec4 right;    // half the image's width at distance 1, in world units
    vec4 up;       // half its height
    vec4 forward;
    vec4 light;    // the direction the light travels
    uint bounces;  // reflections after the first hit
    uint max_depth;
} pc;
