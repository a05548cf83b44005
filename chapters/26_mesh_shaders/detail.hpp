#pragma once
// Chapter 26's --detail: the model made denser, so that culling has vertex
// work to save (book/perf_26_mesh_shaders.md measures it). Each level splits
// every triangle into four at its edges' midpoints: the same surface (a flat
// facet stays flat), four times the triangles, and meshlets of 64 vertices
// that cover a quarter of the area, so their normals spread less and their
// cones are narrower. The tests draw --detail 1 three ways, one picture.

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <unordered_map>
#include <utility>
#include <vector>

namespace ch26 {

// [subdivide]
// One level. A midpoint is made once per edge, found by its two ends
// whichever way round a triangle names them, so the four triangles of a
// neighbour share it and the mesh stays one surface (meshlets share vertices
// across it as before). Vertex has vec4 position and normal (main.cpp).
template <class Vertex>
void subdivide(std::vector<Vertex>& vertices, std::vector<glm::vec3>& positions,
               std::vector<uint32_t>& indices) {
    std::unordered_map<uint64_t, uint32_t> midpoints;
    midpoints.reserve(indices.size());
    const auto midpoint = [&](uint32_t a, uint32_t b) {
        const uint64_t edge = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
        const auto [at, added] = midpoints.try_emplace(edge, uint32_t(vertices.size()));
        if (added) {
            const glm::vec4 n = vertices[a].normal + vertices[b].normal;
            const Vertex v{0.5f * (vertices[a].position + vertices[b].position),
                           glm::length(n) > 1e-20f ? glm::normalize(n) : vertices[a].normal};
            vertices.push_back(v);
            positions.push_back(glm::vec3(v.position));
        }
        return at->second;
    };
    std::vector<uint32_t> finer;
    finer.reserve(4 * indices.size());
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        // Three corners and the middle, each wound as the triangle was.
        finer.insert(finer.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    indices = std::move(finer);
}
// [/subdivide]

}  // namespace ch26
