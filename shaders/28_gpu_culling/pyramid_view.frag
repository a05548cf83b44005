#version 460
#extension GL_GOOGLE_include_directive : require

// --view pyramid: level show_level of the depth pyramid, each texel over the
// pixels it covers. Reversed depth is small far away (about near / distance),
// so the grey is its fourth root: near white, far dark, the sky black.

#include "culling_data.glsl"

layout(set = 0, binding = 5) uniform sampler2D pyramid;
layout(location = 0) out vec4 target;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy) >> (push.show_level + 1);
    float depth = texelFetch(pyramid, texel, int(push.show_level)).r;
    target = vec4(vec3(sqrt(sqrt(depth))), 1.0);
}
