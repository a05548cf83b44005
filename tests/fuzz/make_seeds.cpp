// Writes the fuzzers' seed corpus: small valid inputs that reach deep into
// each parser, from which libFuzzer mutates. Run by the test fuzz.seeds (a
// fixture of every fuzz test), so the corpus is made by the tests, never
// checked in.
//
//   vkt_fuzz_seeds OUT_DIR   writes OUT_DIR/{gltf,image,args}/*
#include <stb_image_write.h>

#include "../unit/base64.hpp"  // the glTF unit tests' base64, for data: URIs

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<uint8_t>;

void write(const fs::path& path, const void* data, size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), std::streamsize(size));
    if (!out) throw std::runtime_error("cannot write " + path.string());
}
void write(const fs::path& path, const std::string& text) {
    write(path, text.data(), text.size());
}
void write(const fs::path& path, const Bytes& bytes) {
    write(path, bytes.data(), bytes.size());
}

void append_to(void* context, void* data, int size) {
    auto* out = static_cast<Bytes*>(context);
    out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
}

// A small picture with some structure (a gradient and a diagonal), as PNG or
// JPEG, with 1, 3 or 4 channels.
Bytes picture(int width, int height, int channels, bool jpeg) {
    std::vector<uint8_t> pixels(size_t(width) * height * channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                pixels[(size_t(y) * width + x) * channels + c] =
                    uint8_t(x == y ? 255 : (x * 32 + y * 16 + c * 64) & 0xff);
    Bytes out;
    if (jpeg)
        stbi_write_jpg_to_func(append_to, &out, width, height, channels, pixels.data(), 90);
    else
        stbi_write_png_to_func(append_to, &out, width, height, channels, pixels.data(),
                               width * channels);
    return out;
}

template <typename T>
void put(Bytes& out, const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof value);
}

// A textured quad: 4 vertices (position, normal, uv as floats), 6 16-bit
// indices, then (when given) the bytes of a PNG, each part 4-byte aligned.
Bytes quad_buffer(const Bytes& png) {
    Bytes out;
    const float v[4][8] = {{-1, -1, 0, 0, 0, 1, 0, 1},
                           {1, -1, 0, 0, 0, 1, 1, 1},
                           {1, 1, 0, 0, 0, 1, 1, 0},
                           {-1, 1, 0, 0, 0, 1, 0, 0}};
    for (const auto& vertex : v)
        for (float f : vertex) put(out, f);
    for (const uint16_t i : std::initializer_list<uint16_t>{0, 1, 2, 0, 2, 3}) put(out, i);
    out.insert(out.end(), png.begin(), png.end());
    while (out.size() % 4) out.push_back(0);
    return out;
}

// The JSON of the quad; `buffer_uri` empty for a .glb (its BIN chunk), and
// the image either in a bufferView (after the indices) or at `image_uri`.
std::string quad_json(const std::string& buffer_uri, size_t buffer_size, size_t png_size,
                      const std::string& image_uri) {
    const std::string uri = buffer_uri.empty() ? "" : "\"uri\": \"" + buffer_uri + "\", ";
    const std::string image = image_uri.empty() ? "{\"bufferView\": 2, \"mimeType\": \"image/png\"}"
                                                : "{\"uri\": \"" + image_uri + "\"}";
    const std::string image_view =
        image_uri.empty()
            ? ", {\"buffer\": 0, \"byteOffset\": 140, \"byteLength\": " + std::to_string(png_size) +
                  "}"
            : "";
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"mesh": 0, "children": [1]}, {"mesh": 0, "translation": [0, 0, -1],
            "rotation": [0, 0.7071068, 0, 0.7071068], "scale": [2, 2, 2]}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                            "indices": 3, "material": 0, "mode": 4}]}],
 "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.5, 1],
                                         "baseColorTexture": {"index": 0}}}],
 "textures": [{"source": 0, "sampler": 0}], "samplers": [{}],
 "images": [)" +
           image + R"(],
 "buffers": [{)" +
           uri + "\"byteLength\": " + std::to_string(buffer_size) + R"(}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 128, "byteStride": 32},
                 {"buffer": 0, "byteOffset": 128, "byteLength": 12})" +
           image_view + R"(],
 "accessors": [
  {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 4, "type": "VEC3",
   "min": [-1, -1, 0], "max": [1, 1, 0]},
  {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 4, "type": "VEC3"},
  {"bufferView": 0, "byteOffset": 24, "componentType": 5126, "count": 4, "type": "VEC2"},
  {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
)";
}

// The quad with what the loader skips with a warning (an animation, a skin,
// two cameras, a light, extras): seeds for tinygltf's parsers of those, which
// ten minutes of mutation from the other seeds never reached
// (tests/fuzz/long-runs.md).
std::string with_skipped_parts(std::string json) {
    json.insert(json.rfind('}'), R"(,
 "animations": [{"channels": [{"sampler": 0, "target": {"node": 1, "path": "rotation"}}],
                 "samplers": [{"input": 3, "output": 2, "interpolation": "LINEAR"}]}],
 "skins": [{"joints": [1], "skeleton": 1}],
 "cameras": [{"type": "perspective",
              "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100, "aspectRatio": 1.5}},
             {"type": "orthographic",
              "orthographic": {"xmag": 1, "ymag": 1, "znear": 0, "zfar": 10}}],
 "extensionsUsed": ["KHR_lights_punctual"],
 "extensions": {"KHR_lights_punctual": {"lights": [{"type": "spot", "color": [1, 1, 1],
   "intensity": 2, "spot": {"innerConeAngle": 0.1, "outerConeAngle": 0.7}}]}},
 "extras": {"author": "vkt", "list": [1, [2, [3]], {"a": null, "b": true, "c": "text"}]})");
    return json;
}

// A .glb container: header, JSON chunk (space-padded), BIN chunk.
Bytes glb(std::string json, const Bytes& bin) {
    while (json.size() % 4) json += ' ';
    Bytes out;
    const uint32_t total = uint32_t(12 + 8 + json.size() + 8 + bin.size());
    put(out, uint32_t(0x46546C67));  // "glTF"
    put(out, uint32_t(2));
    put(out, total);
    put(out, uint32_t(json.size()));
    put(out, uint32_t(0x4E4F534A));  // "JSON"
    out.insert(out.end(), json.begin(), json.end());
    put(out, uint32_t(bin.size()));
    put(out, uint32_t(0x004E4942));  // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

void gltf_seeds(const fs::path& dir, const fs::path& assets) {
    // The repository's scene (its scene.bin and textures sit beside the
    // fuzzer's input, see fuzz_gltf.cpp), as .gltf and as .glb.
    fs::copy_file(assets / "gltf/scene.gltf", dir / "scene.gltf");
    fs::copy_file(assets / "gltf/scene.glb", dir / "scene.glb");
    const Bytes png = picture(4, 4, 4, false);
    // Everything inline: the buffer and the image as data: URIs.
    const Bytes plain = quad_buffer({});
    write(dir / "quad_data_uris.gltf",
          quad_json("data:application/octet-stream;base64," + vkt_test::base64(plain), plain.size(),
                    0, "data:image/png;base64," + vkt_test::base64(png)));
    write(dir / "quad_skipped_parts.gltf",
          with_skipped_parts(
              quad_json("data:application/octet-stream;base64," + vkt_test::base64(plain),
                        plain.size(), 0, "data:image/png;base64," + vkt_test::base64(png))));
    // External files beside it: the repository's scene.bin and checker.png.
    // scene.bin's first 140 bytes are not this quad, so the loader refuses
    // it (an index past the vertices): a seed for the checks' paths.
    write(dir / "quad_external_bad_indices.gltf", quad_json("scene.bin", 31432, 0, "checker.png"));
    // A .glb with the image in a bufferView of the BIN chunk.
    const Bytes with_png = quad_buffer(png);
    write(dir / "quad_image_view.glb",
          glb(quad_json("", with_png.size(), png.size(), ""), with_png));
}

void image_seeds(const fs::path& dir, const fs::path& assets) {
    for (int channels : {1, 3, 4}) {
        const std::string name = std::to_string(channels) + "ch";
        write(dir / ("gradient_" + name + ".png"), picture(16, 8, channels, false));
        write(dir / ("gradient_" + name + ".jpg"), picture(16, 8, channels, true));
    }
    write(dir / "one_pixel.png", picture(1, 1, 4, false));
    write(dir / "odd_size.jpg", picture(9, 17, 3, true));
    fs::copy_file(assets / "textures/checker.png", dir / "checker.png");
    fs::copy_file(assets / "gltf/stripes.png", dir / "stripes.png");
}

void args_seeds(const fs::path& dir) {
    // A seed: one byte for which flags the chapter accepts (0 chapter 01's,
    // 1 chapter 02's, 2 a drawing chapter's), then the arguments, each ended
    // by a NUL byte.
    const std::vector<std::pair<char, std::vector<std::string>>> lists = {
        {2, {"--headless", "--frames", "10", "--size", "320x240"}},
        {2, {"--offscreen", "--screenshot", "out.png", "--benchmark", "--no-validation"}},
        {2, {"--lights=4096", "--shade", "compute", "--warmup", "0.5", "--model", "a.gltf"}},
        {2, {"--speed", "12.5", "--device", "0", "--validation", "--help"}},
        {1, {"--device", "lavapipe", "--validation"}},
        {0, {"--no-validation", "-h"}},
    };
    int n = 0;
    for (const auto& [flags, words] : lists) {
        std::string seed(1, flags);
        for (const std::string& word : words) seed += word + '\0';
        write(dir / ("args_" + std::to_string(n++)), seed);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: vkt_fuzz_seeds OUT_DIR\n");
        return 2;
    }
    const fs::path out = argv[1];
    const fs::path assets = fs::path(VKT_SOURCE_DIR) / "assets";
    try {
        for (const char* kind : {"gltf", "image", "args"}) {
            fs::remove_all(out / kind);
            fs::create_directories(out / kind);
        }
        gltf_seeds(out / "gltf", assets);
        image_seeds(out / "image", assets);
        args_seeds(out / "args");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vkt_fuzz_seeds: %s\n", e.what());
        return 1;
    }
    std::printf("vkt_fuzz_seeds: wrote the seed corpus to %s\n", out.c_str());
    return 0;
}
