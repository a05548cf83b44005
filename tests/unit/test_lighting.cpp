// Chapter 12's lighting model (vkt/scene/lighting.hpp) on hand-worked values, its
// shapes' windings and normals, and its blocks' C++ mirrors
// (chapters/12_lighting/blocks.hpp) against the offsets in the compiled SPIR-V.
#include "../../chapters/12_lighting/blocks.hpp"
#include "../../chapters/12_lighting/scene.hpp"
#include "spirv_reflect.hpp"
#include "vkt/scene/lighting.hpp"
#include "vkt/scene/meshes.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using Catch::Approx;

namespace {

const float root_half = std::sqrt(0.5f);  // cos 45 degrees = sqrt(2)/2

std::string spv(const char* file) {
    return std::string(VKT_BINARY_DIR "/shaders/12_lighting/") + file + ".spv";
}

}  // namespace

TEST_CASE("classic attenuation is 1 / (c + l d + q d^2)", "[lighting]") {
    const vkt::Attenuation k{1.0f, 0.5f, 0.25f};
    CHECK(vkt::attenuation_classic(0.0f, k) == Approx(1.0f));
    CHECK(vkt::attenuation_classic(2.0f, k) == Approx(1.0f / 3.0f));  // 1 + 1 + 1
    CHECK(vkt::attenuation_classic(4.0f, k) == Approx(1.0f / 7.0f));  // 1 + 2 + 4
    CHECK(vkt::attenuation_classic(3.0f, {1.0f, 0.0f, 1.0f}) == Approx(0.1f));
    // The chapter's coefficients (1, 0.35, 0.44) at 2: 1 / (1 + 0.7 + 1.76).
    CHECK(vkt::attenuation_classic(2.0f, {1.0f, 0.35f, 0.44f}) == Approx(1.0f / 3.46f));
    // Never zero, however far.
    CHECK(vkt::attenuation_classic(1000.0f, k) > 0.0f);
}

TEST_CASE("windowed attenuation: (1 - (d/r)^4)^2 / (d^2 + 1), exactly 0 from the radius on",
          "[lighting]") {
    const float r = 4.0f;
    CHECK(vkt::attenuation_windowed(0.0f, r) == 1.0f);
    // d = 1: (1 - 1/256)^2 / 2 = 65025 / 131072.
    CHECK(vkt::attenuation_windowed(1.0f, r) == Approx(65025.0 / 131072.0));
    // d = 2: (1 - 1/16)^2 / 5 = (225/256) / 5 = 45/256.
    CHECK(vkt::attenuation_windowed(2.0f, r) == Approx(45.0 / 256.0));
    CHECK(vkt::attenuation_windowed(4.0f, r) == 0.0f);
    CHECK(vkt::attenuation_windowed(4.5f, r) == 0.0f);
    CHECK(vkt::attenuation_windowed(100.0f, r) == 0.0f);
    // Just inside the radius it is small but not zero, and it only falls.
    CHECK(vkt::attenuation_windowed(3.99f, r) > 0.0f);
    float previous = 2.0f;
    for (float d = 0.0f; d <= 5.0f; d += 0.125f) {
        const float a = vkt::attenuation_windowed(d, r);
        CHECK(a <= previous);
        CHECK(a <= 1.0f / (d * d + 1.0f));  // never above the plain inverse square
        previous = a;
    }
}

TEST_CASE("Lambert is the cosine between the normal and the light, 0 from behind", "[lighting]") {
    const glm::vec3 n(0, 1, 0);
    CHECK(vkt::lambert(n, {0, 1, 0}) == Approx(1.0f));
    CHECK(vkt::lambert(n, glm::normalize(glm::vec3(1, 1, 0))) == Approx(root_half));
    CHECK(vkt::lambert(n, glm::normalize(glm::vec3(0, 1, std::sqrt(3.0f)))) == Approx(0.5f));
    CHECK(vkt::lambert(n, {1, 0, 0}) == 0.0f);   // grazing
    CHECK(vkt::lambert(n, {0, -1, 0}) == 0.0f);  // from below: no negative light
}

TEST_CASE("Blinn-Phong peaks when the half vector is the normal", "[lighting]") {
    const glm::vec3 n(0, 1, 0);
    // Light at 45 degrees on one side, viewer at 45 degrees on the other:
    // the mirror direction, h = n, the full highlight whatever the exponent.
    const glm::vec3 l = glm::normalize(glm::vec3(1, 1, 0));
    const glm::vec3 v = glm::normalize(glm::vec3(-1, 1, 0));
    CHECK(vkt::blinn_phong(n, l, v, 1.0f) == Approx(1.0f));
    CHECK(vkt::blinn_phong(n, l, v, 128.0f) == Approx(1.0f));
    // Light straight above, viewer along the surface: h at 45 degrees,
    // n.h = sqrt(2)/2, so the term is 1/2 with exponent 2 and 1/4 with 4.
    CHECK(vkt::blinn_phong(n, {0, 1, 0}, {1, 0, 0}, 2.0f) == Approx(0.5f));
    CHECK(vkt::blinn_phong(n, {0, 1, 0}, {1, 0, 0}, 4.0f) == Approx(0.25f));
    // Light and viewer on the same side at 45 degrees: h = l, n.h = sqrt(2)/2.
    CHECK(vkt::blinn_phong(n, l, l, 2.0f) == Approx(0.5f));
    // A light behind the surface gives no highlight, even where h is near n.
    CHECK(vkt::blinn_phong(n, {0, -1, 0}, {0, 1, 0}, 8.0f) == 0.0f);
    CHECK(vkt::blinn_phong(n, glm::normalize(glm::vec3(1, -0.1f, 0)), {0, 1, 0}, 8.0f) == 0.0f);
}

TEST_CASE("the normal matrix keeps normals perpendicular under a non-uniform scale", "[lighting]") {
    // Scale x by 2. The plane x + y = 1 has normal (1, 1, 0)/sqrt2; scaled, it
    // is X/2 + Y = 1, i.e. X + 2Y = 2, whose normal is (1, 2, 0)/sqrt5.
    const glm::mat4 model = glm::scale(glm::mat4(1.0f), {2.0f, 1.0f, 1.0f});
    const glm::mat3 normals = vkt::normal_matrix(model);
    CHECK(normals[0][0] == Approx(0.5f));  // diag(1/2, 1, 1)
    CHECK(normals[1][1] == Approx(1.0f));
    CHECK(normals[2][2] == Approx(1.0f));
    const glm::vec3 n = glm::normalize(normals * glm::normalize(glm::vec3(1, 1, 0)));
    const float root5 = std::sqrt(5.0f);
    CHECK(n.x == Approx(1.0f / root5));
    CHECK(n.y == Approx(2.0f / root5));
    CHECK(n.z == Approx(0.0f).margin(1e-7));
    // A direction within the surface, (1, -1, 0), becomes (2, -1, 0): still
    // perpendicular to the new normal, but not to model * normal, (2, 1, 0).
    const glm::vec3 tangent = glm::mat3(model) * glm::vec3(1, -1, 0);
    CHECK(glm::dot(tangent, n) == Approx(0.0f).margin(1e-6));
    const glm::vec3 wrong = glm::normalize(glm::mat3(model) * glm::vec3(1, 1, 0));
    CHECK(glm::dot(tangent, wrong) == Approx(3.0f / root5));
    // For a rotation the normal matrix is the rotation itself.
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    const glm::mat3 same = vkt::normal_matrix(turn);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) CHECK(same[c][r] == Approx(turn[c][r]).margin(1e-6));
}

TEST_CASE("shade: ambient alone beyond the windowed radius", "[lighting]") {
    const vkt::PointLight light{.position = {0, 5, 0}, .radius = 4.0f, .colour = {1, 1, 1}};
    const glm::vec3 colour =
        vkt::shade({0, 0, 0}, {0, 1, 0}, glm::vec3(0.5f), {0, 2, 2}, {&light, 1});
    CHECK(colour.x == Approx(0.015f));  // ambient 0.03 times albedo 0.5
    CHECK(colour.y == Approx(0.015f));
    // Lights add: two equal lights give twice one light's share.
    const vkt::PointLight near{.position = {0, 1, 0}, .radius = 4.0f};
    const vkt::PointLight two[] = {near, near};
    const glm::vec3 one_light =
        vkt::shade({0, 0, 0}, {0, 2, 0}, glm::vec3(0.5f), {0, 2, 2}, {&near, 1});
    const glm::vec3 two_lights = vkt::shade({0, 0, 0}, {0, 1, 0}, glm::vec3(0.5f), {0, 2, 2}, two);
    CHECK(two_lights.x - 0.015f == Approx(2.0f * (one_light.x - 0.015f)));
}

// The centre pixel of chapter 12 run with --lights 1 --shading fragment
// (tests/chapters/12_lighting.cmake checks the GPU's answer). Frame 9,
// t = 0.15 s: light 0 is at (0, 1.5 + 0.5 sin 0.3, -cos 0.12) =
// (0, 1.647760, -0.992809), warm white (1, 0.85, 0.65) times 3, radius 6.
// The floor point (0, 0, 0), normal (0, 1, 0), albedo 0.7, seen from
// (0, 5, 10). By hand:
//   d = sqrt(1.647760^2 + 0.992809^2) = 1.923742
//   l = (0, 0.856539, -0.516082): Lambert 0.856539
//   v = (0, 5, 10) / sqrt(125) = (0, 1, 2) / sqrt(5) = (0, 0.447214, 0.894427)
//   h = normalize(l + v) = (0, 0.960379, 0.278699): n.h^32 = 0.274257
//   window (1 - (d/6)^4)^2 = 0.978976, attenuation 0.978976 / (d^2 + 1) = 0.208258
//   colour = 0.03 * 0.7 + 0.208258 * 3 * (1, 0.85, 0.65) * (0.7 * 0.856539 + 0.5 * 0.274257)
//          = 0.021 + 0.460275 * (1, 0.85, 0.65) = (0.481275, 0.412234, 0.320179)
TEST_CASE("shade: chapter 12's centre pixel, worked by hand", "[lighting]") {
    const float t = 9.0f / 60.0f;
    const vkt::PointLight light{
        .position = {0.0f, 1.5f + 0.5f * std::sin(2.0f * t), -std::cos(0.8f * t)},
        .radius = 6.0f,
        .colour = {1.0f, 0.85f, 0.65f},
        .intensity = 3.0f};
    const glm::vec3 colour =
        vkt::shade({0, 0, 0}, {0, 1, 0}, glm::vec3(0.7f), {0.0f, 5.0f, 10.0f}, {&light, 1});
    CHECK(colour.x == Approx(0.481275f).epsilon(1e-4));
    CHECK(colour.y == Approx(0.412234f).epsilon(1e-4));
    CHECK(colour.z == Approx(0.320179f).epsilon(1e-4));
    // With the classic falloff (1, 0.35, 0.44): 1 / (1 + 0.35 d + 0.44 d^2) = 0.302879.
    const vkt::LightingParams classic{.falloff = vkt::Falloff::classic,
                                      .classic = {1.0f, 0.35f, 0.44f}};
    const glm::vec3 c2 = vkt::shade({0, 0, 0}, {0, 1, 0}, glm::vec3(0.7f), {0.0f, 5.0f, 10.0f},
                                    {&light, 1}, classic);
    CHECK(c2.x == Approx(0.021f + 0.302879f * 3.0f * 0.736706f).epsilon(1e-4));
}

TEST_CASE("chapter 12's shapes are wound counter-clockwise seen from outside", "[lighting]") {
    vkt::shapes::MeshBuilder builder;
    const vkt::shapes::MeshRange ranges[] = {builder.floor(4), builder.cube(),
                                             builder.sphere(10, 6), builder.cylinder(12),
                                             builder.torus(16, 8, 0.15f)};
    for (const auto& range : ranges) {
        REQUIRE(range.index_count % 3 == 0);
        for (uint32_t i = range.first_index; i < range.first_index + range.index_count; i += 3) {
            const vkt::shapes::Vertex& a = builder.vertices[builder.indices[i]];
            const vkt::shapes::Vertex& b = builder.vertices[builder.indices[i + 1]];
            const vkt::shapes::Vertex& c = builder.vertices[builder.indices[i + 2]];
            const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
            REQUIRE(glm::length(face) > 1e-6f);  // no triangle without area
            CHECK(glm::dot(face, a.normal + b.normal + c.normal) > 0.0f);
        }
    }
    for (const auto& vertex : builder.vertices) {
        CHECK(glm::length(vertex.normal) == Approx(1.0f));
        CHECK(glm::all(glm::lessThanEqual(glm::abs(vertex.position), glm::vec3(0.5f + 1e-6f))));
    }
}

TEST_CASE("chapter 12's SceneUniforms matches the shader's std140 block", "[lighting][std140]") {
    using ch12::SceneUniforms;
    for (const char* file : {"lit.vert", "lit.frag"}) {
        const auto words = spirv::read(spv(file));
        const std::map<std::string, uint32_t> expected{
            {"view", offsetof(SceneUniforms, view)},
            {"proj", offsetof(SceneUniforms, proj)},
            {"camera_position", offsetof(SceneUniforms, camera_position)},
            {"light_count", offsetof(SceneUniforms, light_count)},
            {"ambient", offsetof(SceneUniforms, ambient)},
            {"falloff", offsetof(SceneUniforms, falloff)},
            {"classic", offsetof(SceneUniforms, classic)},
            {"specular", offsetof(SceneUniforms, specular)},
            {"shininess", offsetof(SceneUniforms, shininess)},
            {"lights", offsetof(SceneUniforms, lights)},
        };
        CHECK(spirv::offsets(words, "SceneUniforms") == expected);
        // std140 by hand: the array of structs rounds up to 16 after shininess.
        const auto members = spirv::struct_members(words, "SceneUniforms");
        CHECK(members.at("lights").offset == 192);
        CHECK(members.at("lights").array_stride == sizeof(vkt::PointLight));
        CHECK(members.at("view").matrix_stride == 16);
        const std::map<std::string, uint32_t> light{
            {"position", offsetof(vkt::PointLight, position)},
            {"radius", offsetof(vkt::PointLight, radius)},
            {"colour", offsetof(vkt::PointLight, colour)},
            {"intensity", offsetof(vkt::PointLight, intensity)},
        };
        CHECK(spirv::offsets(words, "PointLight") == light);
    }
}

TEST_CASE("chapter 12's ObjectPush matches the shader's std430 push constants",
          "[lighting][std140]") {
    using ch12::ObjectPush;
    const auto words = spirv::read(spv("lit.vert"));
    const std::map<std::string, uint32_t> expected{
        {"model", offsetof(ObjectPush, model)},
        {"normal_matrix", offsetof(ObjectPush, normal_matrix)},
        {"albedo", offsetof(ObjectPush, albedo)},
        {"emissive", offsetof(ObjectPush, emissive)},
    };
    CHECK(spirv::offsets(words, "ObjectPush") == expected);
    // A mat3's columns are 16 bytes apart here, not glm::mat3's 12.
    CHECK(spirv::struct_members(words, "ObjectPush").at("normal_matrix").matrix_stride == 16);
}

TEST_CASE("the SPIR-V reader refuses what is not SPIR-V", "[lighting]") {
    CHECK_THROWS(spirv::read(VKT_BINARY_DIR "/no-such-file.spv"));
    CHECK_THROWS(spirv::read(VKT_SOURCE_DIR "/shaders/12_lighting/lit.vert"));  // GLSL text
    const auto words = spirv::read(spv("lit.frag"));
    CHECK_THROWS(spirv::offsets(words, "NoSuchBlock"));
}

namespace {

// Chapter 12's colour at pixel (x, y) of a 320x240 frame at time t, worked out
// on the CPU: the ray through the pixel's centre meets the nearest triangle
// of the given object's mesh (the very triangles the chapter draws), whose
// vertices' positions and normals are interpolated there (a ray's barycentrics
// in world space are the rasteriser's perspective-correct ones), the normals
// turned by `normals`; then vkt::shade with the chapter's lights.
struct CpuPixel {
    bool hit = false;
    glm::vec3 linear{0.0f};
};
CpuPixel shade_pixel(int x, int y, float t, size_t object_index, bool inverse_transpose) {
    vkt::shapes::MeshBuilder builder;
    vkt::shapes::MeshRange meshes[ch12::mesh_count];
    ch12::build_meshes(builder, meshes);
    const ch12::Object object = ch12::make_objects(t)[object_index];
    const glm::mat4 clip_from_world =
        vkt::vulkan_perspective(glm::radians(45.0f), 320.0f / 240.0f, 0.1f, 100.0f) *
        glm::lookAt(ch12::eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const glm::mat4 world_from_clip = glm::inverse(clip_from_world);
    const glm::vec2 ndc(2.0f * (float(x) + 0.5f) / 320.0f - 1.0f,
                        2.0f * (float(y) + 0.5f) / 240.0f - 1.0f);
    const glm::vec4 near_point = world_from_clip * glm::vec4(ndc, 0.0f, 1.0f);
    const glm::vec4 far_point = world_from_clip * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 origin = glm::vec3(near_point) / near_point.w;
    const glm::vec3 dir = glm::normalize(glm::vec3(far_point) / far_point.w - origin);
    const glm::mat3 normals =
        inverse_transpose ? vkt::normal_matrix(object.model) : glm::mat3(object.model);
    const vkt::shapes::MeshRange range = meshes[object.mesh];
    CpuPixel out;
    float nearest = 1e30f;
    for (uint32_t i = 0; i < range.index_count; i += 3) {
        glm::vec3 p[3], n[3];
        for (uint32_t k = 0; k < 3; ++k) {
            const vkt::shapes::Vertex& v =
                builder.vertices[builder.indices[range.first_index + i + k]];
            p[k] = glm::vec3(object.model * glm::vec4(v.position, 1.0f));
            n[k] = normals * v.normal;
        }
        const glm::vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], q = glm::cross(dir, e2);
        const float det = glm::dot(e1, q);
        if (std::abs(det) < 1e-12f) continue;
        const glm::vec3 s = origin - p[0], r = glm::cross(s, e1);
        const float u = glm::dot(s, q) / det, v = glm::dot(dir, r) / det, d = glm::dot(e2, r) / det;
        if (u < 0 || v < 0 || u + v > 1 || d <= 0 || d >= nearest) continue;
        nearest = d;
        const glm::vec3 position = (1 - u - v) * p[0] + u * p[1] + v * p[2];
        const glm::vec3 normal = (1 - u - v) * n[0] + u * n[1] + v * n[2];
        const std::vector<vkt::PointLight> lights = ch12::make_lights(5, t);
        out = {true, vkt::shade(position, normal, object.albedo, ch12::eye, lights)};
    }
    return out;
}

int srgb_byte(float linear) {
    const float l = std::clamp(linear, 0.0f, 1.0f);
    const float s = l <= 0.0031308f ? 12.92f * l : 1.055f * std::pow(l, 1 / 2.4f) - 0.055f;
    return int(std::lround(s * 255.0f));
}

}  // namespace

TEST_CASE("chapter 12's squashed sphere: its pixel (174, 88) shaded on the CPU", "[lighting]") {
    // tests/chapters/12_lighting.cmake checks this pixel of the chapter's
    // picture (frame 9, per fragment on the right half) with the numbers
    // below: with the inverse transpose the normals stay perpendicular to the
    // squashed surface and the top of the ellipsoid, facing the lights, is
    // bright green; turned by the model matrix itself they lean towards the
    // flattened axis and the same point is a dull grey, 150 levels darker.
    // Over the 517 pixels of the ellipsoid's right half this reference gives
    // lavapipe's colour exactly for 418 and within 1 for the rest, both ways.
    const float t = 9.0f / 60.0f;
    const CpuPixel right = shade_pixel(174, 88, t, 1, true);
    const CpuPixel wrong = shade_pixel(174, 88, t, 1, false);
    REQUIRE(right.hit);
    CHECK(srgb_byte(right.linear.x) == 207);
    CHECK(srgb_byte(right.linear.y) == 238);
    CHECK(srgb_byte(right.linear.z) == 182);
    CHECK(srgb_byte(wrong.linear.x) == 83);
    CHECK(srgb_byte(wrong.linear.y) == 86);
    CHECK(srgb_byte(wrong.linear.z) == 84);
    // The object is the squashed sphere, scaled (2.6, 0.9, 1.3): non-uniform.
    const ch12::Object ellipsoid = ch12::make_objects(t)[1];
    CHECK(ellipsoid.mesh == ch12::sphere_mesh);
    CHECK(glm::length(glm::vec3(ellipsoid.model[0])) == Approx(2.6f));
    CHECK(glm::length(glm::vec3(ellipsoid.model[1])) == Approx(0.9f));
}
