// The files a chapter reads from its user (vkt/core/files.hpp) and the files a
// glTF model names (chapter 10's loader, through tinygltf's FsCallbacks of our
// own): regular files of 1 GiB at most, and only inside the model's folder.
// Every fixture is written here, into the build folder; the files "past
// 1 GiB" are sparse (resize_file), so they take no disk space, and are removed.

#include "base64.hpp"
#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"
#include "vkt/scene/gltf.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using Catch::Matchers::ContainsSubstring;
namespace fs = std::filesystem;

namespace {

// build/<preset>/test_gltf_files/<test>/model, the model's folder, and
// .../<test>/outside beside it; one pair per test, since tests run in parallel.
struct Folders {
    fs::path root, model, outside;
    explicit Folders(const std::string& test)
        : root(fs::path(VKT_BINARY_DIR) / "test_gltf_files" / test),
          model(root / "model"),
          outside(root / "outside") {
        fs::create_directories(model / "sub");
        fs::create_directories(outside);
    }
};

void write_bytes(const fs::path& path, const std::vector<uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    REQUIRE(out.good());
}
fs::path write_text(const fs::path& path, const std::string& text) {
    write_bytes(path, std::vector<uint8_t>(text.begin(), text.end()));
    return path;
}

// A file of `size` bytes that holds none: a hole the file system does not store.
fs::path sparse_file(const fs::path& path, uintmax_t size) {
    write_text(path, "");
    fs::resize_file(path, size);
    return path;
}

// One triangle, (0,0,0) (1,0,0) (0,1,0), and its 16-bit indices 0 1 2: 44 bytes.
std::vector<uint8_t> triangle_bin() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t indices[4] = {0, 1, 2, 0};
    std::vector<uint8_t> bytes(44);
    std::memcpy(bytes.data(), positions, 36);
    std::memcpy(bytes.data() + 36, indices, 8);
    return bytes;
}

using vkt_test::base64;  // tests/unit/base64.hpp

// The triangle's glTF with its buffer at `uri` (byteLength `length`), and
// `extra` after the buffers (images, say).
std::string triangle_json(const std::string& uri, uintmax_t length = 44,
                          const std::string& extra = "") {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"byteLength": )" +
           std::to_string(length) + R"(, "uri": ")" + uri + "\"}]" + extra + "}";
}

// A .glb of JSON only: its buffer is the external file the JSON names.
std::vector<uint8_t> glb_of(std::string json) {
    while (json.size() % 4) json += ' ';
    std::string out;  // the header and the chunk's header, little-endian
    auto u32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) out += char(uint8_t(v >> (8 * i)));
    };
    out += "glTF";
    u32(2);
    u32(uint32_t(12 + 8 + json.size()));
    u32(uint32_t(json.size()));
    out += "JSON" + json;
    return {out.begin(), out.end()};
}

template <typename F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const vkt::Error& e) {
        return e.what();
    }
    return "";
}
std::string load_error(const fs::path& path) {
    return error_of([&] { vkt::load_gltf(path); });
}
std::string model_error(const Folders& f, const std::string& name, const std::string& json) {
    return load_error(write_text(f.model / name, json));
}

}  // namespace

TEST_CASE("files: read_file looks before it reads, and names what it refuses", "[files]") {
    const Folders f("read_file");
    CHECK_THAT(error_of([&] { vkt::read_file(f.root / "no-such-file"); }),
               ContainsSubstring("cannot open") && ContainsSubstring("no-such-file"));
    // A directory "opens", and its end is at 2^63 - 1: std::bad_alloc before.
    CHECK(error_of([&] { vkt::read_file(f.model); }) ==
          f.model.string() + ": is a directory, not a file");
#ifndef _WIN32  // no /dev/zero on Windows
    CHECK(error_of([&] { vkt::read_file("/dev/zero"); }) == "/dev/zero: is not a regular file");
#endif
    const fs::path huge = sparse_file(f.root / "huge.bin", vkt::max_file_bytes + 1);
    CHECK(error_of([&] { vkt::read_file(huge); }) ==
          huge.string() + ": is 1073741825 bytes, past the 1 GiB limit for one file");
    fs::remove(huge);
}

TEST_CASE("files: a path that is not plain is quoted and escaped in messages", "[files]") {
    CHECK(vkt::shown_path("models/car.gltf") == "models/car.gltf");
    CHECK(vkt::shown_path("my models/car.gltf") == "my models/car.gltf");  // a space inside: plain
    CHECK(vkt::shown_path("models/car.gltf ") == "\"models/car.gltf \"");
    CHECK(vkt::shown_path(" car.gltf") == "\" car.gltf\"");
    CHECK(vkt::shown_path("escape_\x1b"
                          "c_reset.gltf") == "\"escape_\\x1bc_reset.gltf\"");
    CHECK(vkt::shown_path("two\nlines\t.gltf") == "\"two\\nlines\\t.gltf\"");
    CHECK(vkt::shown_path("say \"hi\"\\.gltf") == "\"say \\\"hi\\\"\\\\.gltf\"");
    CHECK(vkt::shown_path("") == "\"\"");
    // And read_file's refusals show it so.
    CHECK(error_of([] {
              vkt::read_file(
                  "no-such \x1b"
                  "c.gltf ");
          }) == "cannot open \"no-such \\x1bc.gltf \"");
}

#ifdef __linux__
TEST_CASE(
    "files: a file of /proc, whose size reads as 0, is read from its first bytes, never whole",
    "[files]") {
    const std::vector<char> start = vkt::read_file_start("/proc/self/status", 5);
    CHECK(std::string(start.begin(), start.end()) == "Name:");
    CHECK(error_of([] { vkt::read_file("/proc/self/status"); }) ==
          "/proc/self/status: its size reads as 0 bytes, yet it holds data (a file of /proc or "
          "/sys?): only a file whose size is known is read");
}
#endif

TEST_CASE("files: resolve_inside keeps a URI inside its folder", "[files]") {
    const Folders f("resolve_inside");
    const fs::path folder = f.model;
    const fs::path real = fs::canonical(folder);
    CHECK(vkt::resolve_inside(folder, "a.bin") == real / "a.bin");
    CHECK(vkt::resolve_inside(folder, "sub/../a.bin") == real / "a.bin");
    CHECK(vkt::resolve_inside(folder, "sub/b.bin") == real / "sub" / "b.bin");
    CHECK_THAT(error_of([&] { vkt::resolve_inside(folder, "../a.bin"); }),
               ContainsSubstring("URI \"../a.bin\" leads out of the model's folder"));
    CHECK_THAT(error_of([&] { vkt::resolve_inside(folder, "sub/../../model2/a.bin"); }),
               ContainsSubstring("leads out of the model's folder"));
    CHECK_THAT(error_of([&] { vkt::resolve_inside(folder, "/etc/passwd"); }),
               ContainsSubstring("URI \"/etc/passwd\" is an absolute path"));
    CHECK(error_of([&] { vkt::resolve_inside(folder, std::string("\0AAA", 4)); }) ==
          "URI \"%00AAA\" is not a file name: it holds a control character");
    CHECK_THAT(error_of([&] { vkt::resolve_inside(folder, ""); }), ContainsSubstring("empty URI"));

    // A symbolic link counts where it leads: out is out, in is in. (Not in the
    // Windows build: MinGW's std::filesystem cannot make symbolic links, it
    // fails with ENOSYS.)
#ifndef _WIN32
    fs::remove(folder / "out");
    fs::remove(folder / "in");
    fs::create_directory_symlink(f.outside, folder / "out");
    fs::create_directory_symlink(folder / "sub", folder / "in");
    CHECK_THAT(error_of([&] { vkt::resolve_inside(folder, "out/a.bin"); }),
               ContainsSubstring("URI \"out/a.bin\" leads out of the model's folder"));
    CHECK(vkt::resolve_inside(folder, "in/b.bin") == real / "sub" / "b.bin");
#endif
}

TEST_CASE("gltf files: buffers inside the model's folder load", "[gltf][files]") {
    const Folders f("inside");
    write_bytes(f.model / "tri.bin", triangle_bin());
    write_bytes(f.model / "sub" / "tri angle.bin", triangle_bin());
    for (const char* uri : {"tri.bin", "sub/../tri.bin", "sub/tri%20angle.bin"}) {
        INFO(uri);
        const vkt::GltfScene scene =
            vkt::load_gltf(write_text(f.model / "inside.gltf", triangle_json(uri)));
        CHECK(scene.indices == std::vector<uint32_t>{0, 1, 2});
    }
    const fs::path glb = f.model / "inside.glb";
    write_bytes(glb, glb_of(triangle_json("sub/tri%20angle.bin")));
    CHECK(load_error(glb).empty());
    // A path relative to the working directory: the folder is found all the same.
    const fs::path cwd = fs::current_path();
    fs::current_path(f.model);
    CHECK(load_error("inside.gltf").empty());
    fs::current_path(cwd);
}

TEST_CASE("gltf files: no URI reads outside the model's folder", "[gltf][files]") {
    const Folders f("outside");
    // A buffer that would load, were it allowed: right bytes, right length.
    write_bytes(f.outside / "tri.bin", triangle_bin());
    CHECK_THAT(
        model_error(f, "sibling.gltf", triangle_json("../outside/tri.bin")),
        ContainsSubstring("sibling.gltf: buffer 0: URI \"../outside/tri.bin\" leads out of the "
                          "model's folder"));
    std::error_code error;
    const uintmax_t passwd = fs::file_size("/etc/passwd", error);
    CHECK_THAT(
        model_error(f, "passwd.gltf",
                    triangle_json("../../../../../../etc/passwd", error ? 44 : passwd)),
        ContainsSubstring("passwd.gltf: buffer 0: URI \"../../../../../../etc/passwd\" leads out"));
    // generic_string: '/' between the names, which JSON takes as it is (a
    // Windows '\\' would have to be escaped).
    const std::string absolute = (f.outside / "tri.bin").generic_string();
    CHECK_THAT(
        model_error(f, "absolute.gltf", triangle_json(absolute)),
        ContainsSubstring("absolute.gltf: buffer 0: URI \"" + absolute + "\" is an absolute path"));
#ifndef _WIN32  // MinGW's std::filesystem makes no symbolic links
    fs::remove(f.model / "out");
    fs::create_directory_symlink(f.outside, f.model / "out");
    CHECK_THAT(model_error(f, "symlink.gltf", triangle_json("out/tri.bin")),
               ContainsSubstring("symlink.gltf: buffer 0: URI \"out/tri.bin\" leads out"));
#endif
    // %2e%2e is "..", once tinygltf has %-decoded it.
    CHECK_THAT(model_error(f, "encoded.gltf", triangle_json("%2e%2e/outside/tri.bin")),
               ContainsSubstring("URI \"../outside/tri.bin\" leads out"));
    // The same rule for a .glb, and for an image (which tinygltf only warns about).
    const fs::path glb = f.model / "sibling.glb";
    write_bytes(glb, glb_of(triangle_json("../outside/tri.bin")));
    CHECK_THAT(load_error(glb),
               ContainsSubstring("sibling.glb: buffer 0: URI \"../outside/tri.bin\" leads out"));
    write_bytes(f.model / "tri.bin", triangle_bin());
    CHECK_THAT(
        model_error(f, "image.gltf",
                    triangle_json("tri.bin", 44, R"(, "images": [{"uri": "../outside/a.png"}])")),
        ContainsSubstring("image.gltf: image 0: URI \"../outside/a.png\" leads out"));
}

TEST_CASE("gltf files: tinygltf issue 416's URI is one line naming it", "[gltf][files]") {
    const Folders f("issue416");
    // "%!Q" %-decodes to a NUL byte; tinygltf alone then reads the folder as a
    // file and asks for 2^63 bytes (std::bad_alloc; an abort under ASan).
    write_bytes(f.model / "tri.bin", triangle_bin());
    const std::string error =
        model_error(f, "issue416.gltf",
                    triangle_json("tri.bin", 44, R"(, "images": [{"uri": "%!QAAAQAAA5"}])"));
    CHECK(error == (f.model / "issue416.gltf").string() +
                       ": image 0: URI \"%00AAAQAAA5\" is not a file name: it holds a control "
                       "character");
}

TEST_CASE("gltf files: directories and files past 1 GiB are refused by name", "[gltf][files]") {
    const Folders f("sizes");
    CHECK(load_error(f.model) == f.model.string() + ": is a directory, not a file");
    write_bytes(f.model / "tri.bin", triangle_bin());
    CHECK_THAT(model_error(f, "dir_buffer.gltf", triangle_json("sub")),
               ContainsSubstring("dir_buffer.gltf: ") &&
                   ContainsSubstring("sub: is a directory, not a file"));
    CHECK_THAT(
        model_error(f, "dir_image.gltf",
                    triangle_json("tri.bin", 44, R"(, "images": [{"uri": "."}])")),
        ContainsSubstring("dir_image.gltf: ") && ContainsSubstring(": is a directory, not a file"));

    const fs::path huge = sparse_file(f.model / "huge.bin", vkt::max_file_bytes + 1);
    CHECK_THAT(model_error(f, "huge_buffer.gltf", triangle_json("huge.bin", 44)),
               ContainsSubstring("huge_buffer.gltf: ") &&
                   ContainsSubstring("huge.bin: is 1073741825 bytes, past the 1 GiB limit"));
    fs::remove(huge);
    const fs::path huge_model = sparse_file(f.model / "huge.gltf", vkt::max_file_bytes + 1);
    CHECK(load_error(huge_model) ==
          huge_model.string() + ": is 1073741825 bytes, past the 1 GiB limit for one file");
    fs::remove(huge_model);
}

TEST_CASE("gltf files: data URIs are checked against their byteLength", "[gltf][files]") {
    const Folders f("data_uris");
    const std::string good = "data:application/octet-stream;base64," + base64(triangle_bin());
    CHECK(model_error(f, "data_good.gltf", triangle_json(good)).empty());
    // Decoded, the URI holds 44 bytes, not 4000 (nor 40): refused, and the
    // message quotes the URI only in part, so it stays one short line.
    for (uintmax_t length : {4000, 40}) {
        const std::string error = model_error(f, "data_length.gltf", triangle_json(good, length));
        CHECK_THAT(error, ContainsSubstring("data_length.gltf: buffer 0: data URI "
                                            "\"data:application/octet-stream;base64,") &&
                              ContainsSubstring("...\" is invalid: its base64 decodes to 44 "
                                                "bytes, not the buffer's byteLength " +
                                                std::to_string(length)));
        CHECK(error.find('\n') == std::string::npos);
    }
    const std::string long_uri =
        "data:application/octet-stream;base64," + base64(std::vector<uint8_t>(30000, 7));
    const std::string error = model_error(f, "data_long.gltf", triangle_json(long_uri, 44));
    CHECK_THAT(error, ContainsSubstring("data_long.gltf: buffer 0: data URI "));
    CHECK(error.size() < 400);
    // A data: URI tinygltf does not know would be a file name: refused as such.
    CHECK_THAT(
        model_error(f, "data_webp.gltf", triangle_json("data:image/webp;base64,AAAA")),
        ContainsSubstring("data_webp.gltf: buffer 0: URI \"data:image/webp;base64,AAAA\" is a "
                          "data: URI of a kind tinygltf does not decode"));
}
