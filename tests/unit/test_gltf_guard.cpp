// Chapter 10's guard in front of tinygltf (vkt/scene/gltf_guard.hpp): the
// JSON's nesting depth and a .glb's header and chunks, checked before
// tinygltf sees the bytes; and the loader's messages for what tinygltf
// refuses, in one form, "FILE: WHAT: WHY" (common/scene/src/gltf_messages.cpp).

#include "vkt/core/check.hpp"
#include "vkt/scene/gltf.hpp"
#include "vkt/scene/gltf_guard.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::StartsWith;
namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<uint8_t>;

std::string nested(size_t depth, const std::string& inside = "") {
    return std::string(depth, '[') + inside + std::string(depth, ']');
}

void put_u32(Bytes& out, uint32_t value) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(value >> (8 * i)));
}
void put_chunk(Bytes& out, uint32_t length, const char* type, size_t data_size) {
    put_u32(out, length);
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data_size, uint8_t(' '));
}

// A .glb: header, a JSON chunk of `json` (padded to 4), a BIN chunk of 8
// bytes; `bin_claim` is what the BIN chunk's length field says.
Bytes glb(const std::string& json, uint32_t bin_claim = 8, bool with_bin = true) {
    std::string padded = json;
    while (padded.size() % 4) padded += ' ';
    Bytes out = {'g', 'l', 'T', 'F'};
    put_u32(out, 2);
    put_u32(out, 0);  // the length, filled in below
    put_u32(out, uint32_t(padded.size()));
    out.insert(out.end(), {'J', 'S', 'O', 'N'});
    out.insert(out.end(), padded.begin(), padded.end());
    if (with_bin) put_chunk(out, bin_claim, "BIN\0", 8);
    const auto size = uint32_t(out.size());
    for (int i = 0; i < 4; ++i) out[8 + size_t(i)] = uint8_t(size >> (8 * i));
    return out;
}

std::string layout_error(const Bytes& file) {
    try {
        vkt::check_glb_layout(file);
    } catch (const vkt::Error& e) {
        return e.what();
    }
    return "(accepted)";
}

fs::path folder() {
    const fs::path dir = fs::path(VKT_BINARY_DIR) / "test_gltf_guard";
    fs::create_directories(dir);
    return dir;
}
fs::path write_file(const std::string& name, const std::string& text) {
    const fs::path path = folder() / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}
std::string load_error(const fs::path& path) {
    try {
        vkt::load_gltf(path);
    } catch (const vkt::Error& e) {
        return e.what();
    }
    return "(loaded)";
}

const std::string good_buffer =
    R"({"byteLength": 44, "uri": "data:application/octet-stream;base64,)"
    R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="})";

// One triangle; `buffer` is the buffer's object, `extra` more root members.
std::string triangle(const std::string& buffer = good_buffer, const std::string& extra = "") {
    return R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [)" +
           buffer + "]" + extra + "}";
}

}  // namespace

TEST_CASE("gltf guard: JSON nesting up to the limit passes, one level more is refused",
          "[gltf][guard]") {
    CHECK_FALSE(vkt::check_json_depth(nested(64)));
    CHECK_FALSE(vkt::check_json_depth("{\"a\": " + nested(63) + "}"));
    const auto deep = vkt::check_json_depth("{\"a\":\n  " + nested(64) + "}");
    REQUIRE(deep);
    CHECK_THAT(*deep, StartsWith("JSON: arrays and objects nest more than 64 deep (at line 2, "
                                 "column 66); this loader's limit is 64 levels"));
    CHECK(vkt::gltf_max_json_depth == 64);
    CHECK(vkt::check_json_depth(nested(3), 2));
}

TEST_CASE("gltf guard: brackets inside strings, escaped quotes included, do not count",
          "[gltf][guard]") {
    const std::string brackets(200, '[');
    CHECK_FALSE(vkt::check_json_depth(R"({"a": ")" + brackets + R"("})"));
    // \" does not end the string; \\ does not escape the quote after it.
    CHECK_FALSE(vkt::check_json_depth(R"({"a": "x\")" + brackets + R"("})"));
    CHECK(vkt::check_json_depth(R"({"a": "x\\", "b": )" + nested(70) + "}"));
    // Stray closing brackets do not buy depth back.
    CHECK(vkt::check_json_depth("]]]]]]]]" + nested(65)));
    CHECK_FALSE(vkt::check_json_depth(""));
}

TEST_CASE("gltf guard: a .glb's header and chunks are checked against the file", "[gltf][guard]") {
    const std::string json = R"({"asset": {"version": "2.0"}})";
    const vkt::GlbLayout good = vkt::check_glb_layout(glb(json));
    CHECK(good.json_offset == 20);
    CHECK(good.json_length == 32);  // 29 bytes, padded to 32
    CHECK(good.chunk_count == 2);
    CHECK(vkt::check_glb_layout(glb(json, 0, false)).chunk_count == 1);

    // Finding 2 of issue 25: a BIN chunk that claims 4 or 8 bytes more.
    CHECK_THAT(layout_error(glb(json, 12)),
               ContainsSubstring(".glb chunk 1 (BIN): its length, 12 bytes from byte 60, runs 4 "
                                 "bytes past the end of the file (68 bytes)"));
    CHECK_THAT(layout_error(glb(json, 16)), ContainsSubstring("runs 8 bytes past the end"));
    CHECK_THAT(layout_error(glb(json, 0xFFFFFFF8u)), ContainsSubstring("past the end"));
    CHECK_THAT(layout_error(glb(json, 6)), ContainsSubstring("6, is not a multiple of 4"));

    Bytes file = glb(json);
    file[4] = 1;
    CHECK_THAT(layout_error(file), ContainsSubstring(".glb header: version 1"));
    file = glb(json);
    file.insert(file.end(), 4, 0);  // 4 bytes more than the header's length
    CHECK_THAT(layout_error(file),
               ContainsSubstring("length field says 68 bytes, but the file holds 72"));
    file[8] = 72;  // the length now agrees: 4 bytes too few for a chunk header
    CHECK_THAT(layout_error(file), ContainsSubstring("too few for a chunk's 8-byte header"));
    file = glb(json);
    file[16] = 'B';  // the first chunk is no longer JSON
    CHECK_THAT(layout_error(file), ContainsSubstring("the first chunk of a .glb must be JSON"));
    CHECK_THAT(layout_error(Bytes{'g', 'l', 'T', 'F', 2}),
               ContainsSubstring(".glb header: the file holds 5 bytes"));
    Bytes header_only = glb(json);
    header_only.resize(12);
    header_only[8] = 12;
    CHECK_THAT(layout_error(header_only), ContainsSubstring("no JSON chunk"));
}

TEST_CASE("gltf guard: the chapter's own files pass; a .glb's JSON chunk is depth-checked",
          "[gltf][guard]") {
    for (const char* name : {"scene.gltf", "scene.glb"}) {
        std::ifstream in(fs::path(VKT_SOURCE_DIR) / "assets/gltf" / name, std::ios::binary);
        const std::vector<char> file((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
        REQUIRE(!file.empty());
        CHECK_FALSE(vkt::check_gltf_bytes(file));
    }
    const Bytes deep = glb(R"({"asset": {"version": "2.0", "extras": )" + nested(100) + "}}");
    const std::vector<char> bytes(deep.begin(), deep.end());
    const auto refused = vkt::check_gltf_bytes(bytes);
    REQUIRE(refused);
    CHECK_THAT(*refused, StartsWith("JSON: arrays and objects nest more than 64 deep"));
    const Bytes long_bin = glb("{}", 16);
    CHECK_THAT(*vkt::check_gltf_bytes(std::vector<char>(long_bin.begin(), long_bin.end())),
               StartsWith(".glb chunk 1 (BIN)"));
}

TEST_CASE("gltf guard: the root's arrays are counted and their elements' names found",
          "[gltf][guard]") {
    const std::string json =
        R"({"x": {"buffers": [1, 2]}, "list": [[1, [2]], "]", 3.5e2],
            "buffers": [{"name": "a \"quoted\" name"}, {}, {"uri": "[{", "name": "third"}]})";
    CHECK(vkt::json_array_size(json, "buffers") == 3u);
    CHECK(vkt::json_array_size(json, "list") == 3u);
    CHECK(vkt::json_array_size(R"({"buffers": []})", "buffers") == 0u);
    CHECK_FALSE(vkt::json_array_size(json, "images"));
    CHECK_FALSE(vkt::json_array_size(R"({"buffers": [1, 2)", "buffers"));  // ends early
    CHECK(vkt::json_element_name(json, "buffers", 0) == "a \"quoted\" name");
    CHECK(vkt::json_element_name(json, "buffers", 1).empty());
    CHECK(vkt::json_element_name(json, "buffers", 2) == "third");
    CHECK(vkt::json_element_name(json, "buffers", 3).empty());
    CHECK(vkt::json_element_name("[]", "buffers", 0).empty());
}

TEST_CASE("gltf messages: what tinygltf refuses is named, in words of the file's own",
          "[gltf][guard]") {
    SECTION("a .gltf buffer without a uri names the buffer and says the URI is missing") {
        const std::string text = triangle(R"({"byteLength": 44, "name": "triangle"})");
        CHECK_THAT(load_error(write_file("no_uri.gltf", text)),
                   ContainsSubstring("no_uri.gltf: buffer 0 (\"triangle\"): its \"uri\" is "
                                     "missing"));
    }
    SECTION("no JSON library exception text reaches the reader") {
        std::string text = triangle();
        text.insert(text.find("\"count\": 3"), "\"min\": [1e309, 0, 0], ");
        const std::string message = load_error(write_file("overflow.gltf", text));
        CHECK_THAT(message, ContainsSubstring("overflow.gltf: JSON: the number 1e309 is too "
                                              "large for a double"));
        CHECK_THAT(message, !ContainsSubstring("json.exception"));
        std::string syntax = triangle();
        syntax.insert(syntax.find("\"nodes\""), ",");
        const std::string broken = load_error(write_file("syntax.gltf", syntax));
        CHECK_THAT(broken, ContainsSubstring("syntax.gltf: JSON: malformed at line 1, column"));
        CHECK_THAT(broken,
                   !ContainsSubstring("json.exception") && !ContainsSubstring("not a glTF"));
    }
    SECTION("\"not a glTF file\" only where it is not one") {
        CHECK_THAT(load_error(write_file("text.gltf", "This is text.")),
                   ContainsSubstring("text.gltf: not a glTF file: a .gltf is a JSON object"));
        CHECK_THAT(load_error(write_file("array.gltf", "[1, 2, 3]")),
                   ContainsSubstring("array.gltf: not a glTF file: its JSON is an array"));
        CHECK_THAT(load_error(write_file("no_asset.gltf", R"({"scenes": []})")),
                   ContainsSubstring("no_asset.gltf: not a glTF file: it has no \"asset\""));
    }
    SECTION("a missing property names the element by index and name") {
        std::string text = triangle();
        text.replace(text.find("\"componentType\": 5126, "), 23, "\"name\": \"positions\", ");
        CHECK_THAT(load_error(write_file("no_type.gltf", text)),
                   ContainsSubstring("no_type.gltf: accessor 0 (\"positions\"): the required "
                                     "property \"componentType\" is missing"));
        CHECK_THAT(load_error(write_file("skin.gltf", triangle(good_buffer, ", \"skins\": [{}]"))),
                   ContainsSubstring("skin.gltf: skin 0: tinygltf refuses it without saying why"));
    }
    SECTION("a buffer's file missing or of the wrong size names the buffer") {
        const std::string missing = triangle(R"({"byteLength": 44, "uri": "nothing.bin"})");
        CHECK_THAT(load_error(write_file("missing_bin.gltf", missing)),
                   ContainsSubstring("missing_bin.gltf: buffer 0: its file \"nothing.bin\" does "
                                     "not exist in the model's folder"));
        write_file("short.bin", std::string(20, '\0'));
        const std::string short_bin = triangle(R"({"byteLength": 44, "uri": "short.bin"})");
        CHECK_THAT(load_error(write_file("short_bin.gltf", short_bin)),
                   ContainsSubstring("short_bin.gltf: buffer 0: its file \"") &&
                       ContainsSubstring("short.bin\" holds 20 bytes, not its byteLength 44"));
    }
    SECTION("the loader's own checks name elements by name too") {
        std::string text = triangle();
        text.replace(text.find("\"count\": 3, \"type\": \"VEC3\""), 10,
                     "\"name\": \"positions\", \"count\": 4");
        CHECK_THAT(load_error(write_file("named.gltf", text)),
                   ContainsSubstring("named.gltf: mesh 0 primitive 0 POSITION: accessor 0 "
                                     "(\"positions\") (count 4, byteOffset 0, stride 12) runs "
                                     "past the end of bufferView 0"));
        std::string image = triangle(
            good_buffer,
            R"(, "images": [{"name": "bricks", "uri": "data:image/png;base64,AAAA"}], "textures": [{"source": 0}], "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
        image.replace(image.find("\"indices\": 1"), 12, "\"indices\": 1, \"material\": 0");
        CHECK_THAT(load_error(write_file("named_image.gltf", image)),
                   ContainsSubstring("named_image.gltf: image 0 (\"bricks\"): cannot decode "
                                     "image: not a PNG or JPEG file"));
    }
}

TEST_CASE("gltf guard: indices past an int or negative and factors of the wrong length are refused",
          "[gltf][guard]") {
    using vkt::check_json_values;
    CHECK_FALSE(
        check_json_values(R"({"nodes": [{"mesh": 0, "children": [1]}, {"mesh": 2147483647}]})"));
    CHECK(
        check_json_values(R"({"nodes": [{"mesh": 4294967296}]})") ==
        R"(node 0: "mesh" is 4294967296, which is no index: glTF's are whole numbers from 0 to 2147483647)");
    CHECK(check_json_values(R"({"nodes": [{}, {"children": [0, -1]}]})")
              .value_or("")
              .starts_with(R"(node 1: "children" element 1 is -1, which is no index)"));
    // A key spelt with escapes is the same key to the parser.
    CHECK(check_json_values(R"({"nodes": [{"\u006desh": 2147483648}]})").has_value());
    CHECK(check_json_values(
              R"({"meshes": [{"primitives": [{"attributes": {"POSITION": 99999999999}}]}]})")
              .value_or("")
              .starts_with(R"(mesh 0 primitive 0 attributes: "POSITION" is 99999999999)"));
    // An application's data may hold any number.
    CHECK_FALSE(check_json_values(R"({"nodes": [{"extras": {"mesh": -5, "children": [1e30]}}]})"));
    CHECK(check_json_values(R"({"materials": [{"emissiveFactor": [1, 1]}]})") ==
          R"(material 0: "emissiveFactor" has 2 numbers, not 3)");
    CHECK(
        check_json_values(R"({"materials": [{"pbrMetallicRoughness": {"baseColorFactor": 1}}]})")
            .value_or("")
            .starts_with(
                R"(material 0 pbrMetallicRoughness: "baseColorFactor" is not an array of 4 numbers)"));
    CHECK_FALSE(check_json_values(
        R"({"materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}, "emissiveFactor": [0, 0, 0]}]})"));
}
