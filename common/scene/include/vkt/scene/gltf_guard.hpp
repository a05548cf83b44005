#pragma once
// Chapter 10's glTF loader: what it checks in a model's bytes before tinygltf
// sees them (common/scene/src/gltf_guard.cpp). tinygltf 2.7, Debian 12's,
// trusts two things a hostile file controls:
//
//   - the JSON's nesting: it converts `extras` and `extensions` to its own
//     values by recursion, one call per level, so arrays nested some ten
//     thousand deep in any `extras` overflow the stack (exit 139);
//   - a .glb's BIN chunk length: it compares the length with the file size
//     but forgets the chunk's own 8-byte header, so a length that claims 4
//     or 8 bytes more than the file holds is accepted and read past the end.
//
// Both checks are plain loops over the bytes, with no recursion and no
// allocation that grows with the input. The JSON helpers below also serve
// the loader's messages: they find the name of "buffers"[3] without a JSON
// library, so that a message can name what tinygltf refused.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vkt {

// The deepest nesting of JSON arrays and objects a model may have. glTF's
// own schema nests at most 7 levels (root, meshes, a mesh, primitives, a
// primitive, targets, a target) and 9 or so with an extension's object;
// extras hold an application's data, which is rarely deeper than a few
// levels more. 64 leaves room for all of that many times over, and is
// hundreds of times below the depth at which tinygltf's recursion exhausts
// an 8 MiB stack (14,500 to 30,000 levels, by build; fewer under
// AddressSanitizer, whose frames are larger).
inline constexpr size_t gltf_max_json_depth = 64;

// Checks that `json` nests arrays and objects at most `limit` deep (strings,
// and escaped quotes in them, are skipped). nullopt: it does; else the
// reason, "JSON: arrays and objects nest more than 64 deep (at line 1,
// column 70); ...". Syntax is not checked: the JSON parser does that.
std::optional<std::string> check_json_depth(std::string_view json,
                                            size_t limit = gltf_max_json_depth);

// Where a .glb's chunks lie, once checked.
struct GlbLayout {
    size_t json_offset = 0, json_length = 0;  // the JSON chunk's data
    size_t chunk_count = 0;                   // JSON, BIN if any, and others
};

// Checks a .glb's 12-byte header (magic "glTF", version 2, a total length
// equal to the file's size) and walks its chunks: each 8-byte chunk header and
// its data inside the file, each length a multiple of 4 (chunks start and end
// on 4-byte boundaries), the first chunk JSON, the second (if any) BIN. Throws
// vkt::Error ".glb header: ..." or ".glb chunk N (TYPE): ..." at the first
// fault.
GlbLayout check_glb_layout(std::span<const uint8_t> file);

// Both checks, on a model file's bytes as the loader read them: a .glb (its
// first four bytes "glTF") has its layout checked and its JSON chunk's depth;
// anything else is taken as JSON. nullopt: fit for tinygltf; else the reason
// (one line, without the file's name).
std::optional<std::string> check_gltf_bytes(std::span<const char> file);

// The JSON of a model file: the whole file, or a .glb's JSON chunk (empty
// where the layout is broken: check_gltf_bytes says why).
std::string_view gltf_json_text(std::span<const char> file);

// How many elements the root object's array `member` holds ("buffers": [...]);
// nullopt where there is no such array or the JSON ends early. Expects JSON
// whose depth check_json_depth accepted.
std::optional<size_t> json_array_size(std::string_view json, std::string_view member);

// A data: URI of a buffer or an image, where its text lies in the JSON.
struct JsonDataUri {
    bool image = false;        // of "images"[index], else of "buffers"[index]
    size_t index = 0;          // the element
    size_t begin = 0;          // the string's first character (after its quote)
    size_t end = 0;            // one past its last (its closing quote)
    int64_t byte_length = -1;  // a buffer's "byteLength" where it is a whole number, else -1
};
// Every "uri" that begins "data:" in the root's "buffers" and "images",
// found by a loop over the bytes like the checks above (no recursion, no
// JSON library). A URI with an escape (a backslash) in it is left out:
// its text is not its value.
std::vector<JsonDataUri> json_data_uris(std::string_view json);

// At most how many values (numbers, strings, literals, arrays, objects) the
// JSON holds: the separators and brackets outside strings, plus one. What a
// JSON library builds grows with this count, not with the text's length.
size_t json_value_count(std::string_view json);

// The "name" of element `index` of the root's array `member`, its escapes
// undone (\uXXXX is kept as written); empty where it has none.
std::string json_element_name(std::string_view json, std::string_view member, size_t index);

// What tinygltf reads wrong without a word, checked in the JSON it parsed
// (gltf_values.cpp; "extras" and "extensions" are left alone):
//   - an index (a node's "mesh", a scene's "nodes", an attribute's accessor,
//     a texture's "source", ...) or another member tinygltf narrows to an
//     int: 4294967296 became 0 and drew mesh 0; -2147483649 became
//     2147483647. Each must be a whole number from 0 to 2^31 - 1;
//   - a material's factors: a "baseColorFactor" of other than 4 numbers made
//     tinygltf drop the whole pbrMetallicRoughness block, its texture too;
//     "emissiveFactor" must hold 3.
// nullopt where all is well; else "ELEMENT: WHY" ("node 0: \"mesh\" is
// 4294967296, which is no index: ..."). Expects JSON that parsed, nested at
// most gltf_max_json_depth deep.
std::optional<std::string> check_json_values(std::string_view json);

}  // namespace vkt
