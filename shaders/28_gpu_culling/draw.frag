#version 460
#extension GL_GOOGLE_include_directive : require

// Lambert under a sun and a quarter of ambient light (chapter 12's shapes).
// --view culled's occluded instances are one flat red, unlit: they are drawn
// with no depth test, in whatever order the cull appended them, and where
// two overlap the later one wins; one colour makes that order invisible.

#include "culling_data.glsl"

layout(location = 0) in vec3 world_normal;
layout(location = 1) in vec3 colour;
layout(location = 0) out vec4 target;

const vec3 to_light = normalize(vec3(0.4, 1.0, 0.3));
const float ambient = 0.25;

void main() {
    if (push.list == CULLED) {
        target = vec4(1.0, 0.05, 0.02, 1.0);
        return;
    }
    float lambert = max(dot(normalize(world_normal), to_light), 0.0);
    target = vec4(colour * (ambient + (1.0 - ambient) * lambert), 1.0);
}
