#pragma once
// Chapter 26's meshlets: the shaders' limits, and the culling its task shader
// does, on the CPU. The meshlets themselves (the struct and the builder) are
// in vkt/scene/meshlets.hpp, where chapter 28 finds them too. The unit tests
// (tests/unit/test_meshlets.cpp) check that the culling here never drops a
// triangle the viewer could see.

#include "vkt/scene/meshlets.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace ch26 {

// What meshlets.mesh declares (max_vertices, max_primitives, and the default
// of its workgroup size, which the pipeline may change: mesh_limits.hpp) and
// meshlets.task's workgroup size: the shaders' numbers, which
// tests/unit/test_meshlets.cpp reads back from the compiled SPIR-V.
constexpr uint32_t kMeshVertices = 64, kMeshTriangles = 124, kMeshWorkgroup = 32, kTaskGroup = 32;

using vkt::build_meshlets, vkt::Meshlet, vkt::Meshlets;

// [frustum-planes]
// The six planes of the frustum of a Vulkan clip_from_world matrix (depth 0
// to 1), each (n, d) with n of unit length and n . p + d >= 0 inside: the
// rows r0..r3 of the matrix give r3 + r0 (left), r3 - r0 (right), r3 + r1,
// r3 - r1, r2 (near) and r3 - r2 (far). The task shader does the same.
inline void frustum_planes(const glm::mat4& m, glm::vec4 planes[6]) {
    const auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    planes[0] = row(3) + row(0);
    planes[1] = row(3) - row(0);
    planes[2] = row(3) + row(1);
    planes[3] = row(3) - row(1);
    planes[4] = row(2);
    planes[5] = row(3) - row(2);
    for (int i = 0; i < 6; ++i) planes[i] /= glm::length(glm::vec3(planes[i]));
}

inline bool outside_frustum(const glm::vec4 planes[6], const Meshlet& m) {
    for (int i = 0; i < 6; ++i)
        if (glm::dot(glm::vec3(planes[i]), m.centre) + planes[i].w < -m.radius) return true;
    return false;
}
// [/frustum-planes]

// [cull]
// Back-facing as a whole: every triangle's normal lies within the cone's
// half-angle a of its axis, and every point of the sphere is seen from the
// eye within b = asin(radius / distance) of the direction to its centre; if
// the axis is less than 90 - a - b degrees from that direction, every
// triangle faces away. cos(90 - a - b) = sin(a + b) <= sin a + sin b, so
// dot(centre - eye, axis) >= (sin a) |centre - eye| + radius is enough.
inline bool faces_away(const Meshlet& m, glm::vec3 eye) {
    const glm::vec3 to_centre = m.centre - eye;
    return glm::dot(to_centre, m.cone_axis) >= m.cone_cutoff * glm::length(to_centre) + m.radius;
}
// [/cull]

// What the task shader should find for one view: a meshlet outside the
// frustum counts there, else one facing away counts there (the same order).
struct Culled {
    uint32_t frustum = 0, cone = 0;
};
inline Culled cull_on_cpu(const Meshlets& model, const glm::mat4& clip_from_world, glm::vec3 eye) {
    glm::vec4 planes[6];
    frustum_planes(clip_from_world, planes);
    Culled culled;
    for (const Meshlet& m : model.meshlets) {
        if (outside_frustum(planes, m))
            ++culled.frustum;
        else if (faces_away(m, eye))
            ++culled.cone;
    }
    return culled;
}

}  // namespace ch26
