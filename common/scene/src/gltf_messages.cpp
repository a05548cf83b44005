// Why tinygltf refused a model, in the loader's one form (chapter 10):
// "FILE: WHAT: WHY", WHAT the buffer, image, accessor, ... by index and
// name, WHY in words that need no knowledge of tinygltf or of its JSON
// library. tinygltf's own words are kept only where nothing better is known,
// and then behind what they are about.
//
// tinygltf says which property is wrong but not in which element. It parses
// the root's arrays in one order (parse_order below) and keeps each element
// it has finished, so the first array of which it kept fewer elements than
// the JSON holds is the one it failed in, and the count it kept is the
// index of the element it failed on.

#include "gltf_internal.hpp"

#include "vkt/core/files.hpp"

#include <array>
#include <cstring>
#include <utility>

namespace vkt::gltf_detail {

namespace {

bool contains(const std::string& text, const char* part) {
    return text.find(part) != std::string::npos;
}

// The text between the first `open` and the next `close` after it; empty if none.
std::string between(const std::string& text, const std::string& open, const std::string& close) {
    const size_t start = text.find(open);
    if (start == std::string::npos) return {};
    const size_t from = start + open.size();
    const size_t end = text.find(close, from);
    return end == std::string::npos ? std::string() : text.substr(from, end - from);
}

// "buffer 2", or "buffer 2 ("wheels")" where the JSON gives it a name.
std::string element(std::string_view json, const char* array, const char* one, size_t index) {
    const std::string name = json_element_name(json, array, index);
    return std::string(one) + " " + std::to_string(index) +
           (name.empty() ? "" : " (\"" + printable(name, 60) + "\")");
}

// The element tinygltf failed on (see the top of this file); empty where every
// array it parses is whole, so the fault lies elsewhere.
std::string failed_element(std::string_view json, const tinygltf::Model& m) {
    struct Kept {
        const char* array;  // "buffers", as the JSON names the array
        const char* one;    // "buffer", as the message names an element
        size_t parsed;      // how many of them tinygltf kept
    };
    const std::array<Kept, 13> kept = {{
        {"buffers", "buffer", m.buffers.size()},
        {"bufferViews", "bufferView", m.bufferViews.size()},
        {"accessors", "accessor", m.accessors.size()},
        {"meshes", "mesh", m.meshes.size()},
        {"nodes", "node", m.nodes.size()},
        {"scenes", "scene", m.scenes.size()},
        {"materials", "material", m.materials.size()},
        {"images", "image", m.images.size()},
        {"textures", "texture", m.textures.size()},
        {"animations", "animation", m.animations.size()},
        {"skins", "skin", m.skins.size()},
        {"samplers", "sampler", m.samplers.size()},
        {"cameras", "camera", m.cameras.size()},
    }};
    for (const Kept& k : kept) {
        const std::optional<size_t> in_json = json_array_size(json, k.array);
        if (in_json && k.parsed < *in_json) return element(json, k.array, k.one, k.parsed);
    }
    return {};
}

// nlohmann::json's exception text, "[json.exception.KIND.ID] what": KIND.ID
// means nothing to a reader; say what it is about.
std::optional<std::string> json_library_error(const std::string& err, std::string_view json) {
    const std::string tag = between(err, "[json.exception.", "]");
    if (tag.empty()) return std::nullopt;
    std::string what = first_line(err.substr(err.find(']') + 1));
    if (!what.empty() && what.front() == ' ') what.erase(0, 1);
    if (tag == "out_of_range.406") {  // "number overflow parsing '1e309'"
        const std::string number = between(what, "'", "'");
        return "JSON: the number " + printable(number, 40) +
               " is too large for a double (largest about 1.8e308)";
    }
    if (tag.rfind("parse_error", 0) == 0) {
        const size_t first = json.find_first_not_of(" \t\r\n");
        if (first == std::string_view::npos || json[first] != '{')
            return "not a glTF file: a .gltf is a JSON object, beginning with '{', and this "
                   "begins with \"" +
                   printable(json.substr(first == std::string_view::npos ? 0 : first, 12), 12) +
                   "\"";
        // "parse error at line 3, column 5: syntax error while parsing ..."
        if (what.rfind("parse error ", 0) == 0) what.erase(0, std::strlen("parse error "));
        return "JSON: malformed " + what;
    }
    if (tag == "type_error.316")  // invalid UTF-8 in a string
        return "JSON: a string is not valid UTF-8 (" + what + ")";
    return "JSON: the JSON parser refuses it: " + what;
}

// tinygltf fails the whole file on a data: URI whose base64 it cannot
// decode, in words that name neither what was wrong nor where ("Failed to
// decode 'uri' : data:...;base64,AAA in Buffer", "Failed to decode 'uri' for
// image[2] name = []"). tinygltf's decoder gives up when the base64 decodes
// to nothing or, for a buffer, to other than its byteLength.
std::optional<std::string> invalid_data_uri(const std::string& line, const std::string& failed) {
    const std::string buffer_text = "Failed to decode 'uri' : ";
    if (line.rfind(buffer_text, 0) == 0 && line.ends_with(" in Buffer")) {
        const std::string uri = line.substr(
            buffer_text.size(), line.size() - buffer_text.size() - std::strlen(" in Buffer"));
        return failed + ": data URI \"" + printable(uri, 60) +
               "\" is invalid: its base64 does not decode to the buffer's byteLength";
    }
    if (line.rfind("Failed to decode 'uri' for image[", 0) == 0)
        return failed + ": its data URI is invalid: its base64 decodes to no bytes";
    return std::nullopt;
}

// tinygltf's other words about one element: a property missing or of the
// wrong type, a file missing or of the wrong size.
std::string property_fault(const std::string& line) {
    const std::string property = between(line, "'", "'");
    if (!property.empty() && contains(line, "' property is missing"))
        return "the required property \"" + property + "\" is missing";
    if (!property.empty() && contains(line, "' property is not ")) {
        std::string kind = line.substr(line.find("' property is not ") + 18);
        if (kind.ends_with(" type")) kind.erase(kind.size() - 5);
        return "the property \"" + property + "\" is not " + kind;
    }
    if (line.rfind("File not found : ", 0) == 0)
        return "its file \"" + printable(line.substr(17), 80) +
               "\" does not exist in the model's folder";
    if (line.rfind("File size mismatch : ", 0) == 0) {
        const std::string wanted = between(line, "requestedBytes ", ",");
        const std::string got = line.substr(line.rfind(' ') + 1);
        const std::string name = between(line, " : ", ", requestedBytes");
        return "its file \"" + printable(name, 120) + "\" holds " + got +
               " bytes, not its byteLength " + wanted;
    }
    if (line.rfind("File is empty : ", 0) == 0) return "its file is empty";
    return {};
}

}  // namespace

std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '.'))
        line.pop_back();
    return printable(line, 200);
}

std::string explain_load_failure(const LoadFailure& failure, const tinygltf::Model& model,
                                 std::span<const char> file) {
    const std::string_view json = gltf_json_text(file);
    const std::string& err = failure.err;
    const std::string line = first_line(err);
    const std::string failed = failed_element(json, model);
    const bool glb = file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0;

    // Before our refusal: tinygltf asks for the file "" after saying this.
    if (contains(err, "'uri' is missing from non binary glTF file buffer"))
        return (failed.empty() ? "a buffer" : failed) +
               ": its \"uri\" is missing: in a .gltf every buffer names its bytes by a URI (a "
               "file beside the model, or a data: URI)";
    if (!failure.refusal.empty()) {
        // An image's URI: tinygltf only warned, so no array was cut short.
        const std::string about = !failed.empty() ? failed
                                  : failure.refused_image < model.images.size()
                                      ? element(json, "images", "image", failure.refused_image)
                                      : std::string();
        return about.empty() ? failure.refusal : about + ": " + failure.refusal;
    }
    if (std::optional<std::string> json_error = json_library_error(err, json)) return *json_error;
    if (contains(err, "Root element is not a JSON object"))
        return "not a glTF file: its JSON is an array or a single value, not an object";
    if (contains(err, "JSON string too short"))
        return "not a glTF file: its " + std::to_string(json.size()) +
               " bytes are too few for any glTF";
    if (contains(err, "\"asset\" object not found"))
        return R"(not a glTF file: it has no "asset" object with a "version")";
    // The whole line: printable() would cut a long data: URI before its " in Buffer".
    if (std::optional<std::string> data_uri = invalid_data_uri(
            err.substr(0, err.find('\n')), failed.empty() ? "a buffer or an image" : failed))
        return *data_uri;
    // tinygltf checks an index accessor's view while it reads a mesh, and
    // the element it was reading is not the one at fault: the accessor is.
    if (const std::string n = between(line, "accessor[", "] invalid bufferView"); !n.empty()) {
        // Its meshes are whole by then: name the first primitive that uses it.
        std::string user;
        for (size_t m = 0; m < model.meshes.size() && user.empty(); ++m)
            for (size_t p = 0; p < model.meshes[m].primitives.size() && user.empty(); ++p)
                if (std::to_string(model.meshes[m].primitives[p].indices) == n)
                    user = "mesh " + std::to_string(m) + " primitive " + std::to_string(p) + ": ";
        return user + "index accessor " + printable(n, 12) +
               " has no bufferView (or one that does not exist): glTF requires one for indices";
    }
    const std::string what = failed.empty() ? (glb ? ".glb" : "the model") : failed;
    if (const std::string fault = property_fault(line); !fault.empty()) return what + ": " + fault;
    if (line.empty())
        return what +
               ": tinygltf refuses it without saying why (a required property missing, or of "
               "the wrong type?)";
    return what + ": tinygltf refuses it: " + line;
}

}  // namespace vkt::gltf_detail
