// Chapter 26's meshlet builder (vkt/scene/meshlets.hpp) and culling
// (chapters/26_mesh_shaders/meshlets.hpp): on the chapter's default model (the knot) and a UV
// sphere from chapter 12's shapes, every triangle lands in exactly one meshlet, the limits hold,
// every cone holds its triangles' normals and every sphere their vertices; a meshlet culled as
// back-facing has only triangles that face away; and on a flat grid the counts are known by hand.
#include "../../chapters/26_mesh_shaders/meshlets.hpp"
#include "spirv_reflect.hpp"

#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/gltf.hpp"
#include "vkt/scene/meshes.hpp"

#include <catch2/catch_test_macros.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

using vkt::Meshlet;
using vkt::Meshlets;

namespace {

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
};

Mesh knot() {
    const vkt::GltfScene scene = vkt::load_gltf(VKT_SOURCE_DIR "/assets/gltf/knot.glb");
    Mesh mesh;
    for (const vkt::GltfVertex& v : scene.vertices) mesh.positions.push_back(v.position);
    mesh.indices = scene.indices;
    return mesh;
}

Mesh sphere() {
    vkt::shapes::MeshBuilder builder;
    builder.sphere(48, 24);
    Mesh mesh;
    for (const auto& v : builder.vertices) mesh.positions.push_back(v.position);
    mesh.indices.assign(builder.indices.begin(), builder.indices.end());
    return mesh;
}

// An n x n grid of unit squares in the z = 0 plane, facing +z.
Mesh grid(uint32_t n) {
    Mesh mesh;
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i) mesh.positions.push_back({float(i), float(j), 0.0f});
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i;
            mesh.indices.insert(mesh.indices.end(),
                                {a, a + 1, a + n + 1, a + 1, a + n + 2, a + n + 1});
        }
    return mesh;
}

// A fan of n triangles round vertex 0 (a disc facing +z): vertex 0 is in all of them.
Mesh fan(uint32_t n) {
    Mesh mesh;
    mesh.positions.push_back({0.0f, 0.0f, 0.0f});
    for (uint32_t i = 0; i <= n; ++i) {
        const float a = 6.2831853f * float(i) / float(n + 1);
        mesh.positions.push_back({std::cos(a), std::sin(a), 0.0f});
    }
    for (uint32_t i = 1; i <= n; ++i) mesh.indices.insert(mesh.indices.end(), {0, i, i + 1});
    return mesh;
}

std::array<uint32_t, 3> global_triangle(const Meshlets& out, const Meshlet& m, uint32_t t) {
    const uint32_t packed = out.triangles[m.triangle_offset + t];
    return {out.vertices[m.vertex_offset + (packed & 0xFF)],
            out.vertices[m.vertex_offset + ((packed >> 8) & 0xFF)],
            out.vertices[m.vertex_offset + ((packed >> 16) & 0xFF)]};
}

void check_meshlets(const Mesh& mesh, uint32_t max_vertices, uint32_t max_triangles) {
    const Meshlets out =
        vkt::build_meshlets(mesh.positions, mesh.indices, max_vertices, max_triangles);
    // Every triangle exactly once (as the same three vertices in the same turn).
    std::multiset<std::array<uint32_t, 3>> wanted, got;
    const auto canonical = [](std::array<uint32_t, 3> t) {
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        return t;
    };
    for (size_t i = 0; i < mesh.indices.size(); i += 3)
        wanted.insert(canonical({mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]}));
    size_t triangles = 0;
    for (const Meshlet& m : out.meshlets) {
        CHECK(m.vertex_count >= 3);
        CHECK(m.vertex_count <= max_vertices);
        CHECK(m.triangle_count >= 1);
        CHECK(m.triangle_count <= max_triangles);
        triangles += m.triangle_count;
        // A meshlet's vertices are distinct.
        std::set<uint32_t> distinct(out.vertices.begin() + m.vertex_offset,
                                    out.vertices.begin() + m.vertex_offset + m.vertex_count);
        CHECK(distinct.size() == m.vertex_count);
        const float cone_cos =
            m.cone_cutoff <= 1.0f ? std::sqrt(1.0f - m.cone_cutoff * m.cone_cutoff) : -1.0f;
        for (uint32_t t = 0; t < m.triangle_count; ++t) {
            const uint32_t packed = out.triangles[m.triangle_offset + t];
            for (uint32_t shift : {0u, 8u, 16u}) CHECK(((packed >> shift) & 0xFF) < m.vertex_count);
            const auto tri = global_triangle(out, m, t);
            got.insert(canonical(tri));
            for (uint32_t v : tri)
                CHECK(glm::length(mesh.positions[v] - m.centre) <= m.radius * 1.0001f + 1e-6f);
            const glm::vec3 n = vkt::face_normal(mesh.positions[tri[0]], mesh.positions[tri[1]],
                                                 mesh.positions[tri[2]]);
            if (n != glm::vec3(0.0f)) CHECK(glm::dot(n, m.cone_axis) >= cone_cos - 1e-4f);
        }
    }
    CHECK(triangles == mesh.indices.size() / 3);
    CHECK(got == wanted);
}

}  // namespace

TEST_CASE("build_meshlets: every triangle once, within the limits, cones hold the normals",
          "[meshlets]") {
    check_meshlets(knot(), 64, 124);
    check_meshlets(knot(), 32, 40);
    check_meshlets(sphere(), 64, 124);
    check_meshlets(grid(20), 64, 124);
    check_meshlets(grid(5), 3, 1);  // one triangle each
}

// The growth's work, counted: a triangle's every vertex offers at most
// vkt::kOffers untaken triangles at each step, so however many triangles
// share a vertex the scores stay a bounded number per triangle. Rescanning
// every use of every vertex scored about n / 2 per triangle here (a fan of
// 20,000: 200,009,999 scores, 10,000 a triangle; 20,000 triangles at index 0:
// 595,161,252; a fan of 200,000 took over a minute).
TEST_CASE("build_meshlets: work bounded per triangle however many share a vertex", "[meshlets]") {
    const uint64_t n = 20000;
    const Mesh disc = fan(uint32_t(n));
    check_meshlets(disc, 64, 124);
    const Meshlets from_fan = vkt::build_meshlets(disc.positions, disc.indices, 64, 124);
    CHECK(from_fan.scored <= 2 * vkt::kOffers * n);  // 33 a triangle
    // Every triangle at index 0: one vertex, every triangle degenerate.
    const std::vector<glm::vec3> one_point(1, glm::vec3(0.0f));
    const std::vector<uint32_t> zeros(3 * n, 0);
    const Meshlets from_zeros = vkt::build_meshlets(one_point, zeros, 64, 124);
    CHECK(from_zeros.scored <= vkt::kOffers * n);
    uint64_t triangles = 0;
    for (const Meshlet& m : from_zeros.meshlets) {
        CHECK(m.vertex_count == 1);
        triangles += m.triangle_count;
    }
    CHECK(triangles == n);
    CHECK(from_zeros.meshlets.size() == (n + 123) / 124);
}

TEST_CASE("build_meshlets: the knot makes several hundred compact meshlets", "[meshlets]") {
    const Mesh mesh = knot();
    const Meshlets out = vkt::build_meshlets(mesh.positions, mesh.indices, 64, 124);
    // 30,720 triangles: at best 124 a meshlet (248), at worst a strip of
    // 62 (496); the greedy growth fills them to about 80 on average.
    CHECK(out.meshlets.size() > 248);
    CHECK(out.meshlets.size() < 496);
    // Compact enough that most cones can cull: narrower than 60 degrees.
    const auto narrow = std::count_if(out.meshlets.begin(), out.meshlets.end(),
                                      [](const Meshlet& m) { return m.cone_cutoff < 0.87f; });
    CHECK(narrow * 10 > int64_t(out.meshlets.size()) * 9);
}

TEST_CASE("faces_away never culls a triangle that faces the eye", "[meshlets]") {
    for (const Mesh& mesh : {knot(), sphere()}) {
        const Meshlets out = vkt::build_meshlets(mesh.positions, mesh.indices, 64, 124);
        const glm::vec3 eyes[] = {{0, 0, 4}, {3, 2, -1}, {-0.2f, 0.1f, 1.3f}, {0.5f, -6, 0.5f}};
        uint32_t culled = 0;
        for (const glm::vec3& eye : eyes)
            for (const Meshlet& m : out.meshlets) {
                if (!ch26::faces_away(m, eye)) continue;
                ++culled;
                for (uint32_t t = 0; t < m.triangle_count; ++t) {
                    const auto tri = global_triangle(out, m, t);
                    const glm::vec3 a = mesh.positions[tri[0]];
                    const glm::vec3 n =
                        vkt::face_normal(a, mesh.positions[tri[1]], mesh.positions[tri[2]]);
                    CHECK(glm::dot(n, a - eye) >= 0.0f);  // the eye is behind the face
                }
            }
        CHECK(culled > 0);  // the test saw some
    }
}

TEST_CASE("cull_on_cpu: a flat grid seen from behind, in front and from far away", "[meshlets]") {
    const Mesh mesh = grid(40);  // 3,200 triangles facing +z, x and y from 0 to 40
    const Meshlets out = vkt::build_meshlets(mesh.positions, mesh.indices, 64, 124);
    const auto count = uint32_t(out.meshlets.size());
    const glm::mat4 projection = vkt::vulkan_perspective(glm::radians(90.0f), 1.0f, 0.1f, 1000.0f);
    const glm::vec3 middle(20.0f, 20.0f, 0.0f);
    // In front, looking at it: the whole grid in view, every meshlet faces the eye.
    const glm::vec3 front = middle + glm::vec3(0, 0, 30);
    ch26::Culled culled =
        ch26::cull_on_cpu(out, projection * glm::lookAt(front, middle, {0, 1, 0}), front);
    CHECK(culled.frustum == 0);
    CHECK(culled.cone == 0);
    // Behind it, looking at it: every meshlet faces away (their cones are flat).
    const glm::vec3 back = middle - glm::vec3(0, 0, 30);
    culled = ch26::cull_on_cpu(out, projection * glm::lookAt(back, middle, {0, 1, 0}), back);
    CHECK(culled.frustum == 0);
    CHECK(culled.cone == count);
    // In front but looking away: everything behind the eye, outside the frustum.
    culled = ch26::cull_on_cpu(
        out, projection * glm::lookAt(front, front + glm::vec3(0, 0, 1), {0, 1, 0}), front);
    CHECK(culled.frustum == count);
    CHECK(culled.cone == 0);
    // The planes of a 90-degree frustum from the origin looking down -z.
    glm::vec4 planes[6];
    ch26::frustum_planes(projection, planes);
    CHECK(std::abs(planes[4].w + 0.1f) < 1e-4f);  // near: -z - 0.1 >= 0
    CHECK(std::abs(planes[0].x - std::sqrt(0.5f)) < 1e-4f);
}

TEST_CASE("the mesh and task shaders declare the limits the C++ builds meshlets for",
          "[meshlets]") {
    // SetMeshOutputsEXT past max_vertices or max_primitives is undefined
    // behaviour that lavapipe may forgive; the numbers are written in the
    // shaders and in meshlets.hpp, so they are read back from the SPIR-V.
    const std::string dir = std::string(VKT_BINARY_DIR) + "/shaders/26_mesh_shaders/";
    const auto mesh_spirv = spirv::read(dir + "meshlets.mesh.spv");
    CHECK(spirv::execution_mode(mesh_spirv, spirv::mode_output_vertices) ==
          std::vector<uint32_t>{ch26::kMeshVertices});
    CHECK(spirv::execution_mode(mesh_spirv, spirv::mode_output_primitives) ==
          std::vector<uint32_t>{ch26::kMeshTriangles});
    // The mesh workgroup's x is specialization constant 0 (the pipeline sets
    // it: mesh_limits.hpp), kMeshWorkgroup unless it does.
    std::vector<int> spec_ids;
    CHECK(spirv::local_size(mesh_spirv, &spec_ids) ==
          std::vector<uint32_t>{ch26::kMeshWorkgroup, 1, 1});
    CHECK(spec_ids == std::vector<int>{0, -1, -1});
    const auto task = spirv::read(dir + "meshlets.task.spv");
    CHECK(spirv::local_size(task) == std::vector<uint32_t>{ch26::kTaskGroup, 1, 1});
    // And the builder keeps to them: no meshlet of the knot goes past either.
    const Mesh mesh = knot();
    const Meshlets out = vkt::build_meshlets(mesh.positions, mesh.indices, ch26::kMeshVertices,
                                             ch26::kMeshTriangles);
    REQUIRE(!out.meshlets.empty());
    for (const Meshlet& m : out.meshlets) {
        CHECK(m.vertex_count <= ch26::kMeshVertices);
        CHECK(m.triangle_count <= ch26::kMeshTriangles);
    }
}

TEST_CASE("over many views, no meshlet culled by the frustum has a vertex inside it",
          "[meshlets]") {
    // The task shader's frustum test (outside_frustum, the same formula) is
    // conservative: a meshlet it drops has no vertex that a camera could
    // see. Checked against the clip-space definition of inside (-w <= x, y
    // <= w, 0 <= z <= w) for every vertex, from 200 views around and inside
    // the knot, pseudo-random but the same on every run.
    const Mesh mesh = knot();
    const Meshlets out = vkt::build_meshlets(mesh.positions, mesh.indices, 64, 124);
    uint32_t state = 12345u, culled = 0, kept = 0;
    const auto next = [&]() {  // a linear congruential generator, 0..1
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    };
    for (int view = 0; view < 200; ++view) {
        const glm::vec3 eye(6 * next() - 3, 6 * next() - 3, 6 * next() - 3);
        const glm::vec3 target(2 * next() - 1, 2 * next() - 1, 2 * next() - 1);
        if (glm::length(target - eye) < 0.1f) continue;
        const glm::mat4 clip_from_world =
            vkt::vulkan_perspective(glm::radians(30.0f + 60.0f * next()), 0.5f + next(), 0.05f,
                                    2.0f + 6.0f * next()) *
            glm::lookAt(eye, target, glm::vec3(0, 1, 0));
        glm::vec4 planes[6];
        ch26::frustum_planes(clip_from_world, planes);
        for (const Meshlet& m : out.meshlets) {
            if (!ch26::outside_frustum(planes, m)) {
                ++kept;
                continue;
            }
            ++culled;
            for (uint32_t i = 0; i < m.vertex_count; ++i) {
                const glm::vec4 c = clip_from_world *
                                    glm::vec4(mesh.positions[out.vertices[m.vertex_offset + i]], 1);
                const bool inside = -c.w <= c.x && c.x <= c.w && -c.w <= c.y && c.y <= c.w &&
                                    0 <= c.z && c.z <= c.w;
                CHECK_FALSE(inside);
            }
        }
    }
    // The views did cull, and did keep: the check was not empty either way.
    CHECK(culled > 1000);
    CHECK(kept > 1000);
}
