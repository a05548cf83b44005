#pragma once
// Meshlets, taught in chapter 26 (mesh shaders) and drawn again by chapter
// 28's task path: a triangle list cut on the CPU into small pieces that one
// mesh shader workgroup draws, each with the bounds a task shader can cull
// by. Plain C++ and glm, no Vulkan. The unit tests
// (tests/unit/test_meshlets.cpp) check the limits, that every triangle lands
// in exactly one meshlet, and that each cone holds its triangles' normals.

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace vkt {

// [meshlet]
// One meshlet as the shaders read it (std430: 48 bytes, vec3 + float pairs).
// Its vertices are vertex_count entries of Meshlets::vertices from
// vertex_offset (indices into the model's vertex array); its triangles are
// triangle_count entries of Meshlets::triangles from triangle_offset, each
// three 8-bit indices into the meshlet's own vertices, packed a | b<<8 | c<<16.
struct Meshlet {
    glm::vec3 centre{0.0f};  // the bounding sphere
    float radius = 0.0f;
    glm::vec3 cone_axis{0.0f, 0.0f, 1.0f};  // the normal cone (see faces_away)
    float cone_cutoff = 2.0f;               // sin of the cone's half-angle; 2: never culled
    uint32_t vertex_offset = 0, vertex_count = 0;
    uint32_t triangle_offset = 0, triangle_count = 0;
};
// [/meshlet]
static_assert(sizeof(Meshlet) == 48);

struct Meshlets {
    std::vector<Meshlet> meshlets;
    std::vector<uint32_t> vertices;   // global vertex index per meshlet vertex
    std::vector<uint32_t> triangles;  // packed local indices, one uint per triangle
    uint64_t scored = 0;              // candidate triangles the growth scored: its work
};

inline glm::vec3 face_normal(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    return length > 1e-20f ? n / length : glm::vec3(0.0f);  // 0: a degenerate triangle
}

// The sphere around the meshlet's vertices (centre of their box), and the
// cone: its axis the mean of the triangles' unit normals, its half-angle the
// widest angle between the axis and any of them. A cone of 90 degrees or more
// (a meshlet that folds round) cannot be back-facing as a whole: cutoff 2.
inline void compute_bounds(Meshlet& m, const Meshlets& out, std::span<const glm::vec3> positions) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (uint32_t i = 0; i < m.vertex_count; ++i) {
        lo = glm::min(lo, positions[out.vertices[m.vertex_offset + i]]);
        hi = glm::max(hi, positions[out.vertices[m.vertex_offset + i]]);
    }
    m.centre = 0.5f * (lo + hi);
    m.radius = 0.0f;
    for (uint32_t i = 0; i < m.vertex_count; ++i)
        m.radius = std::max(m.radius,
                            glm::length(positions[out.vertices[m.vertex_offset + i]] - m.centre));
    std::vector<glm::vec3> normals;
    glm::vec3 sum(0.0f);
    for (uint32_t t = 0; t < m.triangle_count; ++t) {
        const uint32_t packed = out.triangles[m.triangle_offset + t];
        const auto at = [&](uint32_t shift) {
            return positions[out.vertices[m.vertex_offset + ((packed >> shift) & 0xFF)]];
        };
        const glm::vec3 n = face_normal(at(0), at(8), at(16));
        if (n == glm::vec3(0.0f)) continue;  // no area, never seen: it limits nothing
        normals.push_back(n);
        sum += n;
    }
    m.cone_cutoff = 2.0f;
    if (glm::length(sum) < 1e-6f) return;
    m.cone_axis = glm::normalize(sum);
    float min_cos = 1.0f;
    for (const glm::vec3& n : normals) min_cos = std::min(min_cos, glm::dot(n, m.cone_axis));
    if (min_cos > 0.0f) m.cone_cutoff = std::sqrt(std::max(0.0f, 1.0f - min_cos * min_cos));
}

// Greedy growth: a meshlet starts at the first triangle not yet taken and
// adds, one at a time, the untaken triangle touching its vertices that needs
// the fewest new vertices (ties: the one nearest the meshlet's middle, which
// keeps it round and its normals close), until a limit would be passed or
// nothing touches it. Compact meshlets have tight spheres and narrow cones,
// so the task shader can cull them.
//
// Each vertex keeps its untaken triangles in a linked list (a taken one
// leaves it in constant time), and offers at most the first kOffers of them
// at each step: the work is at most 64 x kOffers scores per triangle however
// many triangles share a vertex (a fan of 200,000, or 100,000 triangles all
// at index 0). A vertex of an ordinary mesh has fewer, and offers them all.
constexpr uint32_t kOffers = 32;
inline Meshlets build_meshlets(std::span<const glm::vec3> positions,
                               std::span<const uint32_t> indices, uint32_t max_vertices,
                               uint32_t max_triangles) {
    max_vertices = std::min(max_vertices, 256u);  // local indices are 8 bits
    const auto triangle_count = uint32_t(indices.size() / 3);
    // The corners (3t + k) at each vertex, in index order, untaken only.
    constexpr uint32_t none = UINT32_MAX;
    std::vector<uint32_t> head(positions.size(), none), next(3 * size_t(triangle_count), none),
        prev(next.size(), none);
    for (uint32_t c = 3 * triangle_count; c-- > 0;) {
        next[c] = head[indices[c]];
        if (next[c] != none) prev[next[c]] = c;
        head[indices[c]] = c;
    }
    const auto unlink = [&](uint32_t c) {
        (prev[c] != none ? next[prev[c]] : head[indices[c]]) = next[c];
        if (next[c] != none) prev[next[c]] = prev[c];
    };

    Meshlets out;
    std::vector<bool> taken(triangle_count, false);
    std::vector<int32_t> local(positions.size(), -1);  // global -> this meshlet's vertex
    uint32_t seed = 0;
    while (true) {
        while (seed < triangle_count && taken[seed]) ++seed;
        if (seed == triangle_count) break;
        Meshlet m{.vertex_offset = uint32_t(out.vertices.size()),
                  .triangle_offset = uint32_t(out.triangles.size())};
        glm::vec3 middle(0.0f);
        uint32_t next_triangle = seed;
        while (next_triangle != none) {
            // [remap]
            // The triangle joins: each corner new to the meshlet gets the
            // next local index (local[v]: global vertex v's, -1 if none yet).
            uint32_t packed = 0;
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t v = indices[3 * next_triangle + k];
                if (local[v] < 0) {
                    local[v] = int32_t(m.vertex_count++);
                    out.vertices.push_back(v);
                    middle += (positions[v] - middle) / float(m.vertex_count);
                }
                packed |= uint32_t(local[v]) << (8 * k);
                unlink(3 * next_triangle + k);
            }
            // [/remap]
            out.triangles.push_back(packed);
            taken[next_triangle] = true;
            // [close]
            if (++m.triangle_count == max_triangles) break;  // full: close it
            // The best neighbour: fewest new vertices, then nearest the middle.
            next_triangle = none;
            uint32_t best_new = 4;
            float best_distance = std::numeric_limits<float>::max();
            for (uint32_t i = 0; i < m.vertex_count; ++i) {
                uint32_t offered = 0;
                for (uint32_t c = head[out.vertices[m.vertex_offset + i]];
                     c != none && offered < kOffers; c = next[c], ++offered) {
                    const uint32_t t = c / 3;
                    ++out.scored;
                    uint32_t fresh = 0;
                    glm::vec3 centroid(0.0f);
                    for (uint32_t k = 0; k < 3; ++k) {
                        fresh += local[indices[3 * t + k]] < 0 ? 1 : 0;
                        centroid += positions[indices[3 * t + k]] / 3.0f;
                    }
                    if (m.vertex_count + fresh > max_vertices) continue;
                    const float distance = glm::length(centroid - middle);
                    if (fresh < best_new || (fresh == best_new && distance < best_distance)) {
                        next_triangle = t;
                        best_new = fresh;
                        best_distance = distance;
                    }
                }
            }
            // Still none (no untaken neighbour, or each would bring too many
            // vertices): the loop ends and the meshlet is closed.
            // [/close]
        }
        for (uint32_t i = 0; i < m.vertex_count; ++i) local[out.vertices[m.vertex_offset + i]] = -1;
        compute_bounds(m, out, positions);
        out.meshlets.push_back(m);
    }
    return out;
}

}  // namespace vkt
