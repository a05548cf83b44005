#pragma once
// Chapter 07's cube with a colour per face, drawn again by chapter 08. Plain
// C++: the vertices and 16-bit indices that the chapters upload (chapter 05).

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace vkt::shapes {

struct ColouredVertex {
    glm::vec3 position;
    glm::vec3 colour;
};

// [cube]
// A cube of edge 1 around the origin: 4 corners per face, so that each face
// has its own colour, and two triangles per face, counter-clockwise seen from
// outside. Face k has normal n = +-e_i; its corners are n/2 +- u/2 +- v/2 with
// u = e_(i+1), v = +-e_(i+2), chosen so that u x v = n.
inline void make_coloured_cube(std::vector<ColouredVertex>& vertices,
                               std::vector<uint16_t>& indices) {
    const glm::vec3 colours[6] = {
        {0.8f, 0.1f, 0.1f}, {0.1f, 0.6f, 0.6f},  // +x red, -x cyan
        {0.1f, 0.7f, 0.1f}, {0.6f, 0.1f, 0.6f},  // +y green, -y magenta
        {0.1f, 0.2f, 0.8f}, {0.8f, 0.7f, 0.1f},  // +z blue, -z yellow
    };
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const float sign = face % 2 ? -1.0f : 1.0f;
        glm::vec3 n(0.0f), u(0.0f), v(0.0f);
        n[axis] = sign;
        u[(axis + 1) % 3] = 1.0f;
        v[(axis + 2) % 3] = sign;
        const uint16_t first = uint16_t(vertices.size());
        for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
            vertices.push_back({0.5f * (n + c.x * u + c.y * v), colours[face]});
        indices.insert(indices.end(), {first, uint16_t(first + 1), uint16_t(first + 2), first,
                                       uint16_t(first + 2), uint16_t(first + 3)});
    }
}
// [/cube]

}  // namespace vkt::shapes
