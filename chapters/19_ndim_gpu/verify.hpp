#pragma once
// Chapter 19's --verify cpu, its CPU side apart from Vulkan: what the capture
// shader wrote (capture.vert: one vec4 per vertex of the pool per object,
// x and y in clip units, z 1 where the vertex is in front of the eye, w 1
// where it was written at all) compared with two CPU references, vkt::ndim's
// per-plane path (the shader's arithmetic in the shader's order) and chapter
// 18's model matrix.

#include "vkt/domains/ndim.hpp"
#include "vkt/scene/ndim_controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ch19 {

struct Comparison {
    size_t checked = 0, clipped = 0;
    size_t mismatched = 0;                         // in front of the eye on one side only
    size_t missing = 0;                            // never written: a vertex no draw reached
    double plane_error = 0.0, matrix_error = 0.0;  // relative, see below
};

// [compare]
// The scene's poses at `time` with what `controls` added; to_clip turns the
// CPU's projected point into clip units as the push constants do; captured
// is capture.vert's buffer, the meshes' vertices in the scene's order.
inline Comparison compare_with_cpu(const vkt::ndim::Scene& scene,
                                   const vkt::ndim::Controls& controls, float time,
                                   const float to_clip[2], const float* captured) {
    namespace nd = vkt::ndim;
    // Where each mesh's vertices start in the pool, and the pool's size.
    std::vector<size_t> first_vertex;
    size_t pool = 0;
    for (const nd::Mesh& mesh : scene.meshes) {
        first_vertex.push_back(pool);
        pool += mesh.vertex_count();
    }
    Comparison c;
    std::vector<float> world(size_t(scene.dim));
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const nd::Transform t = controls.pose(scene.objects[o], time);
        const nd::Matrix model = nd::model_matrix(t);
        const auto m = size_t(scene.objects[o].mesh);
        const nd::Mesh& mesh = scene.meshes[m];
        for (size_t v = 0; v < mesh.vertex_count(); ++v) {
            const float* gpu = captured + (o * pool + first_vertex[m] + v) * 4;
            if (gpu[3] != 1.0f) {
                ++c.missing;
                continue;
            }
            float by_plane[2] = {0, 0}, by_matrix[2] = {0, 0};
            nd::transform_point(t, mesh.vertex(v), world);
            const bool visible = nd::project_to_2d(world, controls.projection, scene.eye, by_plane);
            nd::transform_point(model, mesh.vertex(v), world);
            nd::project_to_2d(world, controls.projection, scene.eye, by_matrix);
            ++c.checked;
            if (visible != (gpu[2] == 1.0f)) ++c.mismatched;
            if (!visible) {
                ++c.clipped;
                continue;
            }
            // Relative to the coordinate, or to the half screen (1 in clip
            // units) for a point on the screen: a point near an eye lands
            // far outside, where a float has fewer digits to spare.
            for (int k = 0; k < 2; ++k) {
                const double g = gpu[k], p = by_plane[k] * to_clip[k],
                             q = by_matrix[k] * to_clip[k];
                c.plane_error =
                    std::max(c.plane_error, std::abs(g - p) / std::max(1.0, std::abs(p)));
                c.matrix_error =
                    std::max(c.matrix_error, std::abs(g - q) / std::max(1.0, std::abs(q)));
            }
        }
    }
    return c;
}
// [/compare]

}  // namespace ch19
