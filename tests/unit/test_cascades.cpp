// Chapter 22's cascades (chapters/22_shadows/cascades.hpp): the practical
// split scheme against values worked out by hand, and the light's
// orthographic box around each slice of the view; and the geometry behind
// the chapter test's two hand-picked pixels.
#include "../../chapters/22_shadows/cascades.hpp"
#include "../../chapters/22_shadows/scene.hpp"
#include "../../chapters/22_shadows/uniforms.hpp"
#include "spirv_reflect.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstddef>
#include <utility>

using Catch::Approx;

namespace {
// The chapter's view (main.cpp): from (0, 3, 8), looking a little down.
Camera chapter_camera() {
    return {.eye = {0, 3, 8},
            .forward = glm::normalize(glm::vec3(0, -0.25f, -1)),
            .up = glm::normalize(glm::vec3(0, 1, -0.25f)),
            .fov_y = glm::radians(50.0f),
            .aspect = 4.0f / 3.0f,
            .z_near = 0.1f,
            .z_far = 60.0f};
}
}  // namespace

TEST_CASE("cascade_splits: the practical scheme between uniform and logarithmic", "[cascades]") {
    // n = 0.1, f = 60, three cascades, lambda = 0.6 (the chapter's): the
    // logarithmic boundaries 0.1 * 600^(1/3) = 0.8434 and 600^(2/3) / 10 =
    // 7.114, the uniform ones 20.067 and 40.033; blended 0.6 : 0.4, 8.53 and
    // 20.28, as the chapter prints.
    const std::vector<float> splits = cascade_splits(0.1f, 60.0f, 3, 0.6f);
    REQUIRE(splits.size() == 4);
    CHECK(splits[0] == Approx(0.1f));
    CHECK(splits[1] == Approx(8.53f).margin(0.01));
    CHECK(splits[2] == Approx(20.28f).margin(0.01));
    CHECK(splits[3] == Approx(60.0f));
    // lambda 0: uniform; lambda 1: each cascade the same ratio far / near.
    CHECK(cascade_splits(1.0f, 9.0f, 2, 0.0f)[1] == Approx(5.0f));
    CHECK(cascade_splits(1.0f, 9.0f, 2, 1.0f)[1] == Approx(3.0f));
    CHECK(cascade_splits(1.0f, 9.0f, 1, 0.5f).size() == 2);
}

TEST_CASE("light_from_world puts a slice inside the map, depth growing away from the light",
          "[cascades]") {
    const Camera camera = chapter_camera();
    const glm::vec3 light = glm::normalize(glm::vec3(-0.6f, -1.0f, -0.45f));
    const auto corners = slice_corners(camera, 8.53f, 20.28f);
    // The slice's far corners are 20.28 / 8.53 times as far from the axis.
    CHECK(glm::length(corners[4] - (camera.eye + 20.28f * camera.forward)) ==
          Approx(20.28f / 8.53f * glm::length(corners[0] - (camera.eye + 8.53f * camera.forward))));
    const glm::mat4 m = light_from_world(corners, light, 40.0f, 1024);
    glm::vec3 centre(0.0f);
    for (const glm::vec3& p : corners) {
        centre += p / 8.0f;
        const glm::vec4 c = m * glm::vec4(p, 1.0f);
        CHECK(c.w == Approx(1.0f));  // orthographic
        CHECK(std::abs(c.x) <= 1.0f);
        CHECK(std::abs(c.y) <= 1.0f);
        CHECK(c.z > 0.0f);
        CHECK(c.z < 1.0f);
    }
    // The slice's centre is the map's, to within the snap: half a texel,
    // 1/1024 of clip space's width of 2.
    const glm::vec4 mid = m * glm::vec4(centre, 1.0f);
    CHECK(std::abs(mid.x) <= 1.0f / 1024.0f + 1e-6f);
    CHECK(std::abs(mid.y) <= 1.0f / 1024.0f + 1e-6f);
    // A step towards the light: nearer (smaller depth), the same place.
    const glm::vec4 nearer = m * glm::vec4(centre - light, 1.0f);
    CHECK(nearer.z < mid.z);
    CHECK(nearer.x == Approx(mid.x).margin(1e-5));
    CHECK(nearer.y == Approx(mid.y).margin(1e-5));
}

TEST_CASE("light_from_world moves the map by whole texels as the camera moves", "[cascades]") {
    // Without the snap the box follows the slice's centre exactly, so a
    // fixed world point lands at a new place inside its texel after every
    // move, and the shadows' edges crawl. With it, the map's texel grid stays
    // put in the world: the point moves across the map by whole texels only.
    const glm::vec3 light = glm::normalize(glm::vec3(-0.6f, -1.0f, -0.45f));
    const uint32_t size = 1024;
    Camera camera = chapter_camera();
    // Where a world point lands in a map, in texels from the map's corner.
    const auto texel_of = [&](const glm::mat4& m, glm::vec3 p) {
        const glm::vec4 clip = m * glm::vec4(p, 1.0f);
        return (glm::vec2(clip) * 0.5f + 0.5f) * float(size);
    };
    // How far apart two positions are inside their texels (0 to 0.5).
    const auto fraction_apart = [](float a, float b) {
        const float d = (a - b) - std::round(a - b);
        return std::abs(d);
    };
    const std::vector<float> splits = cascade_splits(0.1f, 60.0f, 3, 0.6f);
    for (uint32_t i = 0; i < 3; ++i) {
        INFO("cascade " << i);
        camera.eye = {0, 3, 8};
        const glm::mat4 before =
            light_from_world(slice_corners(camera, splits[i], splits[i + 1]), light, 40.0f, size);
        // A small step sideways and forwards: the slice, and with it its box,
        // slides by 0.37 units, from a few texels of the far cascade to a few
        // dozen of the near one.
        camera.eye += glm::vec3(0.31f, 0.0f, -0.2f);
        const glm::mat4 after =
            light_from_world(slice_corners(camera, splits[i], splits[i + 1]), light, 40.0f, size);
        for (const glm::vec3 p : {glm::vec3(0.0f), glm::vec3(3.0f, 1.5f, 2.0f)}) {
            const glm::vec2 a = texel_of(before, p), b = texel_of(after, p);
            // The box moved: the point is at least a texel away in the map...
            CHECK(glm::length(a - b) >= 1.0f);
            // ...yet at the same place inside its texel.
            CHECK(fraction_apart(a.x, b.x) < 0.01f);
            CHECK(fraction_apart(a.y, b.y) < 0.01f);
        }
    }
}

namespace {

// The nearest of chapter 22's objects (make_scene, in world space) that the
// ray from `origin` towards the light meets, other than the floor: its
// colour and distance, or a negative distance if it meets none.
// Möller-Trumbore over every triangle of every draw.
std::pair<glm::vec4, float> first_blocker(glm::vec3 origin) {
    vkt::shapes::MeshBuilder meshes;
    const std::vector<Draw> draws = make_scene(meshes);
    const glm::vec3 dir = -light_direction();
    std::pair<glm::vec4, float> nearest{glm::vec4(0), -1.0f};
    for (size_t d = 1; d < draws.size(); ++d) {  // draws[0] is the floor
        const Draw& draw = draws[d];
        for (uint32_t i = 0; i < draw.mesh.index_count; i += 3) {
            glm::vec3 v[3];
            for (uint32_t k = 0; k < 3; ++k)
                v[k] = glm::vec3(
                    draw.world_from_object *
                    glm::vec4(
                        meshes.vertices[meshes.indices[draw.mesh.first_index + i + k]].position,
                        1.0f));
            const glm::vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], p = glm::cross(dir, e2);
            const float det = glm::dot(e1, p);
            if (std::abs(det) < 1e-9f) continue;
            const glm::vec3 t0 = origin - v[0], q = glm::cross(t0, e1);
            const float u = glm::dot(t0, p) / det, w = glm::dot(dir, q) / det;
            const float t = glm::dot(e2, q) / det;
            if (u < 0 || w < 0 || u + w > 1 || t <= 1e-4f) continue;
            if (nearest.second < 0 || t < nearest.second) nearest = {draw.colour, t};
        }
    }
    return nearest;
}

}  // namespace

TEST_CASE("the chapter test's shadowed floor point looks at the light through a pillar",
          "[cascades]") {
    // tests/chapters/22_shadows.cmake (and 24's): the floor point
    // (2.1, 0, 1.325) must be in shadow, (2, 0, 4) lit. A ray to the light
    // through the scene the chapter draws (make_scene, light_direction):
    // the first meets the right front pillar, colour (0.85, 0.45, 0.3), at
    // its centre (3, 1.5, 2) 1.5 units of (0.6, 1, 0.45) away, so well inside
    // it (its faces are 0.3 from the centre in x); the second meets nothing.
    const auto [colour, t] = first_blocker({2.1f, 0.0f, 1.325f});
    REQUIRE(t > 0.0f);
    CHECK(colour == glm::vec4(0.85f, 0.45f, 0.3f, 1.0f));
    const glm::vec3 centre = glm::vec3(2.1f, 0.0f, 1.325f) + 1.5f * glm::vec3(0.6f, 1.0f, 0.45f);
    CHECK(centre.x == Approx(3.0f));
    CHECK(centre.y == Approx(1.5f));
    CHECK(centre.z == Approx(2.0f));
    CHECK(first_blocker({2.0f, 0.0f, 4.0f}).second < 0.0f);
    // The floor's Lambert term: n . -light = 1 / |(-0.6, -1, -0.45)| = 0.8.
    CHECK(glm::dot(glm::vec3(0, 1, 0), -light_direction()) == Approx(0.8f));
}

TEST_CASE("chapter 22's FrameBlock matches both compiled shaders' block", "[cascades]") {
    for (const char* shader : {"scene.vert", "scene.frag"}) {
        INFO(shader);
        const auto words =
            spirv::read(std::string(VKT_BINARY_DIR "/shaders/22_shadows/") + shader + ".spv");
        const auto block = spirv::struct_members(words, "Frame");
        CHECK(block.at("clip_from_world").offset == offsetof(FrameBlock, clip_from_world));
        CHECK(block.at("light_from_world").offset == offsetof(FrameBlock, light_from_world));
        CHECK(block.at("light_from_world").array_stride == sizeof(glm::mat4));
        CHECK(block.at("splits").offset == offsetof(FrameBlock, splits));
        CHECK(block.at("eye").offset == offsetof(FrameBlock, eye));
        CHECK(block.at("forward").offset == offsetof(FrameBlock, forward));
        CHECK(block.at("light").offset == offsetof(FrameBlock, light));
        CHECK(block.at("settings").offset == offsetof(FrameBlock, settings));
    }
}
