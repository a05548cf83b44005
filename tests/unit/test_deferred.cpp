// Chapter 16's G-buffer on the CPU (vkt/scene/gbuffer.hpp): the octahedral normal
// encoding, positions from depth, the reference shading of a G-buffer (a
// light beyond its radius adds exactly nothing; lights add up), and the
// chapter's blocks (common/scene/include/vkt/scene/deferred_blocks.hpp) against the SPIR-V.
#include "spirv_reflect.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/deferred_blocks.hpp"
#include "vkt/scene/deferred_scene.hpp"
#include "vkt/scene/gbuffer.hpp"
#include "vkt/scene/lighting.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using Catch::Approx;

namespace {

std::string spv(const char* file) {
    return std::string(VKT_BINARY_DIR "/shaders/16_deferred/") + file + ".spv";
}

// What an R16G16_SNORM target stores for a value in [-1, 1].
int16_t snorm16(float v) {
    return int16_t(std::lround(std::clamp(v, -1.0f, 1.0f) * 32767.0f));
}

// A 1x1 G-buffer: one surface point, seen through `inverse_view_proj`.
vkt::GBufferTexels one_texel(glm::vec3 normal, uint8_t albedo, uint8_t specular, uint8_t shininess,
                             float depth) {
    const glm::vec2 e = vkt::oct_encode(glm::normalize(normal));
    return {1,
            1,
            {albedo, albedo, albedo, 255},
            {snorm16(e.x), snorm16(e.y)},
            {specular, shininess, 0, 0},
            {depth}};
}

}  // namespace

TEST_CASE("octahedral normals: every direction comes back", "[deferred]") {
    float worst = 0, worst_stored = 0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j <= 32; ++j) {
            const float phi = 2.0f * 3.14159265f * float(i) / 64.0f;
            const float theta = 3.14159265f * float(j) / 32.0f;  // poles included
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
            const glm::vec2 e = vkt::oct_encode(n);
            CHECK(std::abs(e.x) <= 1.0f);
            CHECK(std::abs(e.y) <= 1.0f);
            worst = std::max(worst, glm::length(vkt::oct_decode(e) - n));
            // As stored in R16G16_SNORM and read back: 16 bits per number.
            const glm::vec2 stored(vkt::snorm16_to_float(snorm16(e.x)),
                                   vkt::snorm16_to_float(snorm16(e.y)));
            worst_stored = std::max(worst_stored, glm::length(vkt::oct_decode(stored) - n));
        }
    CHECK(worst < 1e-6f);
    CHECK(worst_stored < 1e-4f);  // about 0.006 degrees
    // The axes land on the corners and the middle of the square.
    CHECK(vkt::oct_encode({0, 0, 1}) == glm::vec2(0, 0));
    CHECK(vkt::oct_encode({0, 0, -1}) == glm::vec2(1, 1));
    CHECK(vkt::oct_encode({1, 0, 0}) == glm::vec2(1, 0));
}

TEST_CASE("stored texels read back as the shaders read them", "[deferred]") {
    CHECK(vkt::srgb8_to_linear(0) == 0.0f);
    CHECK(vkt::srgb8_to_linear(255) == Approx(1.0f));
    CHECK(vkt::srgb8_to_linear(218) == Approx(0.7011f).margin(1e-4));  // the floor's albedo 0.7
    CHECK(vkt::unorm8_to_float(26) == Approx(26.0f / 255.0f));
    CHECK(vkt::snorm16_to_float(32767) == 1.0f);
    CHECK(vkt::snorm16_to_float(-32767) == -1.0f);
    CHECK(vkt::snorm16_to_float(-32768) == -1.0f);  // the one value below -1 reads as -1
}

TEST_CASE("a world position comes back from its depth", "[deferred]") {
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 6, 10), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 proj = vkt::vulkan_perspective(glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 100.0f);
    const glm::mat4 inverse = glm::inverse(proj * view);
    // Pixel (40, 170) of 320x240: project its centre at some depth to the
    // world, then check the world point projects back to that centre (within
    // 1e-4 of clip space, a hundredth of a pixel: float rounding of the
    // inverse matrix, amplified where depth is close to 1).
    const float depth = 0.995f;
    const glm::vec3 p = vkt::position_from_depth(inverse, 40, 170, 320, 240, depth);
    const glm::vec4 clip = proj * view * glm::vec4(p, 1.0f);
    CHECK(clip.x / clip.w == Approx((40.5f / 320.0f) * 2.0f - 1.0f).margin(1e-4));
    CHECK(clip.y / clip.w == Approx((170.5f / 240.0f) * 2.0f - 1.0f).margin(1e-4));
    CHECK(clip.z / clip.w == Approx(depth).margin(1e-6));
}

TEST_CASE("shade_gbuffer: out of reach adds exactly 0, and lights add up", "[deferred]") {
    // Looking straight down at the floor point (0, 0, 0) from (0, 4, 0).
    const glm::vec3 eye(0, 4, 0);
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 0, -1));
    const glm::mat4 proj = vkt::vulkan_perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f);
    const glm::mat4 inverse = glm::inverse(proj * view);
    const glm::vec4 clip = proj * view * glm::vec4(0, 0, 0, 1);
    const vkt::GBufferTexels texel = one_texel({0, 1, 0}, 218, 128, 32, clip.z / clip.w);
    const glm::vec3 ambient(0.03f), background(0.02f, 0.02f, 0.04f);
    auto shade = [&](std::span<const vkt::PointLight> lights, glm::vec3 ambient_light) {
        return vkt::shade_gbuffer(texel, inverse, eye, ambient_light, lights, background)[0];
    };
    const float albedo = vkt::srgb8_to_linear(218);

    // Radius 2, 2 away (exactly at the radius) and 3 away: nothing at all.
    const vkt::PointLight edge{.position = {2, 0.0f, 0}, .radius = 2.0f};
    const vkt::PointLight beyond{.position = {0, 3.0f, 0}, .radius = 2.0f, .intensity = 100.0f};
    const vkt::PointLight out_of_reach[] = {edge, beyond};
    CHECK(shade(out_of_reach, ambient) == ambient * albedo);
    CHECK(shade(out_of_reach, glm::vec3(0.0f)) == glm::vec3(0.0f));

    // Two sets of lights in reach: A alone plus B alone is A and B together.
    const vkt::PointLight a[] = {{.position = {0.5f, 1, 0}, .radius = 4, .colour = {1, 0.5f, 0.2f}},
                                 {.position = {-1, 2, 0.3f}, .radius = 5, .intensity = 2}};
    const vkt::PointLight b[] = {
        {.position = {0, 1.5f, -1}, .radius = 3, .colour = {0.2f, 0.4f, 1}}};
    const vkt::PointLight both[] = {a[0], a[1], b[0]};
    const glm::vec3 sum = shade(a, glm::vec3(0.0f)) + shade(b, glm::vec3(0.0f));
    const glm::vec3 together = shade(both, glm::vec3(0.0f));
    CHECK(together.x > 0.1f);
    for (int c = 0; c < 3; ++c) CHECK(sum[c] == Approx(together[c]).epsilon(1e-6));

    // Nothing drawn (depth 1): the background.
    vkt::GBufferTexels empty = texel;
    empty.depth[0] = 1.0f;
    CHECK(vkt::shade_gbuffer(empty, inverse, eye, ambient, both, background)[0] == background);
    // Arrays that do not match the size are refused.
    empty.normal.clear();
    CHECK_THROWS(vkt::shade_gbuffer(empty, inverse, eye, ambient, both, background));
}

TEST_CASE("chapter 16's FrameUniforms matches the shaders' std140 block", "[deferred][std140]") {
    using vkt::deferred::FrameUniforms;
    for (const char* file : {"scene.vert", "gbuffer.frag", "forward.frag", "lighting.frag"}) {
        const auto words = spirv::read(spv(file));
        const std::map<std::string, uint32_t> expected{
            {"view", offsetof(FrameUniforms, view)},
            {"proj", offsetof(FrameUniforms, proj)},
            {"inverse_view_proj", offsetof(FrameUniforms, inverse_view_proj)},
            {"camera_position", offsetof(FrameUniforms, camera_position)},
            {"light_count", offsetof(FrameUniforms, light_count)},
            {"ambient", offsetof(FrameUniforms, ambient)},
            {"depth_view_far", offsetof(FrameUniforms, depth_view_far)},
            {"materials", offsetof(FrameUniforms, materials)},
        };
        CHECK(spirv::offsets(words, "FrameUniforms") == expected);
        CHECK(spirv::struct_members(words, "FrameUniforms").at("materials").array_stride ==
              sizeof(vkt::deferred::Material));
        const std::map<std::string, uint32_t> material{
            {"albedo", offsetof(vkt::deferred::Material, albedo)},
            {"specular", offsetof(vkt::deferred::Material, specular)},
            {"shininess", offsetof(vkt::deferred::Material, shininess)},
        };
        CHECK(spirv::offsets(words, "Material") == material);
    }
}

TEST_CASE("chapter 16's lights, object and lighting push constants match the SPIR-V",
          "[deferred][std140]") {
    // The storage buffer: std430, an array of 32-byte PointLights.
    for (const char* file : {"forward.frag", "lighting.frag"}) {
        const auto words = spirv::read(spv(file));
        CHECK(spirv::struct_members(words, "Lights").at("lights").array_stride ==
              sizeof(vkt::PointLight));
    }
    const auto vert = spirv::read(spv("scene.vert"));
    const std::map<std::string, uint32_t> object{
        {"model", offsetof(vkt::deferred::ObjectPush, model)},
        {"normal_matrix", offsetof(vkt::deferred::ObjectPush, normal_matrix)},
        {"material", offsetof(vkt::deferred::ObjectPush, material)},
    };
    CHECK(spirv::offsets(vert, "ObjectPush") == object);
    CHECK(spirv::struct_members(vert, "ObjectPush").at("normal_matrix").matrix_stride == 16);
    CHECK(vkt::deferred::object_push_size == offsetof(vkt::deferred::ObjectPush, material) + 4);

    const auto frag = spirv::read(spv("lighting.frag"));
    const std::map<std::string, uint32_t> lighting{
        {"view", offsetof(vkt::deferred::LightingPush, view)},
        {"first_light", offsetof(vkt::deferred::LightingPush, first_light)},
        {"light_count", offsetof(vkt::deferred::LightingPush, light_count)},
        {"ambient", offsetof(vkt::deferred::LightingPush, ambient)},
    };
    CHECK(spirv::offsets(frag, "LightingPush") == lighting);
}

namespace {

// The colour chapters 16 and 17 give the bare floor at pixel (x, y) of a
// 320x240 frame at time t under `count` lights, worked out on the CPU: the
// ray through the pixel's centre meets the floor plane y = 0 (normal +y),
// shaded with vkt::shade, the floor's material, and the albedo as the
// G-buffer keeps it (0.7 stored sRGB-encoded as 218, read back as 0.7011).
// sRGB-encoded bytes, as the chapters' _SRGB target stores them.
glm::ivec3 floor_pixel(int x, int y, uint32_t count, float t) {
    namespace d = vkt::deferred;
    const glm::mat4 clip_from_world =
        vkt::vulkan_perspective(glm::radians(45.0f), 320.0f / 240.0f, 0.1f, 100.0f) *
        glm::lookAt(d::eye, glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0));
    const glm::mat4 world_from_clip = glm::inverse(clip_from_world);
    const glm::vec2 ndc(2.0f * (float(x) + 0.5f) / 320.0f - 1.0f,
                        2.0f * (float(y) + 0.5f) / 240.0f - 1.0f);
    const glm::vec4 a = world_from_clip * glm::vec4(ndc, 0, 1);
    const glm::vec4 b = world_from_clip * glm::vec4(ndc, 1, 1);
    const glm::vec3 origin = glm::vec3(a) / a.w, dir = glm::vec3(b) / b.w - origin;
    const glm::vec3 point = origin - (origin.y / dir.y) * dir;
    const d::Material floor = d::make_materials()[0];
    const float albedo = std::pow((218.0f / 255.0f + 0.055f) / 1.055f, 2.4f);
    const vkt::LightingParams params{
        .ambient = glm::vec3(0.03f), .specular = floor.specular, .shininess = floor.shininess};
    const glm::vec3 c =
        vkt::shade(point, {0, 1, 0}, glm::vec3(albedo), d::eye, d::make_lights(count, t), params);
    const auto encode = [](float l) {
        l = std::clamp(l, 0.0f, 1.0f);
        return int(std::lround(
            255.0f * (l <= 0.0031308f ? 12.92f * l : 1.055f * std::pow(l, 1 / 2.4f) - 0.055f)));
    };
    return {encode(c.x), encode(c.y), encode(c.z)};
}

}  // namespace

TEST_CASE("chapters 16 and 17: lit floor pixels shaded on the CPU", "[deferred]") {
    // The numbers tests/chapters/16_deferred.cmake and 17_tiled_deferred.cmake
    // check in the chapters' pictures at frame 9 (16: 32 lights; 17: 1,024).
    // Over a grid of 3,078 bare floor pixels of 16's golden image this
    // reference gives 2,362 exactly and the rest within 1 (the G-buffer's
    // rounding); of 17's, 2,471 exactly and 607 within 1.
    const float t = 9.0f / 60.0f;
    CHECK(floor_pixel(234, 165, 32, t) == glm::ivec3(242, 94, 188));     // 16: a pink pool
    CHECK(floor_pixel(159, 156, 32, t) == glm::ivec3(125, 194, 193));    // 16: a cyan one
    CHECK(floor_pixel(63, 153, 1024, t) == glm::ivec3(207, 174, 187));   // 17
    CHECK(floor_pixel(117, 192, 1024, t) == glm::ivec3(180, 163, 155));  // 17
}
