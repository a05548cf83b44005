// The glTF file and the files it names (chapter 10): tinygltf parses the
// JSON, the .glb container, the buffers and the data: URIs.

#include "gltf_internal.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"

#include <cstring>
#include <exception>
#include <limits>

namespace vkt::gltf_detail {

namespace {

// The loader's own image "decoder" for tinygltf: keep the file's bytes as they
// are, decode them later with vkt::decode_image. An image stored in a
// bufferView is skipped here: tinygltf hands it over without checking the
// view against its buffer, so we read those bytes ourselves, checked.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    image->width = image->height = 0;  // not decoded (yet)
    return true;
}

std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return line;
}

}  // namespace

tinygltf::Model parse_gltf_file(const std::filesystem::path& path) {
    auto fail = [&](const std::string& what) { throw Error(path.string() + ": " + what); };
    std::vector<char> file = read_file(path);  // "cannot open FILE"
    if (file.empty()) fail("not a glTF file: it is empty");
    if (file.size() > std::numeric_limits<unsigned int>::max())
        fail("not a glTF file this loader reads: larger than 4 GiB");
    tinygltf::TinyGLTF gltf;
    gltf.SetImageLoader(keep_image_bytes, nullptr);
    tinygltf::Model model;
    std::string err, warn_text;
    const std::string base_dir = path.parent_path().string();
    const bool glb = file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0;
    bool ok = false;
    try {
        if (glb)
            ok = gltf.LoadBinaryFromMemory(&model, &err, &warn_text,
                                           reinterpret_cast<const unsigned char*>(file.data()),
                                           static_cast<unsigned int>(file.size()), base_dir);
        else
            ok = gltf.LoadASCIIFromString(&model, &err, &warn_text, file.data(),
                                          static_cast<unsigned int>(file.size()), base_dir);
    } catch (const std::exception& e) {  // tinygltf's JSON library may throw
        err = e.what();
        ok = false;
    }
    if (!ok)
        fail(std::string("not a glTF file") + (glb ? " (.glb)" : "") + ": " +
             (err.empty() ? "tinygltf cannot parse it" : first_line(err)));
    return model;
}

}  // namespace vkt::gltf_detail
