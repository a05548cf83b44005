#pragma once
// The glTF loader's parts (chapter 10), private to common/scene: not on any
// include path, so no chapter sees tinygltf. vkt::load_gltf (gltf.hpp) is
// three steps, one file each:
//
//   gltf_files.cpp      the file, and every file it names, read through
//                       tinygltf's FsCallbacks of our own (inside the model's
//                       folder only, no directories, 1 GiB at most); tinygltf
//                       parses the JSON, the .glb chunks and the data: URIs,
//                       after gltf_guard.cpp has checked the JSON's depth and
//                       the .glb's chunks, and gltf_messages.cpp says why it
//                       refused a file
//   gltf_accessors.cpp  the bytes of a buffer view or an accessor, with every
//                       index, offset, stride and count checked first
//   gltf_materials.cpp  the materials and the images they use
//   gltf.cpp            the scene: meshes and their primitives, the node
//                       tree, flattened into GltfScene

#include "vkt/core/files.hpp"
#include "vkt/core/memory_budget.hpp"
#include "vkt/scene/gltf.hpp"
#include "vkt/scene/gltf_guard.hpp"

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace vkt::gltf_detail {

// Parses `path` (.gltf or .glb, told apart by its first four bytes). Images
// are kept as their file's bytes (Image::image), not decoded. Throws Error
// "PATH: what is wrong", one line, for a file that is missing, too large, not
// glTF, names a file outside its folder (or the folder itself), or holds a
// data: URI that does not decode. Every large allocation it makes is
// charged to `budget` first (the file, its JSON as parsed, each data: URI
// decoded, each file a URI names), and refused by it past the limit.
// tinygltf's own warnings (a value of the wrong type it ignored, say) go to
// `warn`, a line each.
tinygltf::Model parse_gltf_file(const std::filesystem::path& path, MemoryBudget& budget,
                                const std::function<void(const std::string&)>& warn);

// What a JSON value may cost once parsed, at most: nlohmann::json's 16 bytes,
// its place in an array or an object's tree, and tinygltf's own Value, into
// which it converts every value of an "extras" or "extensions".
inline constexpr uint64_t json_value_bytes = 64 + sizeof(tinygltf::Value);

// What went wrong in tinygltf's load: its error text, and our file access's
// first refusal (empty if none).
struct LoadFailure {
    std::string err;
    std::string refusal;
    // The image being read when the refusal came (tinygltf only warns about
    // an image it cannot read, and goes on), or SIZE_MAX.
    size_t refused_image = SIZE_MAX;
};
// Why tinygltf refused `file` (the model file's bytes), as "WHAT: WHY" in one
// line: WHAT the element by index and name where it can be found, "not a
// glTF file" only where the file is not one (gltf_messages.cpp).
std::string explain_load_failure(const LoadFailure& failure, const tinygltf::Model& model,
                                 std::span<const char> file);
// An element's name for a message, " (\"wheels\")", or nothing where it has none:
// messages name an element by index, and by name where it has one.
inline std::string quoted_name(const std::string& name) {
    return name.empty() ? std::string() : " (\"" + printable(name, 60) + "\")";
}

// tinygltf's complaint, fit for one line: its first line, printable, at most
// 200 characters (it may quote a whole data: URI).
std::string first_line(const std::string& text);

// gltf.SetFsCallbacks(callbacks), and where tinygltf says it refused them
// (2.9 and later answer; 2.7 cannot refuse), an Error naming SetFsCallbacks:
// without our callbacks tinygltf would read any file a URI names.
void use_fs_callbacks(tinygltf::TinyGLTF& gltf, const tinygltf::FsCallbacks& callbacks);

// What an accessor may hold for each use, as the glTF 2.0 specification lists it.
struct AllowedFormat {
    int type;
    std::vector<int> components;  // component types
    bool needs_normalized;        // integer components must be normalized
};

// Bounds-checked reads of a parsed model's data. Every failure throws Error
// "PATH: WHAT: what is wrong", WHAT saying where the caller was reading
// ("mesh 0 primitive 1 NORMAL").
class Accessors {
public:
    // `budget` is charged for every array read_floats and read_indices make.
    Accessors(const tinygltf::Model& model, std::filesystem::path path, MemoryBudget& budget)
        : model_(model), path_(std::move(path)), budget_(budget) {}

    // The bytes of buffer view `index`, checked against its buffer.
    std::span<const uint8_t> view_bytes(int index, const std::string& what) const;
    const tinygltf::Accessor& accessor(int index, const std::string& what) const;
    // Accessor `index` as floats, its components one after another (integers
    // normalised to 0..1 where the accessor says so), sparse elements applied.
    // Checks its type against `allowed` and every byte against its view.
    std::vector<float> read_floats(int index, const std::string& what,
                                   const std::vector<AllowedFormat>& allowed) const;
    // Index accessor `index` (SCALAR of an unsigned type), widened to 32 bits.
    std::vector<uint32_t> read_indices(int index, const std::string& what) const;

private:
    [[noreturn]] void fail(const std::string& what) const;
    template <typename Decode>
    void apply_sparse(const tinygltf::Accessor& a, const std::string& name, size_t element_size,
                      Decode& decode) const;
    size_t stride_of(const tinygltf::Accessor& a, size_t element_size) const;
    std::span<const uint8_t> element_range(const tinygltf::Accessor& a, const std::string& name,
                                           size_t element_size) const;

    const tinygltf::Model& model_;
    std::filesystem::path path_;
    MemoryBudget& budget_;
};

// Every material of `model` into scene.materials, and every image they use,
// decoded once, into scene.images (gltf_materials.cpp). `warn` is told what
// is skipped; a fault throws Error "PATH: what is wrong".
void load_materials(const tinygltf::Model& model, const std::filesystem::path& path,
                    const Accessors& data, MemoryBudget& budget, GltfMaterials which,
                    GltfScene& scene, const std::function<void(const std::string&)>& warn);

}  // namespace vkt::gltf_detail
