#pragma once
// Chapter 15's scene, as plain data: three meshes in one vertex and one index
// buffer, and a floor plus a grid of objects, each with its mesh, model
// matrix, shade and two texture slots. Nothing here calls Vulkan; main.cpp
// uploads it.

#include "vkt/resources/image_io.hpp"
#include "vkt/scene/camera_math.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace {

// [structs]
// The layouts the shaders read through buffer references (std430): vec4s only,
// so C++ and GLSL agree without padding rules to remember.
struct Vertex {
    glm::vec4 position_u;  // xyz: position, w: texture u
    glm::vec4 normal_v;    // xyz: normal, w: texture v
};
static_assert(sizeof(Vertex) == 32);

struct Object {
    glm::mat4 model;
    glm::vec4 tint;         // rgb: multiplies the texture; w: how often it repeats
    uint32_t side_texture;  // slots in the texture array
    uint32_t top_texture;
    uint32_t pad[2];
};
static_assert(sizeof(Object) == 96);
// [/structs]

// One mesh in the shared vertex and index buffers.
struct Mesh {
    uint32_t first_index = 0, index_count = 0;
    int32_t vertex_offset = 0;
};

// Appends a flat convex face (corners in either order: it is turned to face
// away from the origin) as a fan of triangles, counter-clockwise from outside.
inline void add_face(std::vector<Vertex>& vertices, std::vector<uint16_t>& indices,
                     const Mesh& mesh, std::vector<glm::vec3> corners, std::vector<glm::vec2> uvs) {
    glm::vec3 n = glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
    if (glm::dot(n, corners[0] + corners[1] + corners[2]) < 0.0f) {
        std::reverse(corners.begin(), corners.end());
        std::reverse(uvs.begin(), uvs.end());
        n = -n;
    }
    // Indices count from the mesh's first vertex: the draw's vertexOffset adds the rest.
    const auto first = uint16_t(vertices.size() - size_t(mesh.vertex_offset));
    for (size_t i = 0; i < corners.size(); ++i)
        vertices.push_back({glm::vec4(corners[i], uvs[i].x), glm::vec4(n, uvs[i].y)});
    for (size_t i = 1; i + 1 < corners.size(); ++i)
        indices.insert(indices.end(), {first, uint16_t(first + i), uint16_t(first + i + 1)});
}

// Three meshes, each within -0.5..0.5: a cube, a square pyramid, an octahedron.
inline std::vector<Mesh> make_meshes(std::vector<Vertex>& vertices,
                                     std::vector<uint16_t>& indices) {
    std::vector<Mesh> meshes;
    auto begin = [&] {
        meshes.push_back({uint32_t(indices.size()), 0, int32_t(vertices.size())});
        return meshes.back();
    };
    auto end = [&] {
        meshes.back().index_count = uint32_t(indices.size()) - meshes.back().first_index;
    };
    const std::vector<glm::vec2> square = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const std::vector<glm::vec2> triangle = {{0, 1}, {1, 1}, {0.5f, 0}};

    Mesh cube = begin();
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign;
            add_face(
                vertices, indices, cube,
                {0.5f * (n - u - v), 0.5f * (n + u - v), 0.5f * (n + u + v), 0.5f * (n - u + v)},
                square);
        }
    end();

    Mesh pyramid = begin();
    const glm::vec3 base[] = {
        {-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, 0.5f}, {-0.5f, -0.5f, 0.5f}};
    add_face(vertices, indices, pyramid, {base[0], base[1], base[2], base[3]}, square);
    for (int i = 0; i < 4; ++i)
        add_face(vertices, indices, pyramid, {base[i], base[(i + 1) % 4], {0.0f, 0.5f, 0.0f}},
                 triangle);
    end();

    Mesh octahedron = begin();
    for (float x : {0.5f, -0.5f})
        for (float y : {0.5f, -0.5f})
            for (float z : {0.5f, -0.5f})
                add_face(vertices, indices, octahedron, {{x, 0, 0}, {0, y, 0}, {0, 0, z}},
                         triangle);
    end();
    return meshes;
}

// A small integer hash: the same scene on every machine.
inline uint32_t hash(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

struct Scene {
    std::vector<Vertex> vertices;
    std::vector<uint16_t> indices;
    std::vector<Mesh> meshes;
    std::vector<Object> objects;    // 0: the floor
    std::vector<uint32_t> mesh_of;  // per object, an index into meshes
    float half_width = 1.0f;        // of the floor
};

inline Scene make_scene(uint32_t grid, uint32_t texture_count) {
    Scene scene;
    scene.meshes = make_meshes(scene.vertices, scene.indices);
    const float spacing = 2.0f, half_width = 0.5f * spacing * float(grid);
    scene.half_width = half_width;
    scene.objects.push_back({glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}),
                                        {2.0f * half_width, 0.2f, 2.0f * half_width}),
                             glm::vec4(1.0f, 1.0f, 1.0f, float(grid)),
                             0,
                             0,
                             {}});
    scene.mesh_of = {0};  // the floor is a flat cube
    for (uint32_t i = 0; i < grid * grid; ++i) {
        const uint32_t h = hash(i), g = hash(h);
        const float size = 0.7f + 0.3f * float(h % 1000) / 1000.0f;
        const uint32_t column = i % grid, row = i / grid;  // whole numbers
        const glm::vec3 position((float(column) + 0.5f) * spacing - half_width, 0.5f * size,
                                 (float(row) + 0.5f) * spacing - half_width);
        const float shade = 0.8f + 0.2f * float((g >> 8) % 100) / 100.0f;
        scene.objects.push_back({vkt::transform(position, glm::radians(float((h >> 10) % 360)),
                                                {0, 1, 0}, glm::vec3(size)),
                                 glm::vec4(shade, shade, shade, 1.0f),
                                 1 + (g >> 3) % texture_count,
                                 1 + (g >> 17) % texture_count,
                                 {}});
        scene.mesh_of.push_back((h >> 20) % 3);
    }
    return scene;
}

// Slot 0 of the texture array: a grey checker, the floor's texture and what
// an object shows while its own texture is still "loading".
inline vkt::RgbaImage grey_checker() {
    vkt::RgbaImage image{64, 64, std::vector<uint8_t>(size_t(64) * 64 * 4, 255)};
    for (uint32_t y = 0; y < 64; ++y)
        for (uint32_t x = 0; x < 64; ++x)
            std::memset(&image.pixels[(size_t(y) * 64 + x) * 4],
                        ((x / 32 + y / 32) % 2) ? 150 : 110, 3);
    return image;
}

}  // namespace
