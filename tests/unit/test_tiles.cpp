// Chapter 17's tile maths (vkt/scene/tiles.hpp): tile counts, depth linearisation,
// and the sphere-against-tile-frustum test, by hand and against brute force;
// binning, against culling every light; and the moving lights
// (vkt/scene/moving_lights.hpp) against chapter 16's make_lights.

#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/deferred_scene.hpp"
#include "vkt/scene/moving_lights.hpp"
#include "vkt/scene/tiles.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using Catch::Approx;

TEST_CASE("tile_grid covers the screen, partial tiles included", "[tiles]") {
    CHECK(vkt::tile_grid(320, 240, 16).x == 20);
    CHECK(vkt::tile_grid(320, 240, 16).y == 15);
    CHECK(vkt::tile_grid(320, 240, 16).count() == 300);
    CHECK(vkt::tile_grid(1920, 1080, 16).x == 120);
    CHECK(vkt::tile_grid(1920, 1080, 16).y == 68);  // 1080 = 67.5 tiles: a half row
    CHECK(vkt::tile_grid(250, 130, 16).x == 16);    // 15 full, 1 of 10 pixels
    CHECK(vkt::tile_grid(250, 130, 16).y == 9);     // 8 full, 1 of 2 pixels
    CHECK(vkt::tile_grid(1, 1, 16).count() == 1);
    CHECK(vkt::tile_grid(16, 17, 16).count() == 2);
}

namespace {
const glm::mat4 proj = vkt::vulkan_perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);

// Where a view-space point lands on a width x height screen, in pixels.
glm::vec2 to_pixels(glm::vec3 p, uint32_t width, uint32_t height) {
    const glm::vec4 clip = proj * glm::vec4(p, 1.0f);
    return {(clip.x / clip.w * 0.5f + 0.5f) * float(width),
            (clip.y / clip.w * 0.5f + 0.5f) * float(height)};
}
}  // namespace

TEST_CASE("view_depth undoes the projection's depth", "[tiles]") {
    for (float t : {0.1f, 0.5f, 3.0f, 42.0f, 100.0f}) {
        const glm::vec4 clip = proj * glm::vec4(0.0f, 0.0f, -t, 1.0f);
        CHECK(vkt::view_depth(proj, clip.z / clip.w) == Approx(t).epsilon(1e-4));
    }
}

TEST_CASE("tile frustum planes, worked by hand", "[tiles]") {
    // A 90-degree square view, 32 x 32 pixels, 16-pixel tiles: four tiles,
    // each a quarter of the view. P[0][0] = 1 and P[1][1] = -1, so tile (0, 0)
    // (top left on screen) holds x / -z in [-1, 0] and y / -z in [0, 1]
    // (Vulkan's framebuffer y points down, world y up).
    const vkt::TileFrustum f = vkt::tile_frustum(proj, 32, 32, 0, 0, 16, 1.0f, 10.0f);
    const float s = std::sqrt(0.5f);
    CHECK(f.planes[0].x == Approx(s));  // x - z >= 0: x / -z >= -1
    CHECK(f.planes[0].z == Approx(-s));
    CHECK(f.planes[1].x == Approx(-1.0f));  // -x >= 0: x / -z <= 0
    CHECK(f.planes[1].z == Approx(0.0f).margin(1e-6));
    CHECK(f.planes[2].y == Approx(1.0f));  // y >= 0
    CHECK(f.planes[3].y == Approx(-s));    // -y - z >= 0: y / -z <= 1
    CHECK(f.planes[3].z == Approx(-s));

    // A sphere of radius 1 at (-2, 2, -5): inside the top-left quarter.
    CHECK(vkt::sphere_touches_tile(f, {-2.0f, 2.0f, -5.0f}, 1.0f));
    // At (1.5, 2, -5) it is 1.5 right of the plane x = 0: culled; radius 2 reaches.
    CHECK_FALSE(vkt::sphere_touches_tile(f, {1.5f, 2.0f, -5.0f}, 1.0f));
    CHECK(vkt::sphere_touches_tile(f, {1.5f, 2.0f, -5.0f}, 2.0f));
    // Depth range [1, 10]: centre at distance 12 with radius 1.5 is beyond
    // (12 - 1.5 > 10), radius 2.5 reaches back to 9.5.
    CHECK_FALSE(vkt::sphere_touches_tile(f, {-2.0f, 2.0f, -12.0f}, 1.5f));
    CHECK(vkt::sphere_touches_tile(f, {-2.0f, 2.0f, -12.0f}, 2.5f));
    // In front of the near end: distance 0.5, radius 0.4 ends at 0.9 < 1.
    CHECK_FALSE(vkt::sphere_touches_tile(f, {-0.1f, 0.1f, -0.5f}, 0.4f));
    CHECK(vkt::sphere_touches_tile(f, {-0.1f, 0.1f, -0.5f}, 0.6f));
    // Below the bottom plane y = 0 by 0.5 with radius 0.4: culled.
    CHECK_FALSE(vkt::sphere_touches_tile(f, {-2.0f, -0.5f, -5.0f}, 0.4f));
}

TEST_CASE("a partial tile's frustum ends at the screen's edge", "[tiles]") {
    // 40 pixels wide: tile 2 spans pixels 32..40, not 32..48.
    const vkt::TileFrustum f = vkt::tile_frustum(proj, 40, 40, 2, 0, 16, 0.1f, 100.0f);
    // The right plane is the screen's edge: x / -z <= 1.
    const glm::vec3 n = f.planes[1];
    CHECK(n.x == Approx(-std::sqrt(0.5f)));
    CHECK(n.z == Approx(-std::sqrt(0.5f)));
}

// Brute force: a sphere touches the tile if some point of the tile's volume
// (pixels of the tile, depths in range) lies within it. Sample the volume
// densely; every sampled hit must be kept by the test (conservative).
TEST_CASE("culling never drops a light that touches the tile", "[tiles]") {
    std::mt19937 random(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const uint32_t width = 64, height = 48, tile = 16;
    int touching = 0, kept_not_touching = 0, culled = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const uint32_t tx = uint32_t(unit(random) * 4) % 4, ty = uint32_t(unit(random) * 3) % 3;
        const float near = 1.0f + 5.0f * unit(random), far = near + 6.0f * unit(random);
        const vkt::TileFrustum f = vkt::tile_frustum(proj, width, height, tx, ty, tile, near, far);
        const glm::vec3 centre(-8.0f + 16.0f * unit(random), -8.0f + 16.0f * unit(random),
                               -(12.0f * unit(random)));
        const float radius = 0.2f + 2.0f * unit(random);
        bool touches = false;
        for (int i = 0; i <= 16 && !touches; ++i)
            for (int j = 0; j <= 16 && !touches; ++j)
                for (int k = 0; k <= 16 && !touches; ++k) {
                    // A point of the tile's volume: a pixel position and a depth.
                    const float px = float(tx * tile) + float(tile) * float(i) / 16.0f;
                    const float py = float(ty * tile) + float(tile) * float(j) / 16.0f;
                    const float t = near + (far - near) * float(k) / 16.0f;
                    const float ndc_x = px / float(width) * 2.0f - 1.0f;
                    const float ndc_y = py / float(height) * 2.0f - 1.0f;
                    const glm::vec3 p(ndc_x * t / proj[0][0], ndc_y * t / proj[1][1], -t);
                    const glm::vec2 back = to_pixels(p, width, height);  // the sample is inside
                    REQUIRE(back.x == Approx(px).margin(1e-3));
                    REQUIRE(back.y == Approx(py).margin(1e-3));
                    touches = glm::distance(p, centre) < radius;
                }
        const bool kept = vkt::sphere_touches_tile(f, centre, radius);
        if (touches) {
            ++touching;
            CHECK(kept);
        } else if (kept) {
            ++kept_not_touching;
        } else {
            ++culled;
        }
    }
    // The random cases exercise all three outcomes; the last is the price of
    // testing plane by plane (and, rarely, a touch the 17^3 samples miss).
    CHECK(touching > 20);
    CHECK(culled > 20);
    CHECK(kept_not_touching > 0);  // near corners: kept, though missing (conservative)
}

// Binning (chapter 17's second step): each light's rectangle of tiles, the
// bins by count, prefix sum and fill, and the lists that culling the bins
// keeps, against culling every light in every tile.
namespace {
// A 16:9 view, 150 x 90 pixels: 10 x 6 tiles, the last row partial.
const glm::mat4 wide = vkt::vulkan_perspective(glm::radians(45.0f), 150.0f / 90.0f, 0.1f, 100.0f);
constexpr uint32_t wide_w = 150, wide_h = 90, tile = 16;

struct Sphere {
    glm::vec3 centre;
    float radius;
};

// Spheres in front of, beside and behind the eye, some through its plane.
std::vector<Sphere> random_spheres(uint32_t count, uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Sphere> spheres;
    for (uint32_t i = 0; i < count; ++i) {
        const float t = -2.0f + 30.0f * unit(random);
        spheres.push_back({{(unit(random) - 0.5f) * (2.0f + 1.4f * std::abs(t)),
                            (unit(random) - 0.5f) * (2.0f + 0.9f * std::abs(t)), -t},
                           0.01f + 1.5f * unit(random) * unit(random)});
    }
    return spheres;
}
}  // namespace

TEST_CASE("a light's rectangle holds every tile whose side planes it passes", "[tiles]") {
    const vkt::TileGrid grid = vkt::tile_grid(wide_w, wide_h, tile);
    uint64_t inside = 0, passing = 0;
    for (const Sphere& s : random_spheres(3000, 5)) {
        const vkt::TileRect rect =
            vkt::light_tile_rect(wide, wide_w, wide_h, tile, s.centre, s.radius);
        for (uint32_t ty = 0; ty < grid.y; ++ty)
            for (uint32_t tx = 0; tx < grid.x; ++tx) {
                // Depths [0, 1e30]: only the side planes and "behind the eye" cull.
                const vkt::TileFrustum f =
                    vkt::tile_frustum(wide, wide_w, wide_h, tx, ty, tile, 0.0f, 1e30f);
                const bool in_rect = !rect.empty() && tx >= rect.x0 && tx <= rect.x1 &&
                                     ty >= rect.y0 && ty <= rect.y1;
                if (vkt::sphere_touches_tile(f, s.centre, s.radius)) {
                    ++passing;
                    REQUIRE(in_rect);  // never a tile lost
                }
                inside += in_rect;
            }
    }
    // And the rectangles are nearly tight: the pixel of margin on each side
    // adds a column or a row now and then (2 in 16 on tiles of 16 pixels), and
    // the tiles of a sphere around the eye's plane are all of them.
    CHECK(passing > 5000);
    CHECK(double(inside) < 1.5 * double(passing));
}

TEST_CASE("light_tile_rect by hand", "[tiles]") {
    // The 90-degree square view of 32 x 32 pixels: a small sphere straight
    // ahead lands on the middle four tiles' corner, (16, 16): all four tiles.
    const vkt::TileRect middle = vkt::light_tile_rect(proj, 32, 32, 16, {0, 0, -10}, 0.5f);
    CHECK((middle.x0 == 0 && middle.x1 == 1 && middle.y0 == 0 && middle.y1 == 1));
    // Up and to the right (view-space y up is the top of the screen): tile (1, 0) only.
    const vkt::TileRect corner = vkt::light_tile_rect(proj, 32, 32, 16, {5, 5, -10}, 0.5f);
    CHECK((corner.x0 == 1 && corner.x1 == 1 && corner.y0 == 0 && corner.y1 == 0));
    // Wholly behind the eye: none. Around the eye: every tile.
    CHECK(vkt::light_tile_rect(proj, 32, 32, 16, {0, 0, 5}, 1.0f).empty());
    const vkt::TileRect around = vkt::light_tile_rect(proj, 32, 32, 16, {0, 0, -0.5f}, 1.0f);
    CHECK((around.x0 == 0 && around.x1 == 1 && around.y0 == 0 && around.y1 == 1));
    // Beside the view (x / -z = 3, far outside the slope 1 of the edge): none.
    CHECK(vkt::light_tile_rect(proj, 32, 32, 16, {30, 0, -10}, 1.0f).empty());
}

TEST_CASE("bin_by_tile: counts, prefix sum and fill", "[tiles]") {
    const vkt::TileGrid grid{3, 2};
    const std::vector<vkt::TileRect> rects = {
        {0, 0, 1, 0},  // light 0: tiles 0, 1
        {},            // light 1: none
        {1, 0, 2, 1},  // light 2: tiles 1, 2, 4, 5
        {0, 1, 0, 1},  // light 3: tile 3
    };
    const vkt::Bins bins = vkt::bin_by_tile(rects, grid);
    CHECK(bins.counts == std::vector<uint32_t>{1, 2, 1, 1, 1, 1});
    CHECK(bins.offsets == std::vector<uint32_t>{0, 1, 3, 4, 5, 6});
    CHECK(bins.lights == std::vector<uint32_t>{0, 0, 2, 2, 3, 2, 2});
}

TEST_CASE("culling the bins keeps exactly what culling every light keeps", "[tiles]") {
    const vkt::TileGrid grid = vkt::tile_grid(wide_w, wide_h, tile);
    const std::vector<Sphere> spheres = random_spheres(2000, 17);
    std::vector<vkt::TileRect> rects;
    for (const Sphere& s : spheres)
        rects.push_back(vkt::light_tile_rect(wide, wide_w, wide_h, tile, s.centre, s.radius));
    const vkt::Bins bins = vkt::bin_by_tile(rects, grid);
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    uint64_t kept = 0, candidates = 0;
    for (uint32_t ty = 0; ty < grid.y; ++ty)
        for (uint32_t tx = 0; tx < grid.x; ++tx) {
            // Each tile a depth range of its own, as the G-buffer would give.
            const float near = 0.1f + 20.0f * unit(random), far = near + 8.0f * unit(random);
            const vkt::TileFrustum f =
                vkt::tile_frustum(wide, wide_w, wide_h, tx, ty, tile, near, far);
            std::vector<uint32_t> brute, binned;
            for (uint32_t i = 0; i < spheres.size(); ++i)
                if (vkt::sphere_touches_tile(f, spheres[i].centre, spheres[i].radius))
                    brute.push_back(i);
            const uint32_t t = ty * grid.x + tx;
            for (uint32_t k = 0; k < bins.counts[t]; ++k) {
                const uint32_t i = bins.lights[bins.offsets[t] + k];
                if (vkt::sphere_touches_tile(f, spheres[i].centre, spheres[i].radius))
                    binned.push_back(i);
            }
            REQUIRE(binned == brute);  // both in light order on the CPU
            kept += brute.size();
            candidates += bins.counts[t];
        }
    CHECK(kept > 500);
    CHECK(candidates < uint64_t(spheres.size()) * grid.count() / 4);  // binning culled most
}

TEST_CASE("MovingLights writes make_lights' lights, the phase reduced modulo 2 pi", "[tiles]") {
    // 70,000 lights take the threaded path; 1 and 1,000 the single thread.
    for (uint32_t count : {1u, 1000u, 70000u}) {
        const vkt::deferred::MovingLights moving(count);
        REQUIRE(moving.size() == count);
        REQUIRE(moving.homes().size() == count);
        REQUIRE(moving.paths().size() == count);
        for (const auto& path : moving.paths()) {
            REQUIRE(path.phase >= 0.0f);
            REQUIRE(path.phase < 6.2832f);
        }
        for (float t : {0.0f, 0.75f, 13.3f}) {
            const std::vector<vkt::PointLight> expected = vkt::deferred::make_lights(count, t);
            std::vector<vkt::PointLight> written(count);
            moving.write(t, written.data());
            // make_lights rounds its angle k + speed t to a float: half a unit
            // in the last place of the largest, on a circle of radius 0.6.
            const float largest = float(count) + 1.2f * t;
            const float ulp = std::nextafter(largest, 2.0f * largest + 1.0f) - largest;
            const float bound = 0.6f * (0.5f * ulp + 1e-5f) + 2e-6f;
            float worst = 0.0f;
            for (uint32_t i = 0; i < count; ++i) {
                const glm::vec3 d = written[i].position - expected[i].position;
                worst = std::max({worst, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
                REQUIRE(written[i].position.y == expected[i].position.y);
                REQUIRE(written[i].radius == expected[i].radius);
                REQUIRE(written[i].colour == expected[i].colour);
                REQUIRE(written[i].intensity == expected[i].intensity);
            }
            CAPTURE(count, t, worst, bound);
            REQUIRE(worst <= bound);
        }
    }
}
