#version 450
// Chapter 21's colours: flat, except on the striped quad, whose stripes are
// decided here, per fragment shader invocation. Multisampling smooths the
// edges of triangles but runs this shader once per pixel, so stripes 1.25
// pixels wide still alias, unless sample shading runs it per sample.

layout(location = 0) in vec3 colour;
layout(location = 1) in float striped;

layout(location = 0) out vec4 frag_colour;

void main() {
    // [stripes]
    // Slanted stripes 1.25 pixels wide, light and dark, a hard edge inside
    // the triangle. They follow gl_FragCoord: the pixel's centre, or with
    // sample shading the position of this invocation's sample (the one input
    // Vulkan promises to move; others may still be taken at the centre).
    const float across = dot(gl_FragCoord.xy, vec2(0.92, 0.39)) / 2.5;
    const float light = striped > 0.5 ? step(fract(across), 0.5) : 1.0;
    frag_colour = vec4(colour * mix(0.25, 1.0, light), 1.0);
    // [/stripes]
}
