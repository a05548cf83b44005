// The memory a glTF model may make chapter 10 spend (issue 25): everything
// large the loader allocates is charged to a MemoryBudget before it is
// allocated (vkt/core/memory_budget.hpp), and refused by name with the
// numbers past --max-memory. Every model is written here, into the build
// folder, and removed.

#include "base64.hpp"
#include "peak_resident.hpp"
#include "vkt/core/check.hpp"
#include "vkt/core/memory_budget.hpp"
#include "vkt/scene/gltf.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using Catch::Matchers::ContainsSubstring;
namespace fs = std::filesystem;

namespace {

// build/<preset>/test_gltf_budget/<test>/, one folder per test (they run in
// parallel), removed when the test ends.
struct Folder {
    fs::path dir;
    explicit Folder(const std::string& test)
        : dir(fs::path(VKT_BINARY_DIR) / "test_gltf_budget" / test) {
        fs::create_directories(dir);
    }
    ~Folder() {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
    Folder(const Folder&) = delete;
    Folder& operator=(const Folder&) = delete;
};

fs::path write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    REQUIRE(out.good());
    return path;
}

// One triangle: positions (0,0,0) (1,0,0) (0,1,0), then 16-bit indices 0 1 2.
std::vector<uint8_t> triangle_bin() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t indices[4] = {0, 1, 2, 0};
    std::vector<uint8_t> bytes(44);
    std::memcpy(bytes.data(), positions, 36);
    std::memcpy(bytes.data() + 36, indices, 8);
    return bytes;
}

// The triangle's glTF up to its buffer's URI, whose text the caller writes,
// and what follows the URI.
std::string triangle_head(uint64_t byte_length, const std::string& position_accessor) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [)" +
           position_accessor + R"(,
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"name": "big", "byteLength": )" +
           std::to_string(byte_length) + R"(, "uri": ")";
}
const std::string tail = "\"}]}";
const std::string positions =
    R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"})";

// A triangle whose buffer is a data: URI of `size` bytes: the triangle's 45
// (44 and a zero) and then zeros, written as base64 piece by piece, so that
// the test itself never holds the whole text.
fs::path big_data_uri_model(const fs::path& path, uint64_t size) {
    REQUIRE(size % 3 == 0);
    std::ofstream out(path, std::ios::binary);
    out << triangle_head(size, positions) << "data:application/octet-stream;base64,";
    std::vector<uint8_t> head = triangle_bin();
    head.push_back(0);
    out << vkt_test::base64(head);
    const std::string zeros(65536, 'A');  // base64 of 49,152 zero bytes
    uint64_t left = (size - 45) / 3 * 4;  // base64 characters still to write
    while (left > 0) {
        const uint64_t n = std::min<uint64_t>(left, zeros.size());
        out.write(zeros.data(), std::streamsize(n));
        left -= n;
    }
    out << tail;
    REQUIRE(out.good());
    return path;
}

std::string load_error(const fs::path& path, uint64_t max_memory) {
    try {
        vkt::load_gltf(path, max_memory);
    } catch (const vkt::Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("memory budget: charges add up and the one past the limit is refused by name",
          "[budget]") {
    vkt::MemoryBudget budget(uint64_t(100) << 20);
    budget.charge(uint64_t(60) << 20, "first");
    CHECK(budget.used() == uint64_t(60) << 20);
    CHECK_THROWS_WITH(budget.charge(uint64_t(50) << 20, "model.gltf: image 3"),
                      "model.gltf: image 3: needs 50 MiB, which would bring what this file "
                      "needs to 110 MiB, past the limit of 100 MiB (--max-memory)");
    CHECK(budget.used() == uint64_t(60) << 20);  // nothing charged for the refusal
    budget.charge(uint64_t(40) << 20, "exactly to the limit");
    CHECK_THROWS(budget.charge(1, "one byte more"));
    // A count from a file may be anything: no overflow.
    vkt::MemoryBudget other;
    CHECK_THROWS_WITH(other.charge(UINT64_MAX, "x"), ContainsSubstring("more than 2^60 bytes"));
}

TEST_CASE("memory budget: sizes are read as a reader types them", "[budget]") {
    CHECK(vkt::parse_byte_count("2G") == uint64_t(2) << 30);
    CHECK(vkt::parse_byte_count("512M") == uint64_t(512) << 20);
    CHECK(vkt::parse_byte_count("1536MiB") == uint64_t(1536) << 20);
    CHECK(vkt::parse_byte_count("64k") == uint64_t(64) << 10);
    CHECK(vkt::parse_byte_count("1000") == 1000u);
    CHECK(vkt::parse_byte_count("1T") == uint64_t(1) << 40);
    CHECK_FALSE(vkt::parse_byte_count(""));
    CHECK_FALSE(vkt::parse_byte_count("G"));
    CHECK_FALSE(vkt::parse_byte_count("2X"));
    CHECK_FALSE(vkt::parse_byte_count("-1G"));
    CHECK_FALSE(vkt::parse_byte_count("1.5G"));
    CHECK_FALSE(vkt::parse_byte_count("2000000T"));  // past 2^50
    CHECK(vkt::byte_count_text(uint64_t(2) << 30) == "2 GiB");
    CHECK(vkt::byte_count_text(uint64_t(3) << 29) == "1536 MiB");
    CHECK(vkt::byte_count_text(2048) == "2 KiB");
    CHECK(vkt::byte_count_text(100) == "100 bytes");
}

TEST_CASE("gltf budget: a 50 MB data: URI is decoded once and loads within its budget",
          "[gltf][budget]") {
    const Folder folder("big_data_uri");
    // 39,321,600 bytes (37.5 MiB) of buffer: 52,428,800 characters of base64.
    const fs::path model = big_data_uri_model(folder.dir / "big.gltf", 39321600);
    REQUIRE(fs::file_size(model) > 50u << 20);
    REQUIRE(vkt_test::reset_peak_resident());
    const double before = vkt_test::peak_resident_mib();
    const vkt::GltfScene scene = vkt::load_gltf(model);
    const double after = vkt_test::peak_resident_mib();
    CHECK(scene.vertices.size() == 3);
    std::printf("peak resident memory: %.1f MiB before loading, %.1f MiB after\n", before, after);
    // The file (50 MiB) and the decoded buffer (37.5 MiB), once each. tinygltf
    // decoding it from copies of the JSON's string peaked at 388 MB.
    CHECK(after < before + 120.0);
}

TEST_CASE("gltf budget: past --max-memory the data: URI is refused before it is decoded",
          "[gltf][budget]") {
    const Folder folder("big_data_uri_refused");
    const fs::path model = big_data_uri_model(folder.dir / "big.gltf", 3 << 20);  // 4 MiB of text
    REQUIRE(vkt_test::reset_peak_resident());
    const double before = vkt_test::peak_resident_mib();
    CHECK_THAT(load_error(model, 6u << 20),
               ContainsSubstring("big.gltf: buffer 0 (\"big\"): its data: URI, decoded: needs "
                                 "3 MiB, which would bring what this file needs to 7 MiB, past "
                                 "the limit of 6 MiB (--max-memory)"));
    CHECK(vkt_test::peak_resident_mib() < before + 16.0);
    CHECK(load_error(model, 16u << 20).empty());
}

TEST_CASE("gltf budget: an accessor of 2^28 zeros is refused before it is allocated",
          "[gltf][budget]") {
    const Folder folder("zeros");
    // No bufferView: glTF's zeros, 2^28 of them, 3 GiB as floats, in 500 bytes.
    const std::string zeros = R"({"componentType": 5126, "count": 268435456, "type": "VEC3"})";
    const fs::path model =
        write_text(folder.dir / "zeros.gltf", triangle_head(44, zeros) +
                                                  "data:application/octet-stream;base64," +
                                                  vkt_test::base64(triangle_bin()) + tail);
    REQUIRE(vkt_test::reset_peak_resident());
    const double before = vkt_test::peak_resident_mib();
    CHECK_THAT(load_error(model, vkt::default_max_memory),
               ContainsSubstring("zeros.gltf: mesh 0 primitive 0 POSITION: accessor 0") &&
                   ContainsSubstring("read as floats: needs 3 GiB, which would bring what this "
                                     "file needs to 3072 MiB, past the limit of 1 GiB "
                                     "(--max-memory)"));
    CHECK(vkt_test::peak_resident_mib() < before + 16.0);
}

TEST_CASE("gltf budget: a file a URI names is charged before it is read", "[gltf][budget]") {
    const Folder folder("external");
    {
        std::ofstream bin(folder.dir / "big.bin", std::ios::binary);
        const std::vector<uint8_t> head = triangle_bin();
        bin.write(reinterpret_cast<const char*>(head.data()), std::streamsize(head.size()));
    }
    fs::resize_file(folder.dir / "big.bin", 8u << 20);  // 8 MiB, the rest zeros
    const fs::path model = write_text(folder.dir / "external.gltf",
                                      triangle_head(8u << 20, positions) + "big.bin" + tail);
    // Its bytes and tinygltf's copy of them: 16 MiB.
    CHECK_THAT(
        load_error(model, 12u << 20),
        ContainsSubstring("external.gltf: buffer 0 (\"big\"): URI \"big.bin\": needs 16 MiB"));
    CHECK(load_error(model, 32u << 20).empty());
}

TEST_CASE("gltf budget: a .glb's data: URI is left to tinygltf and charged as its copies",
          "[gltf][budget]") {
    const Folder folder("glb_data_uri");
    // The 4 MiB .gltf above as a .glb's JSON chunk (no BIN chunk).
    const fs::path gltf = big_data_uri_model(folder.dir / "big.gltf", 3 << 20);
    std::string json;
    {
        std::ifstream in(gltf, std::ios::binary);
        json.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    while (json.size() % 4) json += ' ';
    std::string glb = "glTF";
    for (const uint32_t word : {2u, uint32_t(20 + json.size()), uint32_t(json.size())})
        for (int i = 0; i < 4; ++i) glb += char(uint8_t(word >> (8 * i)));
    glb += "JSON" + json;
    const fs::path model = write_text(folder.dir / "big.glb", glb);
    // The file (4 MiB), then 5 times its JSON's text (20 MiB): nlohmann's
    // copy, tinygltf's, the substring it decodes, the bytes twice.
    CHECK_THAT(load_error(model, 16u << 20),
               ContainsSubstring("big.glb: its JSON, parsed (") &&
                   ContainsSubstring("values at most): needs 20 MiB, which would bring what this "
                                     "file needs to 24 MiB, past the limit of 16 MiB"));
    CHECK(load_error(model, 32u << 20).empty());
}
