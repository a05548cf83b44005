#version 460

// Lambert under a sun and a quarter of ambient light (chapter 12's shapes).
layout(location = 0) in vec3 world_normal;
layout(location = 1) in vec3 colour;
layout(location = 0) out vec4 target;

const vec3 to_light = normalize(vec3(0.4, 1.0, 0.3));
const float ambient = 0.25;

void main() {
    float lambert = max(dot(normalize(world_normal), to_light), 0.0);
    target = vec4(colour * (ambient + (1.0 - ambient) * lambert), 1.0);
}
