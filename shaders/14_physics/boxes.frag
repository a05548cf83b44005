#version 450
layout(location = 0) in vec3 normal;
layout(location = 1) in vec3 colour;
layout(location = 0) out vec4 target;

// [shading]
// One fixed directional light (the direction towards it) and Lambert's law:
// a face lit head-on gets all of it, a face turned away gets none; ambient
// light keeps the shadowed faces from going black. Per-face normals make each
// face one flat shade, so the boxes read as 3D.
const vec3 to_light = normalize(vec3(0.4, 1.0, 0.3));
const float ambient = 0.25;

void main() {
    float lambert = max(dot(normalize(normal), to_light), 0.0);
    target = vec4(colour * (ambient + (1.0 - ambient) * lambert), 1.0);
}
// [/shading]
