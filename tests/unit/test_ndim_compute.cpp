// Chapter 20's CPU side (chapters/20_ndim_compute/scene_state.hpp): the
// compute rasteriser's palette orders lines by depth and holds chapter 18's
// colours; and the --verify comparison reports 0 for vertices projected
// exactly as the CPU does, and catches a wrong one. (The keys' pose:
// test_ndim_controls.cpp.)
#include "../../chapters/20_ndim_compute/scene_state.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

namespace {

uint32_t byte(uint32_t word, int k) {
    return word >> (8 * k) & 0xffu;
}

}  // namespace

TEST_CASE("the palette: level 0 is empty, the top byte is the level, colours as chapter 18",
          "[ndim_compute]") {
    for (bool bgra : {true, false}) {
        const std::vector<uint32_t> words = ch20::palette(bgra);
        REQUIRE(words.size() == 256);
        CHECK(words[0] == 0u);
        for (uint32_t level = 1; level < 256; ++level) {
            CHECK(words[level] >> 24 == level);
            CHECK(words[level] > words[level - 1]);  // atomicMax keeps the nearer line
        }
        // Chapter 18's hand-worked colours (tests/chapters/18_ndim_cpu.cmake):
        // depth +-0.5774 is stored as (233, 173, 147) near, (147, 156, 233)
        // far; the nearest level of each is within one step of 255.
        const int r = bgra ? 2 : 0, b = bgra ? 0 : 2;
        const auto level = [](float t) { return 1u + uint32_t((0.5f + 0.5f * t) * 254.0f + 0.5f); };
        const uint32_t near = words[level(0.5774f)], far = words[level(-0.5774f)];
        CHECK(int(byte(near, r)) - 233 <= 1);
        CHECK(int(byte(near, r)) - 233 >= -1);
        CHECK(byte(near, 1) == 173);
        CHECK(int(byte(near, b)) - 147 <= 1);
        CHECK(int(byte(near, b)) - 147 >= -1);
        CHECK(int(byte(far, r)) - 147 <= 1);
        CHECK(int(byte(far, r)) - 147 >= -1);
        CHECK(int(byte(far, 1)) - 156 <= 1);
        CHECK(int(byte(far, 1)) - 156 >= -1);
        CHECK(int(byte(far, b)) - 233 <= 1);
        CHECK(int(byte(far, b)) - 233 >= -1);
    }
}

TEST_CASE("compare_with_cpu: 0 for the CPU's own projection, and it sees a wrong vertex",
          "[ndim_compute]") {
    namespace nd = vkt::ndim;
    const nd::Scene scene = nd::make_scene("default", 4, false);
    const vkt::ndim::Controls keys(4, vkt::ndim::Projection::perspective);
    const ch20::Push push{{0.5f, -0.25f}, scene.eye, 0, 2, 0, {320, 240}};
    std::vector<ch20::Projected> gpu;
    std::vector<float> world(4);
    for (const nd::SceneObject& object : scene.objects) {
        const nd::Transform t = keys.pose(object, 1.0f);
        const nd::Mesh& mesh = scene.meshes[size_t(object.mesh)];
        for (size_t i = 0; i < mesh.vertex_count(); ++i) {
            nd::transform_point(t, mesh.vertex(i), world);
            float xy[2];
            REQUIRE(nd::project_to_2d(world, nd::Projection::perspective, scene.eye, xy));
            gpu.push_back({xy[0] * 0.5f, xy[1] * -0.25f, 0xff000000u,
                           (world[3] - t.position[3]) / mesh.radius()});
        }
    }
    ch20::Comparison c = ch20::compare_with_cpu(scene, keys, 1.0f, push, gpu.data());
    CHECK(c.vertices == 40);
    CHECK(c.hidden == 0);
    CHECK(c.mismatched == 0);
    CHECK(c.position == 0.0);
    CHECK(c.depth < 1e-6);
    gpu[17].x += 0.01f;
    gpu[30].colour = 0;  // marked behind the eye, but it is not
    c = ch20::compare_with_cpu(scene, keys, 1.0f, push, gpu.data());
    CHECK(c.position == Catch::Approx(0.01).margin(1e-6));
    CHECK(c.mismatched == 1);
}
