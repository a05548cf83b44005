// vkt/scene/pbr.hpp (chapter 23): the BRDF's properties the page derives, the
// white furnace on the CPU, the ACES curve; and the glTF loader's
// metallic-roughness materials on assets/gltf/pbr_cubes.gltf.

#include "vkt/scene/gltf.hpp"
#include "vkt/scene/pbr.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <filesystem>

using Catch::Approx;
namespace pbr = vkt::pbr;

namespace {

glm::vec3 direction(float theta, float phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace

TEST_CASE("pbr: GGX's D is a distribution of normals: its projected integral is 1", "[pbr]") {
    for (float alpha : {0.1f, 0.5f, 1.0f}) {
        // The integral of D(h) (n.h) over the hemisphere, by theta (fine
        // steps where a small alpha makes D a narrow peak) and phi.
        double sum = 0.0;
        const int steps = 20000;
        for (int i = 0; i < steps; ++i) {
            const double theta = (i + 0.5) / steps * (std::numbers::pi / 2);
            sum += pbr::distribution_ggx(float(std::cos(theta)), alpha) * std::cos(theta) *
                   std::sin(theta) * (std::numbers::pi / 2 / steps) * 2 * std::numbers::pi;
        }
        CHECK(sum == Approx(1.0).epsilon(0.01));
    }
}

TEST_CASE("pbr: Schlick's Fresnel is F0 head on and 1 at grazing", "[pbr]") {
    const glm::vec3 f0(0.04f, 0.5f, 0.9f);
    CHECK(pbr::fresnel_schlick(f0, 1.0f) == f0);
    CHECK(pbr::fresnel_schlick(f0, 0.0f) == glm::vec3(1.0f));
}

TEST_CASE("pbr: the BRDF is reciprocal: swapping the eye and the light changes nothing", "[pbr]") {
    const glm::vec3 n(0, 0, 1), a = direction(0.4f, 0.3f), b = direction(1.1f, 2.5f);
    for (float roughness : {0.2f, 0.6f, 1.0f})
        for (float metallic : {0.0f, 1.0f}) {
            const pbr::Material m{{0.9f, 0.6f, 0.3f}, metallic, roughness};
            const glm::vec3 ab = pbr::brdf_cos(n, a, b, m) / b.z,
                            ba = pbr::brdf_cos(n, b, a, m) / a.z;
            for (int c = 0; c < 3; ++c) CHECK(ab[c] == Approx(ba[c]).epsilon(1e-4));
        }
}

TEST_CASE("pbr: the white furnace: white, rough, not metal, under a sky of 1, is within 3% of 1",
          "[pbr]") {
    const glm::vec3 n(0, 0, 1);
    const pbr::Material white{glm::vec3(1.0f), 0.0f, 1.0f};
    for (float theta : {0.0f, 0.5f, 1.0f, 1.2f}) {  // n.v 1, 0.88, 0.54, 0.36
        const glm::vec3 v = direction(theta, 0.0f);
        const glm::vec3 e64 = pbr::environment(n, v, white, glm::vec3(1.0f), 64);
        const glm::vec3 e4096 = pbr::environment(n, v, white, glm::vec3(1.0f), 4096);
        CHECK(e64.g == Approx(1.0f).margin(0.03));
        // The chapter's 64 samples per lobe against 4096: well within 1%.
        CHECK(e64.g == Approx(e4096.g).margin(0.01));
    }
    // A black sphere sends nothing back but its Fresnel reflection.
    const glm::vec3 black = pbr::environment(n, n, {glm::vec3(0.0f), 0.0f, 1.0f}, glm::vec3(1), 64);
    CHECK(black.g < 0.1f);
}

// The integral of brdf_cos over the hemisphere by brute force: a grid of
// directions in theta and phi.
glm::vec3 integral(glm::vec3 v, const pbr::Material& m) {
    const int steps = 300;
    const float dt = pbr::pi / 2 / steps, dp = 2 * pbr::pi / steps;
    glm::vec3 sum(0.0f);
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const float theta = (float(i) + 0.5f) * dt, phi = (float(j) + 0.5f) * dp;
            sum +=
                pbr::brdf_cos({0, 0, 1}, v, direction(theta, phi), m) * std::sin(theta) * dt * dp;
        }
    return sum;
}

// The chapter's 64 fixed samples per lobe: within 4% (the worst case here is 3.2% off,
// at a grazing n.v of 0.54).
TEST_CASE("pbr: the sampled sky matches the brute-force integral of the BRDF", "[pbr]") {
    const glm::vec3 n(0, 0, 1);
    for (float theta : {0.3f, 1.0f})
        for (float roughness : {0.5f, 1.0f})
            for (float metallic : {0.0f, 1.0f}) {
                const pbr::Material m{{0.9f, 0.6f, 0.3f}, metallic, roughness};
                const glm::vec3 v = direction(theta, 0.0f);
                const glm::vec3 sampled = pbr::environment(n, v, m, glm::vec3(1.0f), 64);
                const glm::vec3 brute = integral(v, m);
                for (int c = 0; c < 3; ++c) CHECK(sampled[c] == Approx(brute[c]).epsilon(0.04));
            }
}

TEST_CASE("pbr: a smooth white metal reflects the whole sky; a rough one loses much", "[pbr]") {
    const glm::vec3 n(0, 0, 1), v = direction(0.3f, 0.0f);
    const glm::vec3 smooth =
        pbr::environment(n, v, {glm::vec3(1.0f), 1.0f, 0.1f}, glm::vec3(1), 64);
    const glm::vec3 rough = pbr::environment(n, v, {glm::vec3(1.0f), 1.0f, 1.0f}, glm::vec3(1), 64);
    CHECK(smooth.g == Approx(1.0f).margin(0.02));
    // Single scattering: light that would bounce more than once between
    // microfacets is lost; at roughness 1 about two thirds of it (a
    // brute-force integral gives 0.316 here).
    CHECK(rough.g == Approx(0.316f).margin(0.01));
}

// The split sum's BRDF table (chapter 23's image-based light): F0 A + B is
// the share of the light the specular lobe reflects, so it must agree with
// the sampled sky's specular part, the same estimator, for any F0.
TEST_CASE("pbr: the BRDF table's F0 A + B is the specular lobe's share of a uniform sky", "[pbr]") {
    const glm::vec3 n(0, 0, 1);
    for (float theta : {0.3f, 1.0f, 1.3f})
        for (float roughness : {0.2f, 0.6f, 1.0f}) {
            const glm::vec3 v = direction(theta, 0.0f);
            const glm::vec2 ab = pbr::split_sum_lut(v.z, roughness, 64);
            // A white metal: F0 = 1, so the lobe reflects A + B. A black
            // dielectric: no diffuse part, F0 = 0.04.
            const glm::vec3 metal =
                pbr::environment(n, v, {glm::vec3(1.0f), 1.0f, roughness}, glm::vec3(1), 64);
            const glm::vec3 black =
                pbr::environment(n, v, {glm::vec3(0.0f), 0.0f, roughness}, glm::vec3(1), 64);
            CHECK(ab.x + ab.y == Approx(metal.g).margin(1e-4));
            CHECK(0.04f * ab.x + ab.y == Approx(black.g).margin(1e-4));
        }
    // At roughness 1 the white metal keeps 0.316 at theta 0.3 (the brute
    // force above): the table says the same.
    const glm::vec2 rough = pbr::split_sum_lut(std::cos(0.3f), 1.0f, 1024);
    CHECK(rough.x + rough.y == Approx(0.316f).margin(0.01));
}

TEST_CASE("pbr: the BRDF table of a mirror is Schlick's Fresnel at n.v", "[pbr]") {
    // Roughness 0: every half vector is n, l the mirror direction, and the
    // lobe reflects F(n.v) = F0 (1 - (1 - n.v)^5) + (1 - n.v)^5.
    for (float n_dot_v : {0.1f, 0.5f, 0.9f}) {
        const glm::vec2 ab = pbr::split_sum_lut(n_dot_v, 0.0f, 256);
        const float fc = std::pow(1.0f - n_dot_v, 5.0f);
        CHECK(ab.x == Approx(1.0f - fc).margin(0.01));
        CHECK(ab.y == Approx(fc).margin(0.01));
    }
}

TEST_CASE("pbr: the ACES fit rises from 0 to 1, past 0.8 at 1", "[pbr]") {
    CHECK(pbr::aces_narkowicz(0.0f) == 0.0f);
    CHECK(pbr::aces_narkowicz(1.0f) == Approx(0.8038f).margin(1e-3));
    CHECK(pbr::aces_narkowicz(100.0f) == Approx(1.0f).margin(2e-3));
    float last = 0.0f;
    for (float x = 0.01f; x < 4.0f; x *= 1.1f) {  // it reaches 1.0 past about 10
        CHECK(pbr::aces_narkowicz(x) > last);
        last = pbr::aces_narkowicz(x);
    }
}

TEST_CASE("gltf: the metallic-roughness materials, their five textures and TANGENT", "[gltf]") {
    const std::filesystem::path path =
        std::filesystem::path(VKT_SOURCE_DIR) / "assets/gltf/pbr_cubes.gltf";
    const vkt::GltfScene full =
        vkt::load_gltf(path, vkt::default_max_memory, vkt::GltfMaterials::metallic_roughness);
    CHECK(full.warnings.empty());
    REQUIRE(full.materials.size() == 1);
    const vkt::GltfMaterial& m = full.materials[0];
    CHECK(m.base_color_image == 0);
    CHECK(m.metallic_roughness_image == 1);
    CHECK(m.normal_image == 2);
    CHECK(m.occlusion_image == 3);
    CHECK(m.emissive_image == 4);
    CHECK(m.emissive_factor == glm::vec3(4.0f));
    CHECK(full.images.size() == 5);
    REQUIRE(full.primitives.size() == 2);
    // The first cube's vertices carry the file's TANGENT (w = +1); the
    // second's have none (w = 0: the shader makes its own).
    CHECK(full.vertices[full.primitives[0].first_vertex].tangent == glm::vec4(0, 0, -1, 1));
    CHECK(full.vertices[full.primitives[1].first_vertex].tangent == glm::vec4(0.0f));

    // Chapters 10-16 ask for the base colour only: the rest is named, not read.
    const vkt::GltfScene base = vkt::load_gltf(path);
    CHECK(base.materials[0].normal_image == -1);
    CHECK(base.images.size() == 1);
    REQUIRE(base.warnings.size() == 2);
    CHECK(base.warnings[0] ==
          "normal, occlusion, emissive and metallic-roughness textures are ignored (lighting is "
          "chapter 12's)");
    CHECK(base.warnings[1] == "attribute TANGENT is ignored");
}
