#version 450
// Chapter 29's scene, drawn by the graphics queue into the HDR image: a dusk
// gradient with stars and --lamps bright discs on slow orbits, far brighter
// than white (radiance up to 24), so that chapter 23's bloom has light to
// spread. Each
// pixel adds up every lamp: --lamps sets how much graphics work a frame has.
layout(push_constant) uniform Scene {
    vec2 size;    // the image, in pixels
    float time;   // seconds: the frame index / 60
    uint lamps;   // lamp 0 stands still in the middle; the others orbit
} scene;

layout(location = 0) out vec4 radiance;

// [lamps]
const vec3 sky_top = vec3(0.02, 0.03, 0.08);
const vec3 sky_bottom = vec3(0.10, 0.05, 0.12);
const float lamp_radius = 0.04;  // of the image's height
const float star = 0.6;          // a star's radiance

void main() {
    vec2 p = (gl_FragCoord.xy - 0.5 * scene.size) / scene.size.y;  // height 1, centre 0
    vec3 sum = mix(sky_top, sky_bottom, gl_FragCoord.y / scene.size.y);
    // Stars: single pixels, about one in 300, picked by an integer hash of
    // the pixel (the same on every device): sharp points that a blurred or
    // shifted picture would not keep.
    uvec2 q = uvec2(gl_FragCoord.xy);
    uint h = (q.x * 73856093u) ^ (q.y * 19349663u);
    h = (h ^ (h >> 13u)) * 0x5bd1e995u;
    h ^= h >> 15u;
    if (h % 300u == 7u) sum += vec3(star);
    for (uint i = 0u; i < scene.lamps; ++i) {
        float k = float(i);
        // Lamp i: an ellipse of its own, at its own speed; its colour from
        // three phases of one cosine; its brightness 6 to 24.
        vec2 centre = i == 0u ? vec2(0.0)
                              : vec2(0.8 * sin(0.37 * k + scene.time * (0.2 + 0.013 * k)),
                                     0.4 * cos(0.71 * k + scene.time * (0.3 + 0.007 * k)));
        vec3 colour = 0.5 + 0.5 * cos(6.2832 * (0.13 * k + vec3(0.0, 0.33, 0.67)));
        float brightness = i == 0u ? 16.0 : 6.0 + 18.0 * fract(0.618 * k);
        // Coverage of the pixel by the disc, 1 inside, 0 outside, a pixel's
        // ramp at the rim.
        float rim = (lamp_radius - length(p - centre)) * scene.size.y;
        sum += clamp(rim + 0.5, 0.0, 1.0) * brightness * (i == 0u ? vec3(1.0, 0.8, 0.5) : colour);
    }
    radiance = vec4(sum, 1.0);
}
// [/lamps]
