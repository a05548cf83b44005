#version 460

layout(location = 0) in vec3 world_normal;
layout(location = 1) in vec3 colour;
layout(location = 0) out vec4 target;

// [shade]
// A sun from above and a little behind the camera's start, and a quarter of
// ambient light: lit = colour * (ambient + (1 - ambient) * max(n . l, 0)).
const vec3 to_light = normalize(vec3(0.4, 1.0, 0.3));
const float ambient = 0.25;

void main() {
    float lambert = max(dot(normalize(world_normal), to_light), 0.0);
    target = vec4(colour * (ambient + (1.0 - ambient) * lambert), 1.0);
}
// [/shade]
