// Chapter 15's scene (chapters/15_bindless/scene.hpp): the meshes are closed
// and wound counter-clockwise from outside (the chapter culls back faces),
// and the scene is the same every time, with every texture in use.

#include "../../chapters/15_bindless/scene.hpp"

#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <set>

TEST_CASE("chapter 15's meshes: sizes, and every triangle faces outwards", "[bindless_scene]") {
    std::vector<Vertex> vertices;
    std::vector<uint16_t> indices;
    const std::vector<Mesh> meshes = make_meshes(vertices, indices);
    REQUIRE(meshes.size() == 3);
    // Cube: 6 quads; pyramid: a quad and 4 triangles; octahedron: 8 triangles.
    CHECK(meshes[0].index_count == 36);
    CHECK(meshes[1].index_count == 6 + 12);
    CHECK(meshes[2].index_count == 24);
    CHECK(meshes[1].vertex_offset == 24);
    CHECK(meshes[2].vertex_offset == 24 + 16);
    CHECK(vertices.size() == 24 + 16 + 24);
    CHECK(indices.size() == 36 + 18 + 24);
    for (const Mesh& mesh : meshes)
        for (uint32_t t = 0; t < mesh.index_count; t += 3) {
            // As the GPU reads them: index + vertexOffset.
            const auto& a = vertices[size_t(mesh.vertex_offset) + indices[mesh.first_index + t]];
            const auto& b =
                vertices[size_t(mesh.vertex_offset) + indices[mesh.first_index + t + 1]];
            const auto& c =
                vertices[size_t(mesh.vertex_offset) + indices[mesh.first_index + t + 2]];
            const glm::vec3 pa(a.position_u), pb(b.position_u), pc(c.position_u);
            const glm::vec3 n = glm::cross(pb - pa, pc - pa);
            INFO("triangle " << t / 3 << " of the mesh at index " << mesh.first_index);
            CHECK(glm::dot(n, pa + pb + pc) > 0.0f);  // counter-clockwise seen from outside
            CHECK(glm::dot(glm::normalize(n), glm::vec3(a.normal_v)) > 0.999f);
            for (const glm::vec3& p : {pa, pb, pc}) {
                CHECK(std::abs(p.x) <= 0.5f);
                CHECK(std::abs(p.y) <= 0.5f);
                CHECK(std::abs(p.z) <= 0.5f);
            }
        }
}

TEST_CASE("chapter 15's scene: the floor, 1024 objects on it, all 48 textures used",
          "[bindless_scene]") {
    const Scene scene = make_scene(32, 48);
    REQUIRE(scene.objects.size() == 1025);
    REQUIRE(scene.mesh_of.size() == 1025);
    CHECK(scene.half_width == 32.0f);
    CHECK(scene.objects[0].side_texture == 0);
    CHECK(scene.objects[0].top_texture == 0);
    std::set<uint32_t> used;
    for (size_t i = 1; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        CHECK(scene.mesh_of[i] < 3);
        CHECK(o.side_texture >= 1);
        CHECK(o.side_texture <= 48);
        CHECK(o.top_texture >= 1);
        CHECK(o.top_texture <= 48);
        used.insert(o.side_texture);
        used.insert(o.top_texture);
        // The bottom of the mesh (y = -0.5) rests on the floor's top (y = 0).
        const glm::vec4 bottom = o.model * glm::vec4(0.0f, -0.5f, 0.0f, 1.0f);
        CHECK(std::abs(bottom.y) < 1e-5f);
        CHECK(std::abs(bottom.x) < 32.0f);
        CHECK(std::abs(bottom.z) < 32.0f);
    }
    CHECK(used.size() == 48);

    const Scene again = make_scene(32, 48);
    CHECK(again.mesh_of == scene.mesh_of);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        CHECK(again.objects[i].model == scene.objects[i].model);
        CHECK(again.objects[i].side_texture == scene.objects[i].side_texture);
    }
}
