// Writes the hostile input files of issue 25, made fresh by a test fixture
// (bad_input.hostile_files.make) rather than kept as blobs in the repository:
//
//   deep_extras.gltf         an `extras` of arrays nested 100,000 deep: tinygltf
//                            2.7 recursed once per level and overflowed its stack
//                            (exit 139 from 30,000 levels on in a release build)
//   long_bin_chunk_4.glb,    assets/gltf/scene.glb with its BIN chunk's length
//   long_bin_chunk_8.glb     (and its buffer's byteLength) 4 or 8 bytes more
//                            than the file holds: tinygltf 2.7 forgets the chunk
//                            header in its check, accepts the file and reads
//                            past the end of it
//   huge_claim.png           a PNG whose header says 16384 x 16384 (1 GiB of
//                            pixels) and whose one IDAT holds 12 bytes
//   huge_claim.gltf          a triangle whose material's texture is huge_claim.png
//
//   vkt_make_hostile_files OUT_DIR [gltf]   (gltf: only the two kinds of glTF
//                                            finding, for the fuzzer's regressions)

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<uint8_t>;

void write(const fs::path& path, const Bytes& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + path.string());
}
void write(const fs::path& path, std::string_view text) {
    write(path, Bytes(text.begin(), text.end()));
}

Bytes read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in || bytes.empty()) throw std::runtime_error("cannot read " + path.string());
    return bytes;
}

uint32_t get_u32(const Bytes& b, size_t at) {
    return uint32_t(b.at(at)) | uint32_t(b.at(at + 1)) << 8 | uint32_t(b.at(at + 2)) << 16 |
           uint32_t(b.at(at + 3)) << 24;
}
void put_u32(Bytes& b, size_t at, uint32_t v) {
    for (size_t i = 0; i < 4; ++i) b.at(at + i) = uint8_t(v >> (8 * i));
}
void put_u32_big(Bytes& b, uint32_t v) {
    for (int i = 3; i >= 0; --i) b.push_back(uint8_t(v >> (8 * i)));
}

// scene.glb with its second chunk's (BIN's) length raised by `extra` bytes,
// and its buffer's byteLength with it (the number keeps its width, so the
// JSON chunk keeps its length): tinygltf 2.7 then copies `extra` bytes from
// past the end of the file's bytes (AddressSanitizer: heap-buffer-overflow).
Bytes long_bin_chunk(Bytes glb, uint32_t extra) {
    const size_t json_length = get_u32(glb, 12);
    const size_t bin_header = 20 + json_length;  // after the header and the JSON chunk
    if (get_u32(glb, bin_header + 4) != 0x004E4942) throw std::runtime_error("scene.glb: no BIN");
    const uint32_t bin_length = get_u32(glb, bin_header);
    put_u32(glb, bin_header, bin_length + extra);
    const std::string json(glb.begin() + 20, glb.begin() + 20 + std::ptrdiff_t(json_length));
    const std::string old_length = "\"byteLength\":" + std::to_string(bin_length) + "}";
    const std::string new_length = "\"byteLength\":" + std::to_string(bin_length + extra) + "}";
    const size_t at = json.find(old_length);
    if (at == std::string::npos || old_length.size() != new_length.size())
        throw std::runtime_error("scene.glb: no buffer of byteLength " +
                                 std::to_string(bin_length));
    std::copy(new_length.begin(), new_length.end(), glb.begin() + 20 + std::ptrdiff_t(at));
    return glb;
}

std::string deep_extras(size_t depth) {
    return R"({"asset": {"version": "2.0", "extras": )" + std::string(depth, '[') +
           std::string(depth, ']') + "}}\n";
}

// PNG's CRC-32 (ISO 3309), bit by bit: these files are small.
uint32_t crc32(const uint8_t* data, size_t size) {
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
}

void png_chunk(Bytes& png, const char* type, const Bytes& data) {
    put_u32_big(png, uint32_t(data.size()));
    const size_t start = png.size();
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    put_u32_big(png, crc32(png.data() + start, png.size() - start));
}

// A PNG whose IHDR claims width x height RGBA pixels, with a 12-byte IDAT
// (the start of a zlib stream, far from all the rows it promises).
Bytes png_claiming(uint32_t width, uint32_t height) {
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    Bytes ihdr;
    put_u32_big(ihdr, width);
    put_u32_big(ihdr, height);
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, no filter, no interlace
    png_chunk(png, "IHDR", ihdr);
    png_chunk(png, "IDAT", {0x78, 0x9C, 0x63, 0x60, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00, 0, 0});
    png_chunk(png, "IEND", {});
    return png;
}

// One triangle (data: URI buffer) whose material's texture is `image`.
std::string textured_triangle(const std::string& image) {
    return R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 1, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}], "images": [{"uri": ")" +
           image + R"("}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC2"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}]
}
)";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3 || (argc == 3 && std::string_view(argv[2]) != "gltf")) {
        std::fprintf(stderr, "usage: vkt_make_hostile_files OUT_DIR [gltf]\n");
        return 2;
    }
    const fs::path out = argv[1];
    try {
        fs::create_directories(out);
        write(out / "deep_extras.gltf", deep_extras(100000));
        const Bytes scene = read(fs::path(VKT_SOURCE_DIR) / "assets/gltf/scene.glb");
        write(out / "long_bin_chunk_4.glb", long_bin_chunk(scene, 4));
        write(out / "long_bin_chunk_8.glb", long_bin_chunk(scene, 8));
        if (argc == 2) {
            write(out / "huge_claim.png", png_claiming(16384, 16384));
            write(out / "huge_claim.gltf", textured_triangle("huge_claim.png"));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vkt_make_hostile_files: %s\n", e.what());
        return 1;
    }
    std::printf("vkt_make_hostile_files: wrote %s\n", out.c_str());
    return 0;
}
