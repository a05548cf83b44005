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
//   big_data_uri.gltf        a triangle whose buffer is a 50 MiB base64 data: URI
//                            (37.5 MiB of bytes, zeros after the triangle's):
//                            tinygltf alone peaked at 388 MB decoding it
//   huge_claim.jpg           a JPEG whose header says 8192 x 8192 (inside the
//                            budget: 939 MiB) and whose scan holds 16 bytes
//   jpeg_claim.gltf          a triangle whose material's texture is huge_claim.jpg
//   flat_4096.jpg            a true JPEG of 4096 x 4096 flat grey in 64 KiB: what
//                            the JPEG check lets through, and a budget of 235 MiB
//
// and those of issue 39, each made past what our own code did with it:
//
//   node_chain.gltf          100,000 nodes, each the only child of the one before,
//                            the last with the triangle: one call per level
//                            overflowed the stack (exit 139 from about 16,350)
//   fan_200000.gltf, .bin    a fan of 200,000 triangles with normals, all
//                            sharing vertex 0: chapter 26's meshlet builder
//                            rescanned every use of every vertex (over 60 s)
//   zeros_100000.gltf, .bin  100,000 triangles whose indices are all 0 (over 70 s)
//   warnings_20000.gltf      20,000 distinct names in extensionsUsed: each
//                            warning was compared with every one before it and
//                            all were printed (400,000 took 228 s)
//   materials_65156.gltf     65,156 empty materials: one descriptor set each, and
//                            lavapipe crashed (exit 139)
//   instances_2000.gltf      2,000 nodes sharing one mesh of 300,000 vertices whose
//                            POSITION has no bufferView (all zeros): 24 KB that
//                            26 flattened into gigabytes, and 10 transformed
//                            600 million vertices for its bounds
//   nan_position.gltf,       a quad (two triangles) with one corner's POSITION, or
//   nan_normal.gltf          its NORMAL, NaN: drawn with exit 0, half the quad
//                            missing, or lit black in 23
//   mesh_2_32.gltf           a node whose "mesh" is 4294967296: tinygltf narrowed
//                            it to 0 and mesh 0 was drawn (exit 0)
//   mesh_negative.gltf       "mesh": -2147483649, reported as mesh 2147483647
//   base_color_2.gltf        a baseColorFactor of 2 numbers: tinygltf dropped the
//                            whole pbrMetallicRoughness block without a word
//   palette_index.png        a 2 x 2 palette PNG of one colour whose pixels use
//                            index 5: libpng's complaint was silenced as a
//                            warning and the pixels were drawn black (exit 0)
//   materials_1e6.gltf       a million empty materials (3 MB): tinygltf's objects
//                            for them took 2 GiB before anything was charged
//   positions_2_24.gltf      POSITION of 2^24 zeros (no bufferView), not indexed:
//                            the index list made for it was not charged
//   indices_no_view.gltf     the triangle's index accessor without a bufferView:
//                            tinygltf's refusal was blamed on "node 0"
//   instances_200.gltf       200 of them: within the limit on vertices drawn, but
//                            26's flattened copy needs 9 GiB
//
// and those refused in words that named the wrong thing, or nothing:
//
//   empty_bin_chunk.glb      a .glb whose BIN chunk is empty: "buffer 0: tinygltf
//                            refuses it: Insufficient storage space ..."
//   cmyk.jpg, cmyk_image.gltf  a CMYK JPEG (4 components, no Adobe marker), and a
//                            triangle textured with it: "Unsupported color
//                            conversion request"
//   dnl.jpg                  a JPEG of height 0: "Empty JPEG image (DNL not supported)"
//   iend_out_of_place.png    a PNG whose IEND comes before its IDAT: "IEND: out of place"
//   ihdr_zero_width.png      a PNG of width 0: "Invalid IHDR data"
//   image_uri_outside.gltf   an image at "../outside.png": refused without "image 0:"
//   "trailing_space.gltf ",  not glTF, under names a terminal shows wrongly (a
//   "escape_\x1bc_reset.gltf" trailing space; ESC c, which resets a terminal):
//                            the names were printed raw
//   flat_8192.jpg            a flat 8192 x 8192 JPEG in 256 KiB (939 MiB decoded,
//                            staged and mipmapped): what --max-memory 1G admits
//
//   vkt_make_hostile_files OUT_DIR [gltf]   (gltf: only the files that need no
//                                            other file, for the fuzzers'
//                                            regressions)

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
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

// A triangle (positions, then 16-bit indices) whose buffer is a data: URI of
// `size` bytes, the rest zeros: written piece by piece, never held whole.
void write_big_data_uri(const fs::path& path, uint64_t size) {
    std::ofstream out(path, std::ios::binary);
    out << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"byteLength": )"
        << size << R"(, "uri": "data:application/octet-stream;base64,)";
    // The triangle's 44 bytes and one zero: 60 characters, then 'A's (zeros).
    out << "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAAA";
    const std::string zeros(65536, 'A');
    for (uint64_t left = (size - 45) / 3 * 4; left > 0;) {
        const uint64_t n = std::min<uint64_t>(left, zeros.size());
        out.write(zeros.data(), std::streamsize(n));
        left -= n;
    }
    out << "\"}]}\n";
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

// A baseline grey JPEG whose frame header (SOF0) says width x height, with
// one Huffman table of a single 1-bit code for DC and one for AC: each 8x8
// block is two bits ("no change", "end of block"), a flat grey picture, and
// `blocks` of them are in its scan. Written byte by byte: no encoder needed.
// With 4 `components` (and no Adobe marker) libjpeg reads it as CMYK.
Bytes jpeg_claiming(uint16_t width, uint16_t height, size_t blocks, uint8_t components = 1) {
    Bytes jpeg = {0xFF, 0xD8};  // SOI
    auto segment = [&](uint8_t marker, const Bytes& data) {
        jpeg.insert(jpeg.end(),
                    {0xFF, marker, uint8_t((data.size() + 2) >> 8), uint8_t(data.size() + 2)});
        jpeg.insert(jpeg.end(), data.begin(), data.end());
    };
    Bytes quantisation = {0x00};  // 8-bit table 0
    quantisation.resize(65, 1);
    segment(0xDB, quantisation);
    Bytes frame = {
        8, uint8_t(height >> 8), uint8_t(height), uint8_t(width >> 8), uint8_t(width), components};
    Bytes scan = {components};
    for (uint8_t c = 1; c <= components; ++c) {
        frame.insert(frame.end(), {c, 0x11, 0});  // component c: 1x1 sampling, table 0
        scan.insert(scan.end(), {c, 0x00});       // Huffman tables 0 and 0
    }
    scan.insert(scan.end(), {0, 63, 0});
    segment(0xC0, frame);
    Bytes huffman_dc = {0x00, 1};  // DC table 0: one code of length 1 ...
    huffman_dc.resize(17, 0);
    huffman_dc.push_back(0x00);  // ... for category 0: no change
    segment(0xC4, huffman_dc);
    Bytes huffman_ac = huffman_dc;
    huffman_ac[0] = 0x10;  // AC table 0: the one code is 0x00, end of block
    segment(0xC4, huffman_ac);
    segment(0xDA, scan);
    const size_t bytes = (2 * blocks * components + 7) / 8;
    jpeg.insert(jpeg.end(), bytes, 0x00);   // two 0 bits a block (0x00 needs no stuffing)
    jpeg.insert(jpeg.end(), {0xFF, 0xD9});  // EOI
    return jpeg;
}

// The triangle of textured_triangle, untextured, with `nodes` for its node
// list (node 0 the scene's root) and `extra` after its buffers: each file
// below is this triangle made hostile in one way.
std::string triangle_with(const std::string& nodes, const std::string& extra = "") {
    return R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" +
           nodes + R"(,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}])" +
           extra + "\n}\n";
}

// Nodes 0 .. depth-1, each the one child of the one before; the last draws mesh 0.
std::string node_chain(size_t depth) {
    std::string nodes = "[";
    for (size_t i = 0; i + 1 < depth; ++i)
        nodes += R"({"children": [)" + std::to_string(i + 1) + "]},";
    return nodes + R"({"mesh": 0}])";
}

void put_f32(Bytes& b, float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    for (int i = 0; i < 4; ++i) b.push_back(uint8_t(u >> (8 * i)));
}

// A mesh of `vertices` positions and normals (a .bin beside the .gltf),
// drawn as `mode` from `index_count` 16-bit zeros, or unindexed if none.
void write_mesh(const fs::path& gltf, const Bytes& bin, size_t vertices, int mode,
                size_t index_count) {
    const std::string bin_name = gltf.stem().string() + ".bin";
    write(gltf.parent_path() / bin_name, bin);
    const size_t vec3s = 12 * vertices;
    std::string indices, index_view, index_accessor;
    if (index_count > 0) {
        indices = R"(, "indices": 2)";
        index_view = R"(, {"buffer": 0, "byteOffset": )" + std::to_string(2 * vec3s) +
                     R"(, "byteLength": )" + std::to_string(2 * index_count) + "}";
        index_accessor = R"(, {"bufferView": 2, "componentType": 5123, "count": )" +
                         std::to_string(index_count) + R"(, "type": "SCALAR"})";
    }
    write(gltf,
          R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "mode": )" +
              std::to_string(mode) + indices + R"(}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
              std::to_string(vertices) + R"(, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": )" +
              std::to_string(vertices) + R"(, "type": "VEC3"})" + index_accessor + R"(],
  "bufferViews": [{"buffer": 0, "byteLength": )" +
              std::to_string(vec3s) + R"(}, {"buffer": 0, "byteOffset": )" + std::to_string(vec3s) +
              R"(, "byteLength": )" + std::to_string(vec3s) + "}" + index_view + R"(],
  "buffers": [{"byteLength": )" +
              std::to_string(bin.size()) + R"(, "uri": ")" + bin_name + R"("}]
}
)");
}

// A fan of `triangles` round vertex 0 (TRIANGLE_FAN, mode 6), a disc facing +z.
void write_fan(const fs::path& gltf, size_t triangles) {
    const size_t vertices = triangles + 2;
    Bytes bin;
    for (size_t i = 0; i < vertices; ++i) {
        const double a = i == 0 ? 0.0 : 6.283185307179586 * double(i - 1) / double(triangles + 1);
        const float r = i == 0 ? 0.0f : 1.0f;
        for (float f : {r * float(std::cos(a)), r * float(std::sin(a)), 0.0f}) put_f32(bin, f);
    }
    for (size_t i = 0; i < vertices; ++i)
        for (float f : {0.0f, 0.0f, 1.0f}) put_f32(bin, f);
    write_mesh(gltf, bin, vertices, 6, 0);
}

// `triangles` triangles of one vertex: every index 0.
void write_zeros(const fs::path& gltf, size_t triangles) {
    Bytes bin;
    for (float f : {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f}) put_f32(bin, f);
    bin.resize(bin.size() + 2 * 3 * triangles, 0);
    write_mesh(gltf, bin, 1, 4, 3 * triangles);
}

// The triangle, and `count` distinct extensions it uses (none required).
std::string many_extensions(size_t count) {
    std::string names;
    for (size_t i = 0; i < count; ++i)
        names += (i ? ", \"EXT_hostile_" : "\"EXT_hostile_") + std::to_string(i) + "\"";
    return triangle_with(R"([{"mesh": 0}])", ",\n  \"extensionsUsed\": [" + names + "]");
}

// The triangle, and `count` empty materials (the triangle uses none of them).
std::string many_materials(size_t count) {
    std::string list;
    for (size_t i = 0; i < count; ++i) list += i ? ", {}" : "{}";
    return triangle_with(R"([{"mesh": 0}])", ",\n  \"materials\": [" + list + "]");
}

// `nodes` nodes (children of node 0) all drawing mesh 0: `vertices` zeros,
// unindexed, from an accessor with no bufferView.
std::string many_instances(size_t nodes, size_t vertices) {
    std::string list = R"([{"children": [)";
    for (size_t i = 1; i <= nodes; ++i) list += (i > 1 ? ", " : "") + std::to_string(i);
    list += "]}";
    for (size_t i = 1; i <= nodes; ++i)
        list += R"(, {"mesh": 0, "translation": [)" + std::to_string(i) + ", 0, 0]}";
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" +
           list + R"(],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"componentType": 5126, "count": )" +
           std::to_string(vertices) + R"(, "type": "VEC3", "min": [0, 0, 0], "max": [0, 0, 0]}]
}
)";
}

std::string base64(const Bytes& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 |
                           (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                           (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0);
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

// A unit quad facing +z, two triangles with normals, in a data: URI; corner
// 2's POSITION (`nan_position`) or NORMAL made NaN.
std::string nan_quad(bool nan_position) {
    const float nan = std::nanf("");
    Bytes bin;
    const float positions[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (int v = 0; v < 4; ++v)
        for (int c = 0; c < 3; ++c)
            put_f32(bin, nan_position && v == 2 && c == 1 ? nan : positions[v][c]);
    for (int v = 0; v < 4; ++v)
        for (float f : {0.0f, 0.0f, 1.0f})
            put_f32(bin, !nan_position && v == 2 && f == 1.0f ? nan : f);
    bin.insert(bin.end(), {0, 0, 1, 0, 2, 0, 0, 0, 2, 0, 3, 0});  // 0 1 2, 0 2 3: 16-bit
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 12}],
  "buffers": [{"byteLength": 108, "uri": "data:application/octet-stream;base64,)" +
           base64(bin) + R"("}]
}
)";
}

uint32_t adler32(const Bytes& data) {
    uint32_t a = 1, b = 0;
    for (uint8_t byte : data) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    return b << 16 | a;
}

// A 2 x 2, 8-bit palette PNG with one colour (red) whose pixels are all
// index 5, its rows in one stored (uncompressed) deflate block.
Bytes png_palette_index_past_end() {
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    Bytes ihdr;
    put_u32_big(ihdr, 2);
    put_u32_big(ihdr, 2);
    ihdr.insert(ihdr.end(), {8, 3, 0, 0, 0});  // 8 bits, palette
    png_chunk(png, "IHDR", ihdr);
    png_chunk(png, "PLTE", {0xFF, 0x00, 0x00});
    const Bytes rows = {0, 5, 5, 0, 5, 5};  // each row: filter 0, two indices
    Bytes idat = {0x78, 0x01, 0x01, uint8_t(rows.size()), 0, uint8_t(~rows.size()), 0xFF};
    idat.insert(idat.end(), rows.begin(), rows.end());
    put_u32_big(idat, adler32(rows));
    png_chunk(png, "IDAT", idat);
    png_chunk(png, "IEND", {});
    return png;
}

// A PNG of `chunks` after its signature, each chunk's type and data, in
// that order: what libpng refuses for its order or its header.
Bytes png_of(const std::vector<std::pair<const char*, Bytes>>& chunks) {
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    for (const auto& [type, data] : chunks) png_chunk(png, type, data);
    return png;
}
Bytes ihdr_of(uint32_t width, uint32_t height) {
    Bytes ihdr;
    put_u32_big(ihdr, width);
    put_u32_big(ihdr, height);
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, no filter, no interlace
    return ihdr;
}
// A 1 x 1 RGBA picture's one row (filter 0, 4 bytes), stored in deflate.
Bytes one_pixel_idat() {
    const Bytes row = {0, 0xFF, 0x80, 0x00, 0xFF};
    Bytes idat = {0x78, 0x01, 0x01, uint8_t(row.size()), 0, uint8_t(~row.size()), 0xFF};
    idat.insert(idat.end(), row.begin(), row.end());
    put_u32_big(idat, adler32(row));
    return idat;
}

// A .glb of `json` (padded with spaces to 4 bytes) and a BIN chunk of `bin`.
Bytes glb_of(std::string json, const Bytes& bin) {
    json.resize((json.size() + 3) / 4 * 4, ' ');
    Bytes glb = {'g', 'l', 'T', 'F', 2, 0, 0, 0, 0, 0, 0, 0};
    const auto chunk = [&](const char* type, const uint8_t* data, size_t size) {
        for (size_t i = 0; i < 4; ++i) glb.push_back(uint8_t(uint32_t(size) >> (8 * i)));
        glb.insert(glb.end(), type, type + 4);
        glb.insert(glb.end(), data, data + size);
    };
    chunk("JSON", reinterpret_cast<const uint8_t*>(json.data()), json.size());
    chunk("BIN\0", bin.data(), bin.size());
    put_u32(glb, 8, uint32_t(glb.size()));
    return glb;
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
        write(out / "node_chain.gltf", triangle_with(node_chain(100000)));
        write(out / "warnings_20000.gltf", many_extensions(20000));
        write(out / "materials_65156.gltf", many_materials(65156));
        write(out / "instances_2000.gltf", many_instances(2000, 300000));
        write(out / "instances_200.gltf", many_instances(200, 300000));
        write(out / "nan_position.gltf", nan_quad(true));
        write(out / "nan_normal.gltf", nan_quad(false));
        write(out / "mesh_2_32.gltf", triangle_with(R"([{"mesh": 4294967296}])"));
        write(out / "mesh_negative.gltf", triangle_with(R"([{"mesh": -2147483649}])"));
        std::string base_color_2 = triangle_with(
            R"([{"mesh": 0}])",
            R"(, "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5]}}])");
        base_color_2.replace(base_color_2.find(R"("indices": 1)"), 12,
                             R"("indices": 1, "material": 0)");
        write(out / "base_color_2.gltf", base_color_2);
        write(out / "palette_index.png", png_palette_index_past_end());
        write(out / "materials_1e6.gltf", many_materials(1000000));
        std::string no_view = triangle_with(R"([{"mesh": 0}])");
        const std::string view_1 = R"({"bufferView": 1, "componentType": 5123)";
        no_view.replace(no_view.find(view_1), view_1.size(), R"({"componentType": 5123)");
        write(out / "indices_no_view.gltf", no_view);
        // An empty BIN chunk where the buffer wants 44 bytes of it.
        write(out / "empty_bin_chunk.glb",
              glb_of(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"byteLength": 44}]})",
                     {}));
        // Pictures the decoders refuse in their own jargon: CMYK, a height of
        // 0 (to come in a DNL marker), a chunk out of place, a header of width 0.
        write(out / "cmyk.jpg", jpeg_claiming(8, 8, 1, 4));
        write(out / "dnl.jpg", jpeg_claiming(8, 0, 1));
        write(
            out / "iend_out_of_place.png",
            png_of(
                {{"IHDR", ihdr_of(1, 1)}, {"IEND", {}}, {"IDAT", one_pixel_idat()}, {"IEND", {}}}));
        write(out / "ihdr_zero_width.png",
              png_of({{"IHDR", ihdr_of(0, 1)}, {"IDAT", one_pixel_idat()}, {"IEND", {}}}));
        write(out / "positions_2_24.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"componentType": 5126, "count": 16777216, "type": "VEC3"}]}
)");
        if (argc == 2) {
            write(out / "huge_claim.png", png_claiming(16384, 16384));
            write(out / "huge_claim.gltf", textured_triangle("huge_claim.png"));
            write_big_data_uri(out / "big_data_uri.gltf", 39321600);
            write(out / "huge_claim.jpg", jpeg_claiming(8192, 8192, 64));
            write(out / "jpeg_claim.gltf", textured_triangle("huge_claim.jpg"));
            write(out / "flat_4096.jpg", jpeg_claiming(4096, 4096, 512 * 512));
            write_fan(out / "fan_200000.gltf", 200000);
            write_zeros(out / "zeros_100000.gltf", 100000);
            // An image whose URI leads out of the model's folder (refused,
            // with tinygltf only warning), and the CMYK JPEG as a model's image.
            write(out / "image_uri_outside.gltf", textured_triangle("../outside.png"));
            write(out / "cmyk_image.gltf", textured_triangle("cmyk.jpg"));
            // Names a terminal would show wrongly: a trailing space, an
            // escape sequence (ESC c resets the terminal). Not glTF.
            write(out / "trailing_space.gltf ", "not glTF\n");
            const std::string escape = "escape_\x1b";  // then "c": ESC c
            write(out / (escape + "c_reset.gltf"), "not glTF\n");
            // A flat 8192 x 8192 JPEG of 256 KiB: 939 MiB decoded, staged and
            // mipmapped, what a budget of 1 GiB still lets through.
            write(out / "flat_8192.jpg", jpeg_claiming(8192, 8192, 1024 * 1024));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vkt_make_hostile_files: %s\n", e.what());
        return 1;
    }
    std::printf("vkt_make_hostile_files: wrote %s\n", out.c_str());
    return 0;
}
