#pragma once
// Chapter 12's shapes, made in code with a normal at every vertex: a floor
// grid, a cube, a UV sphere, a cylinder and a torus. Each fits in the unit box
// around the origin (edge or diameter 1) and is wound counter-clockwise seen
// from outside: (b - a) x (c - a) points the way the normals do
// (tests/unit/test_lighting.cpp checks every triangle).

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace vkt::shapes {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

// Where one shape lies in the shared index buffer.
struct MeshRange {
    uint32_t first_index = 0;
    uint32_t index_count = 0;
};

struct MeshBuilder {
    std::vector<Vertex> vertices;
    std::vector<uint16_t> indices;

    uint16_t vertex(glm::vec3 p, glm::vec3 n) {
        vertices.push_back({p, n});
        return uint16_t(vertices.size() - 1);
    }
    void triangle(uint32_t a, uint32_t b, uint32_t c) {
        indices.insert(indices.end(), {uint16_t(a), uint16_t(b), uint16_t(c)});
    }

    // A square floor of edge 1 in the y = 0 plane, normal +y, cut into
    // cells x cells squares: (cells + 1)^2 vertices. Few cells make the
    // per-vertex lighting's coarseness visible.
    MeshRange floor(int cells) {
        MeshRange range{uint32_t(indices.size()), 0};
        const uint32_t first = uint32_t(vertices.size()), row = uint32_t(cells + 1);
        for (int j = 0; j <= cells; ++j)
            for (int i = 0; i <= cells; ++i)
                vertex({float(i) / float(cells) - 0.5f, 0.0f, float(j) / float(cells) - 0.5f},
                       {0, 1, 0});
        for (uint32_t j = 0; j < uint32_t(cells); ++j)
            for (uint32_t i = 0; i < uint32_t(cells); ++i) {
                const uint32_t a = first + j * row + i;  // a, a + z, a + x: up
                triangle(a, a + row, a + 1);
                triangle(a + 1, a + row, a + row + 1);
            }
        range.index_count = uint32_t(indices.size()) - range.first_index;
        return range;
    }

    // Chapter 07's cube of edge 1: four corners per face, so each face has
    // its own (flat) normal.
    MeshRange cube() {
        MeshRange range{uint32_t(indices.size()), 0};
        for (int face = 0; face < 6; ++face) {
            const int axis = face / 2;
            const float sign = face % 2 ? -1.0f : 1.0f;
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign;  // u x v = n
            const uint32_t first = uint32_t(vertices.size());
            for (glm::vec2 c :
                 {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
                vertex(0.5f * (n + c.x * u + c.y * v), n);
            triangle(first, first + 1, first + 2);
            triangle(first, first + 2, first + 3);
        }
        range.index_count = uint32_t(indices.size()) - range.first_index;
        return range;
    }

    // A UV sphere of diameter 1: `slices` around, `stacks` from pole to pole.
    // The normal of a sphere is its position, scaled to unit length.
    MeshRange sphere(int slices, int stacks) {
        constexpr float pi = std::numbers::pi_v<float>;
        MeshRange range{uint32_t(indices.size()), 0};
        const uint32_t first = uint32_t(vertices.size()), row = uint32_t(slices + 1);
        for (int j = 0; j <= stacks; ++j) {
            const float theta = pi * float(j) / float(stacks);  // 0 at the top
            for (int i = 0; i <= slices; ++i) {
                const float phi = 2.0f * pi * float(i) / float(slices);
                const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                                  std::sin(theta) * std::sin(phi));
                vertex(0.5f * n, n);
            }
        }
        for (uint32_t j = 0; j < uint32_t(stacks); ++j)
            for (uint32_t i = 0; i < uint32_t(slices); ++i) {
                const uint32_t a = first + j * row + i;
                // The triangles that would have no area at the poles are left out.
                if (j != 0) triangle(a, a + 1, a + row + 1);
                if (j + 1 != uint32_t(stacks)) triangle(a, a + row + 1, a + row);
            }
        range.index_count = uint32_t(indices.size()) - range.first_index;
        return range;
    }

    // A cylinder of diameter 1 and height 1 around the y axis: smooth sides
    // (normals pointing straight out) and flat caps with their own vertices.
    MeshRange cylinder(int segments) {
        constexpr float pi = std::numbers::pi_v<float>;
        MeshRange range{uint32_t(indices.size()), 0};
        const uint32_t sides = uint32_t(vertices.size());
        for (int i = 0; i <= segments; ++i) {
            const float phi = 2.0f * pi * float(i) / float(segments);
            const glm::vec3 n(std::cos(phi), 0.0f, std::sin(phi));
            vertex(0.5f * n + glm::vec3(0, 0.5f, 0), n);  // 2i: top edge
            vertex(0.5f * n - glm::vec3(0, 0.5f, 0), n);  // 2i + 1: bottom edge
        }
        for (uint32_t i = 0; i < uint32_t(segments); ++i) {
            const uint32_t top = sides + 2 * i, bottom = top + 1;
            triangle(top, top + 2, bottom + 2);
            triangle(top, bottom + 2, bottom);
        }
        for (float y : {0.5f, -0.5f}) {
            const glm::vec3 n(0.0f, 2.0f * y, 0.0f);
            const uint32_t centre = vertex({0, y, 0}, n);
            for (int i = 0; i <= segments; ++i) {
                const float phi = 2.0f * pi * float(i) / float(segments);
                vertex({0.5f * std::cos(phi), y, 0.5f * std::sin(phi)}, n);
            }
            for (uint32_t i = 0; i < uint32_t(segments); ++i) {
                const uint32_t ring = centre + 1 + i;
                if (y > 0)
                    triangle(centre, ring + 1, ring);
                else
                    triangle(centre, ring, ring + 1);
            }
        }
        range.index_count = uint32_t(indices.size()) - range.first_index;
        return range;
    }

    // A torus around the y axis, outer diameter 1: the tube (radius `tube`)
    // circles the axis at 0.5 - tube. The normal points from the tube's
    // centre line to the surface.
    MeshRange torus(int around, int tube_segments, float tube) {
        constexpr float pi = std::numbers::pi_v<float>;
        MeshRange range{uint32_t(indices.size()), 0};
        const float ring = 0.5f - tube;
        const uint32_t first = uint32_t(vertices.size()), row = uint32_t(tube_segments + 1);
        for (int i = 0; i <= around; ++i) {
            const float u = 2.0f * pi * float(i) / float(around);
            for (int j = 0; j <= tube_segments; ++j) {
                const float v = 2.0f * pi * float(j) / float(tube_segments);
                const glm::vec3 n(std::cos(v) * std::cos(u), std::sin(v),
                                  std::cos(v) * std::sin(u));
                const glm::vec3 centre(ring * std::cos(u), 0.0f, ring * std::sin(u));
                vertex(centre + tube * n, n);
            }
        }
        for (uint32_t i = 0; i < uint32_t(around); ++i)
            for (uint32_t j = 0; j < uint32_t(tube_segments); ++j) {
                const uint32_t a = first + i * row + j;
                triangle(a, a + 1, a + row + 1);
                triangle(a, a + row + 1, a + row);
            }
        range.index_count = uint32_t(indices.size()) - range.first_index;
        return range;
    }
};

}  // namespace vkt::shapes
