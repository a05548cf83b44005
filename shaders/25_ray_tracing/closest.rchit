#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
// Chapter 25: the nearest surface a ray hit. It lights the point, asking a
// shadow ray whether the light reaches it, and adds what a mirror would see
// by tracing the reflected ray: rays traced from here are one level deeper.
#include "ray_common.glsl"

layout(set = 0, binding = 0) uniform accelerationStructureEXT scene;
// The scene's vertices (position, normal: six floats) and its 16-bit
// indices, two to a word; one record per instance (main.cpp's Object).
layout(set = 0, binding = 2, std430) readonly buffer Vertices { float vertices[]; };
layout(set = 0, binding = 3, std430) readonly buffer Indices { uint index_words[]; };
struct Object {
    vec4 colour;
    uint first_index;
    float reflectivity;
    uint checker;
    uint unused;
};
layout(set = 0, binding = 4, std430) readonly buffer Objects { Object objects[]; };

// [declarations]
// The payload this shader was run for (the tracer's, of the same type,
// whatever its location there), two payloads of its own for the rays it
// traces (traceRayEXT's last argument names one by location), and the hit's
// two barycentric coordinates, which the triangle intersection fills in.
layout(location = 0) rayPayloadInEXT Hit hit;
layout(location = 1) rayPayloadEXT Hit reflected;
layout(location = 2) rayPayloadEXT uint shadowed;
hitAttributeEXT vec2 barycentrics;
// [/declarations]

uint index_at(uint i) {
    return (index_words[i / 2] >> (16 * (i % 2))) & 0xffffu;
}

vec3 normal_at(uint vertex) {
    return vec3(vertices[6 * vertex + 3], vertices[6 * vertex + 4], vertices[6 * vertex + 5]);
}

// [closest-hit]
void main() {
    // Which object, which triangle, where in it: the instance's custom
    // index, the primitive's number within its mesh, the barycentrics.
    const Object object = objects[gl_InstanceCustomIndexEXT];
    const uint first = object.first_index + 3 * gl_PrimitiveID;
    const vec3 w = vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics);
    const vec3 local = w.x * normal_at(index_at(first)) + w.y * normal_at(index_at(first + 1)) +
                       w.z * normal_at(index_at(first + 2));
    // A normal goes to world space by the inverse transpose of the
    // instance's transform: a row vector times world-from-object's inverse.
    const vec3 normal = normalize(vec3(local * gl_WorldToObjectEXT));
    const vec3 point = gl_WorldRayOriginEXT + gl_HitTEXT * gl_WorldRayDirectionEXT;
    vec3 albedo = object.colour.rgb;
    if (object.checker != 0 && mod(floor(point.x) + floor(point.z), 2.0) != 0.0) albedo *= 0.3;

    // Any hit between the point and the light will do: no closest hit is
    // looked for and none is run; only the shadow miss shader (miss index
    // 1) clears the flag. The origin is lifted off the surface, so that the
    // ray does not find the triangle it starts on.
    const vec3 to_light = -pc.light.xyz;
    const vec3 origin = point + 1e-3 * normal;
    const float lambert = max(dot(normal, to_light), 0.0);
    shadowed = 1;
    if (lambert > 0.0 && hit.depth < pc.max_depth)
        traceRayEXT(scene,
                    gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT |
                        gl_RayFlagsSkipClosestHitShaderEXT,
                    0xff, 0, 1, 1, origin, 0.0, to_light, 1000.0, 2);
    vec3 colour = albedo * (0.15 + 0.85 * lambert * float(1 - shadowed));

    // A mirror's colour is partly what its reflected ray finds: this very
    // shader again, one level deeper, until --bounces reflections are spent.
    if (object.reflectivity > 0.0 && hit.depth <= pc.bounces) {
        reflected.depth = hit.depth + 1;
        traceRayEXT(scene, gl_RayFlagsOpaqueEXT, 0xff, 0, 1, 0, origin, 0.0,
                    reflect(gl_WorldRayDirectionEXT, normal), 1000.0, 1);
        colour = mix(colour, reflected.colour, object.reflectivity);
    }
    hit.colour = colour;
}
// [/closest-hit]
