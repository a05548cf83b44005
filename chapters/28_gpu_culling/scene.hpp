#pragma once
// Chapter 28's scene: a field of N instances of four of chapter 12's shapes
// on a grid, every eighth row a wall, and the CPU's own frustum test (the
// reference the GPU's counts are checked against). Plain C++ and glm.

#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ch28 {

// One instance as cull.comp and draw.vert read it (std430, 80 bytes).
struct Instance {
    glm::vec4 position_yaw;  // xyz: where its centre stands; w: its turn about +y, radians
    glm::vec4 scale;         // xyz: its size along its own axes
    glm::vec4 colour;        // rgb: linear
    glm::vec4 box_centre;    // its world-space bounding box: centre ...
    glm::vec4 box_half;      // ... and half extents (xyz); w: its mesh's index, as a float
};
static_assert(sizeof(Instance) == 80);

// Where a mesh lies in the index buffer, the box around its vertices, and
// (the task path, task_path.hpp) its meshlets.
struct Mesh {
    vkt::shapes::MeshRange range;
    glm::vec3 lo, hi;
    uint32_t first_meshlet = 0, meshlet_count = 0;
};

enum MeshKind : uint32_t { cube, sphere, cylinder, torus, floor_mesh, mesh_count };

constexpr float kSpacing = 3.0f;    // metres between grid points
constexpr uint32_t kWallEvery = 8;  // every eighth row is a wall

inline uint32_t hash(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

// The shapes, finer than chapter 12's: some thousand triangles for a sphere
// or a torus, so that a field of them is millions of triangles.
inline std::vector<Mesh> make_meshes(vkt::shapes::MeshBuilder& builder) {
    std::vector<Mesh> meshes(mesh_count);
    meshes[cube].range = builder.cube();
    meshes[sphere].range = builder.sphere(32, 16);
    meshes[cylinder].range = builder.cylinder(32);
    meshes[torus].range = builder.torus(32, 16, 0.15f);
    meshes[floor_mesh].range = builder.floor(1);
    for (Mesh& mesh : meshes) {
        mesh.lo = glm::vec3(1e30f);
        mesh.hi = glm::vec3(-1e30f);
        for (uint32_t i = 0; i < mesh.range.index_count; ++i) {
            const glm::vec3 p =
                builder.vertices[builder.indices[mesh.range.first_index + i]].position;
            mesh.lo = glm::min(mesh.lo, p);
            mesh.hi = glm::max(mesh.hi, p);
        }
    }
    return meshes;
}

// The box around a mesh once scaled, turned and moved: the transformed box's
// centre, and half extents |M| * half (each axis of the turned box projected).
inline void set_box(Instance& instance, const Mesh& mesh, uint32_t kind) {
    const glm::mat4 m = vkt::transform(glm::vec3(instance.position_yaw), instance.position_yaw.w,
                                       {0, 1, 0}, glm::vec3(instance.scale));
    const glm::vec3 centre = 0.5f * (mesh.lo + mesh.hi), half = 0.5f * (mesh.hi - mesh.lo);
    glm::vec3 extent(0.0f);
    for (int axis = 0; axis < 3; ++axis) extent += glm::abs(glm::vec3(m[axis])) * half[axis];
    instance.box_centre = m * glm::vec4(centre, 1.0f);
    instance.box_half = glm::vec4(extent, float(kind));
}

// Instances 0 .. n - 1 on a grid of side ceil(sqrt(n)), kSpacing apart; then
// the floor, instance n, which is never culled.
inline std::vector<Instance> make_instances(uint32_t n, const std::vector<Mesh>& meshes) {
    const glm::vec3 palette[] = {{0.80f, 0.25f, 0.20f}, {0.90f, 0.60f, 0.15f},
                                 {0.25f, 0.65f, 0.30f}, {0.20f, 0.45f, 0.80f},
                                 {0.60f, 0.35f, 0.75f}, {0.85f, 0.85f, 0.80f}};
    const auto side = uint32_t(std::ceil(std::sqrt(double(n))));
    const float half = 0.5f * kSpacing * float(side);
    std::vector<Instance> instances(n + 1);
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t h = hash(i), g = hash(h), column = i % side, row = i / side;
        const glm::vec3 at(kSpacing * (float(column) + 0.5f) - half, 0.0f,
                           kSpacing * (float(row) + 0.5f) - half);
        Instance& o = instances[i];
        uint32_t kind = cube;
        if (row % kWallEvery == 0) {
            // A wall 2.8 wide: a gap of 0.2 to the next, so no two instances
            // touch (two that touched could tie in depth, and then the order
            // of the draws, which the culling changes, would decide a pixel).
            o.scale = glm::vec4(2.8f, 3.0f, 0.4f, 0.0f);
            o.position_yaw = glm::vec4(at + glm::vec3(0, 1.5f, 0), 0.0f);
            o.colour = glm::vec4(0.55f, 0.52f, 0.50f, 1.0f);
        } else {
            kind = h % 4;
            const float size = 0.6f + 0.8f * float((h >> 8) % 1000) / 1000.0f;
            o.scale = glm::vec4(glm::vec3(size), 0.0f);
            o.position_yaw =
                glm::vec4(at + glm::vec3(0, 0.5f * size, 0), float((g >> 8) % 628) / 100.0f);
            o.colour = glm::vec4(palette[(g >> 4) % 6], 1.0f);
        }
        set_box(o, meshes[kind], kind);
    }
    Instance& floor = instances[n];
    floor.scale = glm::vec4(2.0f * half + 2.0f * kSpacing, 1.0f, 2.0f * half + 2.0f * kSpacing, 0);
    floor.position_yaw = glm::vec4(0.0f);
    floor.colour = glm::vec4(0.45f, 0.45f, 0.45f, 1.0f);
    set_box(floor, meshes[floor_mesh], floor_mesh);
    return instances;
}

// [cpu-frustum]
// The CPU's frustum test, in double precision: a box is outside when all
// eight corners lie beyond one plane of the clip volume (-w <= x, y <= w,
// 0 <= z <= w). Each plane is a row combination of the matrix; scaled to
// unit normal, it gives a corner's distance in metres. Boxes within 1 cm of
// a plane (float rounding on the GPU may decide either way) are counted
// apart, as `boundary`.
// The camera stands in the field, 5 m up, and turns slowly while it looks a
// little down across it. Reversed depth (near 1, far 0): vulkan_perspective
// with the planes swapped, which keeps float depth's precision where the
// distances are large. second: --path task --view culled's camera, 40 m
// ahead of the first, 8 m to its right and 22 m up, looking back down at
// the ground 12 m ahead of it.
inline glm::mat4 camera(uint32_t n, VkExtent2D extent, double time, bool second = false) {
    const float side = kSpacing * std::ceil(std::sqrt(float(n)));
    const float yaw = 0.5f + 0.02f * float(time);
    glm::vec3 eye(0.37f * kSpacing, 5.0f, 0.1f * side);
    glm::vec3 ahead(std::sin(yaw), -0.12f, -std::cos(yaw));
    if (second) {
        const glm::vec3 flat(ahead.x, 0.0f, ahead.z), right(-ahead.z, 0.0f, ahead.x);
        const glm::vec3 target = eye + 12.0f * flat;
        eye += glm::vec3(0, 22.0f, 0) + 8.0f * right + 40.0f * flat;
        ahead = glm::vec3(target.x, 0.0f, target.z) - eye;
    }
    const glm::mat4 view = glm::lookAt(eye, eye + ahead, glm::vec3(0, 1, 0));
    const float aspect = float(extent.width) / float(extent.height);
    return vkt::vulkan_perspective(glm::radians(60.0f), aspect, 2.0f * side, 0.1f) * view;
}

struct FrustumCount {
    uint32_t inside = 0, boundary = 0;
};
inline FrustumCount count_in_frustum(const std::vector<Instance>& instances, uint32_t n,
                                     const glm::mat4& clip_from_world) {
    const glm::dmat4 m(clip_from_world);
    const auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    glm::dvec4 planes[6] = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
                            row(3) - row(1), row(2),          row(3) - row(2)};
    for (glm::dvec4& plane : planes) plane /= glm::length(glm::dvec3(plane));
    constexpr double margin = 0.01;
    FrustumCount count;
    for (uint32_t i = 0; i < n; ++i) {
        const glm::dvec3 c(instances[i].box_centre), h(instances[i].box_half);
        bool out_sure = false, out_maybe = false;
        for (const glm::dvec4& plane : planes) {
            int beyond = 0, near_plane = 0;
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 s(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
                const double d = glm::dot(plane, glm::dvec4(c + s * h, 1.0));  // inside: d > 0
                beyond += d < -margin;
                near_plane += d < margin;
            }
            out_sure |= beyond == 8;
            out_maybe |= near_plane == 8;
        }
        if (!out_maybe)
            ++count.inside;
        else if (!out_sure)
            ++count.boundary;
    }
    return count;
}
// [/cpu-frustum]

}  // namespace ch28
