// vkt/scene/gltf.hpp (chapter 10): the glTF loader, on files these tests write
// themselves (JSON by hand, buffers byte by byte, a .glb container by hand).

#include "base64.hpp"
#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"
#include "vkt/scene/gltf.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

using Catch::Approx;
using Catch::Matchers::ContainsSubstring;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir() {
    const fs::path dir = fs::path(VKT_BINARY_DIR) / "test_gltf";
    fs::create_directories(dir);
    return dir;
}

void write_bytes(const fs::path& path, const void* data, size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), std::streamsize(size));
    REQUIRE(out.good());
}
void write_text(const fs::path& path, const std::string& text) {
    write_bytes(path, text.data(), text.size());
}
std::vector<uint8_t> bytes_of(const fs::path& path) {
    std::vector<char> file = vkt::read_file(path);
    return {file.begin(), file.end()};
}

// A buffer built up piece by piece; each piece starts 4-byte aligned.
struct Bin {
    std::vector<uint8_t> bytes;
    template <typename T>
    size_t add(const std::vector<T>& values) {
        while (bytes.size() % 4) bytes.push_back(0);
        const size_t offset = bytes.size();
        bytes.resize(offset + values.size() * sizeof(T));
        std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
        return offset;
    }
};

using vkt_test::base64;  // tests/unit/base64.hpp

std::string data_uri(const std::vector<uint8_t>& data,
                     const char* mime = "application/octet-stream") {
    return std::string("data:") + mime + ";base64," + base64(data);
}

// Replaces every `key` in `text` with `value`.
std::string fill(std::string text, const std::vector<std::pair<std::string, std::string>>& values) {
    for (const auto& [key, value] : values)
        for (size_t at = text.find(key); at != std::string::npos;
             at = text.find(key, at + value.size()))
            text.replace(at, key.size(), value);
    return text;
}

// One triangle: (0,0,0), (1,0,0), (0,1,0), and its three indices of
// `component_type` after the positions. The buffer is a data: URI.
struct Triangle {
    Bin bin;
    size_t index_offset = 0, index_bytes = 0;
    explicit Triangle(int component_type, std::vector<uint32_t> indices = {0, 1, 2}) {
        bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
        if (component_type == 5121) {
            index_offset = bin.add(std::vector<uint8_t>(indices.begin(), indices.end()));
            index_bytes = indices.size();
        } else if (component_type == 5123) {
            index_offset = bin.add(std::vector<uint16_t>(indices.begin(), indices.end()));
            index_bytes = 2 * indices.size();
        } else {
            index_offset = bin.add(indices);
            index_bytes = 4 * indices.size();
        }
    }
};

const char* triangle_json = R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0]}], "scene": 0,
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": $POSCOUNT, "type": "$POSTYPE"},
    {"bufferView": 1, "componentType": $ICT, "count": $ICOUNT, "type": "SCALAR"}
  ],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": 36},
    {"buffer": 0, "byteOffset": $IOFFSET, "byteLength": $IBYTES}
  ],
  "buffers": [{"byteLength": $BUFBYTES, "uri": "$URI"}]$EXTRA
})";

std::string triangle_file(const Triangle& t, int component_type, std::string extra = "",
                          std::string pos_count = "3", std::string pos_type = "VEC3") {
    const size_t count = t.index_bytes / (component_type == 5121   ? 1
                                          : component_type == 5123 ? 2
                                                                   : 4);
    return fill(triangle_json, {{"$POSCOUNT", pos_count},
                                {"$POSTYPE", pos_type},
                                {"$ICT", std::to_string(component_type)},
                                {"$ICOUNT", std::to_string(count)},
                                {"$IOFFSET", std::to_string(t.index_offset)},
                                {"$IBYTES", std::to_string(t.index_bytes)},
                                {"$BUFBYTES", std::to_string(t.bin.bytes.size())},
                                {"$URI", data_uri(t.bin.bytes)},
                                {"$EXTRA", extra}});
}

fs::path write_file(const std::string& name, const std::string& text) {
    const fs::path path = temp_dir() / name;
    write_text(path, text);
    return path;
}

void check_triangle(const vkt::GltfScene& scene) {
    REQUIRE(scene.vertices.size() == 3);
    CHECK(scene.indices == std::vector<uint32_t>{0, 1, 2});
    REQUIRE(scene.primitives.size() == 1);
    CHECK(scene.primitives[0].index_count == 3);
    REQUIRE(scene.draws.size() == 1);
    CHECK(scene.vertices[1].position == glm::vec3(1, 0, 0));
    CHECK(scene.vertices[2].position == glm::vec3(0, 1, 0));
    // No NORMAL: the flat normal of a counter-clockwise triangle in z = 0 is +z.
    CHECK(scene.vertices[0].normal == glm::vec3(0, 0, 1));
    CHECK(scene.bounds_min == glm::vec3(0, 0, 0));
    CHECK(scene.bounds_max == glm::vec3(1, 1, 0));
    // No material: glTF's default one, white.
    REQUIRE(scene.materials.size() == 1);
    CHECK(scene.materials[0].base_color_factor == glm::vec4(1));
    CHECK(scene.materials[0].base_color_image == -1);
}

// What load_gltf throws for `path`, or "" if it loads.
std::string error_of(const fs::path& path) {
    try {
        vkt::load_gltf(path);
    } catch (const vkt::Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("gltf: 8, 16 and 32-bit indices are widened to 32 bits", "[gltf]") {
    for (int type : {5121, 5123, 5125}) {
        INFO("componentType " << type);
        Triangle t(type);
        check_triangle(vkt::load_gltf(write_file("indices.gltf", triangle_file(t, type))));
    }
}

TEST_CASE("gltf: a non-indexed primitive draws its vertices in order", "[gltf]") {
    Triangle t(5125);
    std::string text = triangle_file(t, 5125);
    text = fill(text, {{R"(, "indices": 1)", ""}});
    check_triangle(vkt::load_gltf(write_file("non_indexed.gltf", text)));
}

TEST_CASE("gltf: strips and fans become triangle lists with the same winding", "[gltf]") {
    // Four vertices of a unit square, as a strip 0 1 2 3 and a fan 0 1 2 3.
    Bin bin;
    bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    const std::string base = fill(R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": $MODE}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"}],
      "bufferViews": [{"buffer": 0, "byteLength": 48}],
      "buffers": [{"byteLength": 48, "uri": "$URI"}]})",
                                  {{"$URI", data_uri(bin.bytes)}});
    // Strip: (0 1 2) and (2 1 3), both counter-clockwise; no NORMAL, so
    // flat-shaded vertices in that order.
    vkt::GltfScene strip = vkt::load_gltf(write_file("strip.gltf", fill(base, {{"$MODE", "5"}})));
    REQUIRE(strip.vertices.size() == 6);
    CHECK(strip.vertices[3].position == glm::vec3(0, 1, 0));
    CHECK(strip.vertices[4].position == glm::vec3(1, 0, 0));
    CHECK(strip.vertices[5].position == glm::vec3(1, 1, 0));
    for (const vkt::GltfVertex& v : strip.vertices) CHECK(v.normal == glm::vec3(0, 0, 1));
    // Fan: (0 1 2), (0 2 3).
    vkt::GltfScene fan = vkt::load_gltf(write_file("fan.gltf", fill(base, {{"$MODE", "6"}})));
    REQUIRE(fan.vertices.size() == 6);
    CHECK(fan.vertices[3].position == glm::vec3(0, 0, 0));
    CHECK(fan.vertices[5].position == glm::vec3(1, 1, 0));
    // Points are skipped, and then nothing is left to draw.
    // The error says why: what was skipped (found on real files, where the
    // warnings were never printed because the load failed).
    CHECK_THAT(error_of(write_file("points.gltf", fill(base, {{"$MODE", "0"}}))),
               ContainsSubstring("points.gltf: nothing to draw: no node of the scene has a mesh "
                                 "with triangles (points and lines are not supported"));
}

TEST_CASE("gltf: sparse vertex attributes replace the elements they name", "[gltf]") {
    // Like Khronos' SimpleSparseAccessor (which was refused before): the
    // POSITION accessor is the triangle (0,0,0) (1,0,0) (0,1,0), and its sparse
    // part replaces element 2 with (0,2,0).
    Bin bin;
    bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});  // 0..35: the base
    bin.add(std::vector<uint16_t>{2, 0});                    // 36..39: index 2 (+ pad)
    bin.add(std::vector<float>{0, 2, 0});                    // 40..51: its new value
    const std::string base = fill(R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "accessors": [{"bufferView": $BASE, "componentType": 5126, "count": 3, "type": "VEC3",
        "sparse": {"count": $COUNT, "indices": {"bufferView": 1, "componentType": 5123},
                   "values": {"bufferView": 2, "byteOffset": $VOFFSET}}}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 2},
                      {"buffer": 0, "byteOffset": 40, "byteLength": 12}],
      "buffers": [{"byteLength": 52, "uri": "$URI"}]})",
                                  {{"$URI", data_uri(bin.bytes)}});
    const auto file = [&](const char* view, const char* count, const char* offset) {
        return fill(base, {{"$BASE", view}, {"$COUNT", count}, {"$VOFFSET", offset}});
    };
    vkt::GltfScene scene = vkt::load_gltf(write_file("sparse.gltf", file("0", "1", "0")));
    REQUIRE(scene.vertices.size() == 3);
    CHECK(scene.vertices[0].position == glm::vec3(0, 0, 0));
    CHECK(scene.vertices[1].position == glm::vec3(1, 0, 0));
    CHECK(scene.vertices[2].position == glm::vec3(0, 2, 0));
    CHECK(scene.bounds_max == glm::vec3(1, 2, 0));
    CHECK(scene.warnings.empty());
    // Without a base view the other elements are zeros. (A view of -1 is no
    // index: tinygltf would take it for none, glTF allows 0 and up.)
    CHECK_THAT(error_of(write_file("sparse_minus_1.gltf", file("-1", "1", "0"))),
               ContainsSubstring("sparse_minus_1.gltf: accessor 0: \"bufferView\" is -1, which "
                                 "is no index: glTF's are whole numbers from 0 to 2147483647"));
    scene = vkt::load_gltf(write_file(
        "sparse_zeros.gltf",
        fill(file("0", "1", "0"),
             {{R"("bufferView": 0, "componentType": 5126)", R"("componentType": 5126)"}})));
    REQUIRE(scene.vertices.size() == 3);
    CHECK(scene.vertices[1].position == glm::vec3(0, 0, 0));
    CHECK(scene.vertices[2].position == glm::vec3(0, 2, 0));
    // Bad sparse parts are refused with one line.
    CHECK_THAT(error_of(write_file("sparse_bad.gltf", file("0", "2", "0"))),
               ContainsSubstring(
                   "sparse_bad.gltf: mesh 0 primitive 0 POSITION: accessor 0 (sparse): "
                   "indices (count 2, byteOffset 0) run past the end of bufferView 1 (2 bytes)"));
    CHECK_THAT(
        error_of(write_file("sparse_bad.gltf", file("0", "1", "4"))),
        ContainsSubstring("accessor 0 (sparse): values (count 1, byteOffset 4) run past the end "
                          "of bufferView 2 (12 bytes)"));
    CHECK_THAT(error_of(write_file("sparse_bad.gltf", file("0", "4", "0"))),
               ContainsSubstring("accessor 0 (sparse): count 4 is not between 1 and 3"));
    // An index past the accessor's end: element 7 of 3.
    Bin far = bin;
    far.bytes[36] = 7;
    CHECK_THAT(
        error_of(write_file("sparse_bad.gltf", fill(file("0", "1", "0"),
                                                    {{data_uri(bin.bytes), data_uri(far.bytes)}}))),
        ContainsSubstring(
            "accessor 0 (sparse): index 0 is 7, past the end of the accessor (3 elements)"));
    // Every number of the file made absurd: load or throw vkt::Error, never crash.
    const std::string text = file("0", "1", "0");
    const std::regex number(R"(-?\b[0-9]+\b)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
         it != std::sregex_iterator(); ++it) {
        if (size_t(it->position()) > text.find("base64,")) break;  // the data: URI and after
        for (const char* value : {"4000000000", "-1", "0", "2147483647", "65536"}) {
            std::string variant = text;
            variant.replace(size_t(it->position()), size_t(it->length()), value);
            INFO(variant);
            try {
                vkt::load_gltf(write_file("sparse_fuzz.gltf", variant));
            } catch (const vkt::Error&) {
            }
        }
    }
}

TEST_CASE("gltf: a file with nothing left to draw says what was skipped", "[gltf]") {
    // The triangle's indices made sparse: no exporter writes that, so its
    // primitive is skipped, and the one error line says so.
    Bin bin;
    bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    bin.add(std::vector<uint16_t>{0, 1, 2, 0});
    const std::string text = fill(R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR",
         "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123},
                    "values": {"bufferView": 1}}}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8}],
      "buffers": [{"byteLength": 44, "uri": "$URI"}]})",
                                  {{"$URI", data_uri(bin.bytes)}});
    CHECK_THAT(
        error_of(write_file("sparse_indices.gltf", text)),
        ContainsSubstring("sparse_indices.gltf: nothing to draw: no node of the scene has a mesh "
                          "with triangles (sparse index accessors are not supported: primitives "
                          "using one are skipped)"));
}

TEST_CASE("gltf: interleaved vertices (byteStride) and offsets (bufferView and accessor)",
          "[gltf]") {
    // 8 bytes of padding, then 3 vertices of position, normal and uv side by
    // side: 32 bytes each. The view starts at byte 8; the normals start at
    // accessor byteOffset 12, the uvs at 24. The 16-bit indices follow in a
    // view whose accessor skips its first two indices (byteOffset 4).
    Bin bin;
    bin.add(std::vector<float>{-1, -1});
    bin.add(std::vector<float>{0, 0, 0, 0, 0, 1, 0.25f, 0.5f,  //
                               2, 0, 0, 0, 0, 1, 0.75f, 0.5f,  //
                               0, 3, 0, 0, 0, 1, 0.25f, 1.0f});
    const size_t index_offset = bin.add(std::vector<uint16_t>{9, 9, 2, 1, 0, 0});
    const std::string text =
        fill(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
        {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 3, "type": "VEC3"},
        {"bufferView": 0, "byteOffset": 24, "componentType": 5126, "count": 3, "type": "VEC2"},
        {"bufferView": 1, "byteOffset": 4, "componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 8, "byteLength": 96, "byteStride": 32},
                      {"buffer": 0, "byteOffset": $IOFF, "byteLength": 12}],
      "buffers": [{"byteLength": $LEN, "uri": "interleaved.bin"}]})",
             {{"$IOFF", std::to_string(index_offset)}, {"$LEN", std::to_string(bin.bytes.size())}});
    write_bytes(temp_dir() / "interleaved.bin", bin.bytes.data(),
                bin.bytes.size());  // external buffer
    vkt::GltfScene scene = vkt::load_gltf(write_file("interleaved.gltf", text));
    REQUIRE(scene.vertices.size() == 3);
    CHECK(scene.vertices[1].position == glm::vec3(2, 0, 0));
    CHECK(scene.vertices[2].position == glm::vec3(0, 3, 0));
    CHECK(scene.vertices[2].normal == glm::vec3(0, 0, 1));
    CHECK(scene.vertices[1].uv == glm::vec2(0.75f, 0.5f));
    CHECK(scene.vertices[2].uv == glm::vec2(0.25f, 1.0f));
    CHECK(scene.indices == std::vector<uint32_t>{2, 1, 0});
    CHECK(scene.bounds_max == glm::vec3(2, 3, 0));
}

TEST_CASE("gltf: normalised unsigned byte texture coordinates", "[gltf]") {
    Bin bin;
    bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    const size_t uv_offset = bin.add(std::vector<uint8_t>{0, 255, 9, 9, 255, 0, 9, 9, 51, 102});
    const std::string text = fill(R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
        {"bufferView": 1, "componentType": 5121, "normalized": $NORM, "count": 3, "type": "VEC2"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": $UVOFF, "byteLength": 10, "byteStride": 4}],
      "buffers": [{"byteLength": $LEN, "uri": "$URI"}]})",
                                  {{"$UVOFF", std::to_string(uv_offset)},
                                   {"$LEN", std::to_string(bin.bytes.size())},
                                   {"$URI", data_uri(bin.bytes)}});
    vkt::GltfScene scene = vkt::load_gltf(write_file("uv8.gltf", fill(text, {{"$NORM", "true"}})));
    REQUIRE(scene.vertices.size() == 3);  // flat normals keep the triangle's order
    CHECK(scene.vertices[0].uv == glm::vec2(0, 1));
    CHECK(scene.vertices[2].uv.x == Approx(0.2));
    CHECK(scene.vertices[2].uv.y == Approx(0.4));
    // Not normalised: glTF does not allow unsigned bytes for TEXCOORD_0.
    CHECK_THAT(
        error_of(write_file("uv8.gltf", fill(text, {{"$NORM", "false"}}))),
        ContainsSubstring(
            "TEXCOORD_0: accessor 1 is VEC2 of UNSIGNED_BYTE, which glTF does not allow here"));
}

TEST_CASE("gltf: a hand-made .glb with its image in a bufferView", "[gltf]") {
    // The image: a 2x1 PNG from write_png.
    const fs::path png = temp_dir() / "glb_texture.png";
    vkt::write_png(png, {2, 1, {255, 0, 0, 255, 0, 0, 255, 255}});
    const std::vector<uint8_t> png_bytes = bytes_of(png);
    Triangle t(5123);
    const size_t image_offset = t.bin.add(png_bytes);
    while (t.bin.bytes.size() % 4) t.bin.bytes.push_back(0);
    std::string json = fill(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1], "baseColorTexture": {"index": 0}}}],
      "textures": [{"source": 0}],
      "images": [{"bufferView": 2, "mimeType": "image/png"}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": $IOFF, "byteLength": 6},
                      {"buffer": 0, "byteOffset": $PNGOFF, "byteLength": $PNGLEN}],
      "buffers": [{"byteLength": $LEN}]})",
                            {{"$IOFF", std::to_string(t.index_offset)},
                             {"$PNGOFF", std::to_string(image_offset)},
                             {"$PNGLEN", std::to_string(png_bytes.size())},
                             {"$LEN", std::to_string(t.bin.bytes.size())}});
    // The container: a 12-byte header, then chunks of (length, type, data).
    auto make_glb = [&](std::string json_chunk) {
        while (json_chunk.size() % 4) json_chunk += ' ';  // the JSON chunk is padded with spaces
        std::vector<uint8_t> glb;
        auto u32 = [&](uint32_t v) {
            for (int i = 0; i < 4; ++i) glb.push_back(uint8_t(v >> (8 * i)));
        };
        u32(0x46546C67);  // "glTF"
        u32(2);
        u32(uint32_t(12 + 8 + json_chunk.size() + 8 + t.bin.bytes.size()));
        u32(uint32_t(json_chunk.size()));
        u32(0x4E4F534A);  // "JSON"
        glb.insert(glb.end(), json_chunk.begin(), json_chunk.end());
        u32(uint32_t(t.bin.bytes.size()));
        u32(0x004E4942);  // "BIN\0"
        glb.insert(glb.end(), t.bin.bytes.begin(), t.bin.bytes.end());
        return glb;
    };
    // Named .bin: the loader goes by the first four bytes, not by the name.
    const fs::path path = temp_dir() / "hand_made_glb.bin";
    const std::vector<uint8_t> glb = make_glb(json);
    write_bytes(path, glb.data(), glb.size());

    vkt::GltfScene scene = vkt::load_gltf(path);
    REQUIRE(scene.indices.size() == 3);
    REQUIRE(scene.materials.size() == 1);
    CHECK(scene.materials[0].base_color_factor == glm::vec4(0.5f, 0.25f, 1, 1));
    CHECK(scene.materials[0].base_color_image == 0);
    REQUIRE(scene.images.size() == 1);
    CHECK(scene.images[0].width == 2);
    CHECK(scene.images[0].pixels == std::vector<uint8_t>{255, 0, 0, 255, 0, 0, 255, 255});

    // The image's view running past the buffer is caught before anything reads it.
    const std::string broken = fill(
        json, {{"\"byteLength\": " + std::to_string(png_bytes.size()), "\"byteLength\": 99999"}});
    const std::vector<uint8_t> broken_glb = make_glb(broken);
    write_bytes(temp_dir() / "broken_image_view.glb", broken_glb.data(), broken_glb.size());
    CHECK_THAT(error_of(temp_dir() / "broken_image_view.glb"),
               ContainsSubstring("image 0: bufferView 2 (offset " + std::to_string(image_offset) +
                                 ", length 99999) runs past the end of buffer 0"));
}

TEST_CASE("gltf: a material's factor and its embedded PNG texture; the default material",
          "[gltf]") {
    const fs::path png = temp_dir() / "material_texture.png";
    vkt::write_png(png, {1, 2, {10, 20, 30, 255, 40, 50, 60, 128}});
    Triangle t(5121);
    std::string text = triangle_file(t, 5121);
    text = fill(text, {{R"("indices": 1})",
                        R"("indices": 1, "material": 0}, {"attributes": {"POSITION": 0}})"},
                       {"$EXTRA", ""}});
    text.pop_back();  // the closing brace
    text +=
        R"(, "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 0.75], "baseColorTexture": {"index": 0}}}],
      "textures": [{"source": 0, "sampler": 0}], "samplers": [{"wrapS": 10497, "wrapT": 10497}],
      "images": [{"uri": ")" +
        data_uri(bytes_of(png), "image/png") + R"("}]})";
    vkt::GltfScene scene = vkt::load_gltf(write_file("material.gltf", text));
    REQUIRE(scene.primitives.size() == 2);
    REQUIRE(scene.materials.size() == 2);  // the file's, and the default one after it
    CHECK(scene.primitives[0].material == 0);
    CHECK(scene.primitives[1].material == 1);
    CHECK(scene.materials[0].base_color_factor == glm::vec4(1, 0.5f, 0.25f, 0.75f));
    CHECK(scene.materials[0].base_color_image == 0);
    CHECK(scene.materials[1].base_color_factor == glm::vec4(1));
    CHECK(scene.materials[1].base_color_image == -1);
    REQUIRE(scene.images.size() == 1);
    CHECK(scene.images[0].height == 2);
    CHECK(scene.images[0].pixels == std::vector<uint8_t>{10, 20, 30, 255, 40, 50, 60, 128});
    CHECK(scene.warnings.empty());
}

TEST_CASE("gltf: world matrices are parent * child, from matrix and from TRS", "[gltf]") {
    // grandparent: TRS translation (0, 0, -5)
    // parent: matrix = translate(10, 0, 0) * rotate 90 degrees about y
    // child: translation (0, 2, 0), rotation 90 degrees about z, scale 2
    // The child's vertex (0, 0, 1), worked by hand: scale (0, 0, 2); rotate
    // about z: (0, 0, 2); translate: (0, 2, 2). Parent: rotate about y,
    // (x, y, z) -> (z, y, -x): (2, 2, 0); translate: (12, 2, 0).
    // Grandparent: (12, 2, -5).
    Bin bin;
    bin.add(std::vector<float>{0, 0, 1, 1, 0, 1, 0, 1, 1});
    const float h = std::sqrt(0.5f);
    const std::string text =
        fill(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"translation": [0, 0, -5], "children": [1]},
                {"matrix": [0, 0, -1, 0,  0, 1, 0, 0,  1, 0, 0, 0,  10, 0, 0, 1], "children": [2, 3]},
                {"mesh": 0, "translation": [0, 2, 0], "rotation": [0, 0, $H, $H], "scale": [2, 2, 2]},
                {"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "buffers": [{"byteLength": 36, "uri": "$URI"}]})",
             {{"$H", std::to_string(h)}, {"$URI", data_uri(bin.bytes)}});
    vkt::GltfScene scene = vkt::load_gltf(write_file("hierarchy.gltf", text));
    REQUIRE(scene.draws.size() == 2);     // the mesh is used by two nodes...
    CHECK(scene.primitives.size() == 1);  // ...and built once
    const glm::vec4 child = scene.draws[0].world * glm::vec4(0, 0, 1, 1);
    CHECK(child.x == Approx(12).margin(1e-5));
    CHECK(child.y == Approx(2).margin(1e-5));
    CHECK(child.z == Approx(-5).margin(1e-5));
    // The sibling without a transform: only the parent's and grandparent's.
    // (1, 0, 1) -> rotate about y: (1, 0, -1) -> (11, 0, -1) -> (11, 0, -6).
    const glm::vec4 sibling = scene.draws[1].world * glm::vec4(1, 0, 1, 1);
    CHECK(sibling.x == Approx(11).margin(1e-5));
    CHECK(sibling.z == Approx(-6).margin(1e-5));
    // Bounds over both draws, in world space.
    CHECK(scene.bounds_max.x == Approx(12).margin(1e-5));
    CHECK(scene.bounds_min.z == Approx(-6).margin(1e-5));

    // A cycle never ends; it is refused.
    const std::string cycle =
        fill(text, {{R"({"mesh": 0}],)", R"({"mesh": 0, "children": [0]}],)"}});
    CHECK_THAT(error_of(write_file("cycle.gltf", cycle)),
               ContainsSubstring("node 0 appears twice in the node tree"));
}

TEST_CASE("gltf: gltf_node_matrix is T * R * S", "[gltf]") {
    const glm::mat4 m = vkt::gltf_node_matrix({}, {1, 2, 3}, {0, 0, 0, 1}, {2, 3, 4});
    const glm::vec4 p = m * glm::vec4(1, 1, 1, 1);
    CHECK(p == glm::vec4(3, 5, 7, 1));
    CHECK_THROWS_WITH(vkt::gltf_node_matrix({1, 2}, {}, {}, {}), "matrix has 2 numbers, not 16");
}

TEST_CASE("gltf: bad input gives one line naming the file and the fault", "[gltf]") {
    SECTION("a missing file") {
        CHECK_THAT(error_of(temp_dir() / "no-such-file.gltf"),
                   ContainsSubstring("cannot open") && ContainsSubstring("no-such-file.gltf"));
    }
    SECTION("not glTF") {
        CHECK_THAT(error_of(write_file("not_gltf.gltf", "hello, I am not JSON")),
                   ContainsSubstring("not_gltf.gltf: not a glTF file"));
        CHECK_THAT(
            error_of(write_file("not_gltf2.gltf", R"({"asset": {"version": "2.0"}, "nodes": 5})")),
            ContainsSubstring("not_gltf2.gltf: "));
        CHECK_THAT(error_of(write_file("empty.gltf", "")),
                   ContainsSubstring("empty.gltf: not a glTF file"));
        CHECK_THAT(error_of(write_file("short.glb", "glTF\x02")),
                   ContainsSubstring("short.glb: .glb header: the file holds 5 bytes"));
    }
    SECTION("an accessor running past the end of its bufferView") {
        Triangle t(5125);
        CHECK_THAT(error_of(write_file("long_accessor.gltf", triangle_file(t, 5125, "", "4"))),
                   ContainsSubstring("long_accessor.gltf: mesh 0 primitive 0 POSITION: accessor 0 "
                                     "(count 4, byteOffset 0, stride 12) runs past the end of "
                                     "bufferView 0 (36 bytes)"));
    }
    SECTION("a bufferView running past the end of its buffer") {
        Triangle t(5125);
        std::string text = triangle_file(t, 5125);
        text = fill(text, {{R"("byteOffset": 0, "byteLength": 36)",
                            R"("byteOffset": 40, "byteLength": 36)"}});
        CHECK_THAT(
            error_of(write_file("long_view.gltf", text)),
            ContainsSubstring(
                "bufferView 0 (offset 40, length 36) runs past the end of buffer 0 (48 bytes)"));
    }
    SECTION("an index past the end of the vertex data") {
        Triangle t(5123, {0, 1, 7});
        CHECK_THAT(
            error_of(write_file("bad_index.gltf", triangle_file(t, 5123))),
            ContainsSubstring("bad_index.gltf: mesh 0 primitive 0: index 2 is 7, past the end "
                              "of the vertex data (3 vertices)"));
    }
    SECTION("a type glTF does not allow for the attribute") {
        Triangle t(5125);
        CHECK_THAT(
            error_of(write_file("vec2_position.gltf", triangle_file(t, 5125, "", "3", "VEC2"))),
            ContainsSubstring(
                "POSITION: accessor 0 is VEC2 of FLOAT, which glTF does not allow here"));
        std::string signed_indices =
            fill(triangle_file(t, 5125), {{"\"componentType\": 5125", "\"componentType\": 5124"}});
        CHECK_THAT(error_of(write_file("int_indices.gltf", signed_indices)),
                   ContainsSubstring("index accessor 1 is SCALAR of"));
    }
    SECTION("an image that cannot be decoded") {
        Triangle t(5125);
        std::string text = triangle_file(t, 5125);
        text = fill(text, {{R"("indices": 1})", R"("indices": 1, "material": 0})"}});
        text.pop_back();
        text += R"(, "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
          "textures": [{"source": 0}], "images": [{"uri": "not_an_image.png"}]})";
        write_text(temp_dir() / "not_an_image.png", "this is text, not a PNG");
        CHECK_THAT(
            error_of(write_file("bad_image.gltf", text)),
            ContainsSubstring("bad_image.gltf: image 0 (not_an_image.png): cannot decode image"));
        std::filesystem::remove(temp_dir() / "not_an_image.png");
        CHECK_THAT(error_of(temp_dir() / "bad_image.gltf"),
                   ContainsSubstring("cannot open") && ContainsSubstring("not_an_image.png"));
    }
    SECTION("a data: URI that does not decode names the buffer or image, not the JSON") {
        Triangle t(5125);
        const std::string good = triangle_file(t, 5125);
        // The second buffer's base64 is 1 byte, not its byteLength of 4.
        const std::string second =
            fill(good,
                 {{R"("}])",
                   R"("}, {"byteLength": 4, "uri": "data:application/octet-stream;base64,AA"}])"}});
        CHECK_THAT(
            error_of(write_file("short_data_uri.gltf", second)),
            ContainsSubstring("short_data_uri.gltf: buffer 1: data URI "
                              "\"data:application/octet-stream;base64,AA\" is invalid: "
                              "its base64 decodes to 1 byte, not the buffer's byteLength 4") &&
                !ContainsSubstring("not a glTF file"));
        std::string image = good;
        image.pop_back();
        image +=
            R"(, "images": [{"uri": "data:image/png;base64,iVBO"}, {"uri": "data:image/png;base64,!!"}]})";
        CHECK_THAT(error_of(write_file("bad_image_data_uri.gltf", image)),
                   ContainsSubstring("bad_image_data_uri.gltf: image 1: its data URI is invalid: "
                                     "its base64 decodes to no bytes"));
    }
    SECTION("a URI naming the model's own folder names the URI") {
        Triangle t(5125);
        const std::string dot = fill(triangle_file(t, 5125), {{data_uri(t.bin.bytes), "."}});
        CHECK_THAT(error_of(write_file("uri_dot.gltf", dot)),
                   ContainsSubstring("uri_dot.gltf: buffer 0: URI \".\": ") &&
                       ContainsSubstring(": is a directory, not a file"));
    }
    SECTION("a required extension") {
        Triangle t(5125);
        const std::string extra =
            R"(, "extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"])";
        CHECK_THAT(error_of(write_file("draco.gltf", triangle_file(t, 5125, extra))),
                   ContainsSubstring("draco.gltf: requires extension KHR_draco_mesh_compression, "
                                     "which this loader does not support"));
    }
}

TEST_CASE("gltf: what is not supported is named in a warning and skipped", "[gltf]") {
    Triangle t(5125);
    const std::string extra =
        R"(, "extensionsUsed": ["KHR_materials_emissive_strength"], "animations": [])";
    std::string text = triangle_file(t, 5125, extra);
    // A second primitive of lines beside the triangle.
    text = fill(text, {{R"("indices": 1})",
                        R"("indices": 1}, {"attributes": {"POSITION": 0}, "mode": 1})"}});
    vkt::GltfScene scene = vkt::load_gltf(write_file("warnings.gltf", text));
    CHECK(scene.primitives.size() == 1);
    REQUIRE(scene.warnings.size() == 2);
    CHECK(scene.warnings[0] ==
          "uses extension KHR_materials_emissive_strength, which this loader ignores");
    CHECK(scene.warnings[1] == "points and lines are not supported: such primitives are skipped");
}

TEST_CASE("gltf: no number in a valid file, made absurd, crashes the loader", "[gltf]") {
    // Every number of a valid file, one at a time, replaced by a huge value, a
    // negative one and zero: the loader must load or throw vkt::Error, nothing
    // else (no crash, no other exception).
    const fs::path png = temp_dir() / "fuzz_texture.png";
    vkt::write_png(png, {1, 1, {1, 2, 3, 255}});
    Triangle t(5123);
    std::string text = triangle_file(t, 5123);
    text = fill(text, {{R"("indices": 1})", R"("indices": 1, "material": 0})"}});
    text.pop_back();
    text +=
        R"(, "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "baseColorTexture": {"index": 0, "texCoord": 0}}}],
      "textures": [{"source": 0, "sampler": 0}], "samplers": [{"wrapS": 10497}],
      "images": [{"uri": "fuzz_texture.png"}]})";
    REQUIRE_NOTHROW(vkt::load_gltf(write_file("fuzz.gltf", text)));
    const std::regex number(R"(-?\b[0-9]+(\.[0-9]+)?\b)");
    int variants = 0;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
         it != std::sregex_iterator(); ++it) {
        if (size_t(it->position()) > text.find("base64,") &&
            size_t(it->position()) < text.find("\"}]"))
            continue;  // inside the data: URI
        for (const char* value : {"4000000000", "-1", "0", "2147483647", "1e30"}) {
            std::string variant = text;
            variant.replace(size_t(it->position()), size_t(it->length()), value);
            const fs::path path = write_file("fuzz_variant.gltf", variant);
            INFO(variant);
            try {
                vkt::load_gltf(path);
            } catch (const vkt::Error&) {
            }
            ++variants;
        }
    }
    CHECK(variants > 100);
}

TEST_CASE("gltf: the chapter's scene loads the same from .gltf and .glb", "[gltf]") {
    const fs::path dir = fs::path(VKT_SOURCE_DIR) / "assets" / "gltf";
    vkt::GltfScene text = vkt::load_gltf(dir / "scene.gltf");
    vkt::GltfScene binary = vkt::load_gltf(dir / "scene.glb");
    CHECK(text.warnings.empty());
    CHECK(text.draws.size() == 5);
    CHECK(text.primitives.size() == 5);
    CHECK(text.materials.size() == 5);
    CHECK(text.images.size() == 3);
    CHECK(text.indices == binary.indices);
    CHECK(text.vertices.size() == binary.vertices.size());
    CHECK(std::memcmp(text.vertices.data(), binary.vertices.data(),
                      text.vertices.size() * sizeof(vkt::GltfVertex)) == 0);
    for (size_t i = 0; i < text.images.size(); ++i)
        CHECK(text.images[i].pixels == binary.images[i].pixels);
    CHECK(text.bounds_min == binary.bounds_min);
    CHECK(text.bounds_max == binary.bounds_max);
    // The floor is 6 x 6 at y = 0; the pyramid on the brick cube is the tallest.
    CHECK(text.bounds_min.x == Approx(-3));
    CHECK(text.bounds_min.y == Approx(0).margin(1e-6));
    CHECK(text.bounds_max.y == Approx(1.7).margin(1e-5));  // the pyramid's apex: 1 + 0.7
}
