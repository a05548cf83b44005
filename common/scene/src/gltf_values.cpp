// The values tinygltf reads without telling (chapter 10): see
// check_json_values in vkt/scene/gltf_guard.hpp. One pass over the JSON's
// characters with a stack of its own (the depth check has bounded it).

#include "vkt/scene/gltf_guard.hpp"

#include "vkt/core/files.hpp"

#include <array>
#include <cstdint>

namespace vkt {

namespace {

// Members whose number tinygltf narrows to an int: each an index, a count of
// texture coordinates, or an enumeration, none of them negative or past 2^31.
constexpr std::array<std::string_view, 21> integer_members = {
    "scene",         "mesh",       "camera",
    "skin",          "indices",    "material",
    "buffer",        "source",     "bufferView",
    "sampler",       "index",      "texCoord",
    "node",          "input",      "output",
    "componentType", "mode",       "target",
    "skeleton",      "byteStride", "inverseBindMatrices"};
// Arrays of indices.
constexpr std::array<std::string_view, 3> index_arrays = {"children", "nodes", "joints"};

bool one_of(std::string_view name, auto list) {
    for (std::string_view n : list)
        if (n == name) return true;
    return false;
}

// "meshes" -> "mesh", "nodes" -> "node": an array's element as messages name it.
std::string singular(std::string_view plural) {
    if (plural == "meshes") return "mesh";
    if (plural.ends_with('s')) plural.remove_suffix(1);
    return std::string(plural);
}

// A key as JSON spells it, its escapes undone where they are plain ASCII
// ("\u006desh" is "mesh" to the parser, so it is here too).
std::string key_text(std::string_view raw) {
    std::string out;
    for (size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] != '\\' || i + 1 >= raw.size()) {
            out += raw[i];
        } else if (raw[i + 1] == 'u' && i + 5 < raw.size()) {
            unsigned value = 0;
            for (size_t k = i + 2; k < i + 6; ++k) {
                const char c = raw[k];
                value = value * 16 + unsigned(c >= 'a'   ? c - 'a' + 10
                                              : c >= 'A' ? c - 'A' + 10
                                                         : c - '0');
            }
            out += value < 0x80 ? char(value) : '?';
            i += 5;
        } else {
            out += raw[++i];
        }
    }
    return out;
}

struct Frame {
    bool array = false;
    std::string key;      // an object's member being read; an array: the member it is
    size_t elements = 0;  // an array's elements so far
};

class ValueCheck {
public:
    explicit ValueCheck(std::string_view json) : json_(json) {}

    std::optional<std::string> run() {
        for (size_t i = 0; i < json_.size() && !why_; ++i) {
            const char c = json_[i];
            if (c == '"') {
                const size_t start = i + 1;
                for (++i; i < json_.size() && json_[i] != '"'; ++i)
                    if (json_[i] == '\\') ++i;
                const std::string_view text =
                    json_.substr(start, std::min(i, json_.size()) - start);
                if (expect_key_)
                    stack_.back().key = key_text(text);
                else
                    value(false);
                expect_key_ = false;
            } else if (c == '{' || c == '[') {
                if (stack_.size() > 2 * gltf_max_json_depth) return std::nullopt;
                if (!stack_.empty()) value(c == '[');
                stack_.push_back({c == '[', stack_.empty() ? std::string() : stack_.back().key, 0});
                expect_key_ = c == '{';
            } else if (c == '}' || c == ']') {
                if (stack_.empty()) return std::nullopt;
                const Frame closed = stack_.back();
                stack_.pop_back();
                if (closed.array) check_factor_length(closed);
                expect_key_ = false;
            } else if (c == ',') {
                expect_key_ = !stack_.empty() && !stack_.back().array;
            } else if (c == '-' || (c >= '0' && c <= '9') || c == 't' || c == 'f' || c == 'n') {
                size_t end = i;
                while (end < json_.size() && json_[end] != ',' && json_[end] != '}' &&
                       json_[end] != ']' && json_[end] != ' ' && json_[end] != '\n' &&
                       json_[end] != '\r' && json_[end] != '\t')
                    ++end;
                const std::string_view token = json_.substr(i, end - i);
                value(false);
                if (!stack_.empty() && !ignored()) check_integer(token);
                i = end - 1;
            }
        }
        return why_;
    }

private:
    // Inside "extras" or "extensions": an application's data, or an
    // extension this loader ignores.
    bool ignored() const {
        for (const Frame& f : stack_)
            if (f.key == "extras" || f.key == "extensions") return true;
        return false;
    }

    // A value begins: an array counts it; a factor must be an array.
    void value(bool is_array) {
        if (stack_.empty()) return;
        Frame& top = stack_.back();
        if (top.array) {
            ++top.elements;
        } else if (!is_array && factor_length(stack_.size(), top.key) > 0 && !ignored()) {
            why_ = element_name(stack_.size()) + ": \"" + top.key + "\" is not an array of " +
                   std::to_string(factor_length(stack_.size(), top.key)) + " numbers";
        }
    }

    // How many numbers the factor member `key` of the object at depth `depth`
    // must hold, or 0 where it is not one: materials[i].emissiveFactor (3),
    // materials[i].pbrMetallicRoughness.baseColorFactor (4).
    size_t factor_length(size_t depth, const std::string& key) const {
        if (depth < 3 || stack_[1].key != "materials") return 0;
        if (depth == 3 && key == "emissiveFactor") return 3;
        if (depth == 4 && stack_[2].key == "pbrMetallicRoughness" && key == "baseColorFactor")
            return 4;
        return 0;
    }

    void check_factor_length(const Frame& closed) {
        const size_t wanted = factor_length(stack_.size(), closed.key);
        if (wanted == 0 || closed.elements == wanted || ignored()) return;
        why_ = element_name(stack_.size()) + ": \"" + closed.key + "\" has " +
               std::to_string(closed.elements) + " numbers, not " + std::to_string(wanted) +
               (closed.key == "baseColorFactor"
                    ? " (tinygltf would drop the whole pbrMetallicRoughness block, its "
                      "textures too, without a word)"
                    : "");
    }

    void check_integer(std::string_view token) {
        const Frame& top = stack_.back();
        const bool in_attributes =
            stack_.size() >= 2 && !top.array &&
            (stack_[stack_.size() - 2].key == "attributes" ||
             (stack_[stack_.size() - 2].array && stack_[stack_.size() - 2].key == "targets"));
        const bool wanted = top.array ? one_of(top.key, index_arrays)
                                      : (in_attributes || one_of(top.key, integer_members));
        if (!wanted || stack_.size() < 2) return;
        const bool negative = token.starts_with('-');
        const std::string_view digits = negative ? token.substr(1) : token;
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos)
            return;  // not a whole number: tinygltf's own check refuses it
        const bool too_large = digits.size() > 10 || (digits.size() == 10 && digits > "2147483647");
        if (!negative && !too_large) return;
        const std::string where =
            top.array ? "\"" + top.key + "\" element " + std::to_string(top.elements - 1)
                      : "\"" + top.key + "\"";
        why_ = element_name(top.array ? stack_.size() - 1 : stack_.size()) + ": " + where + " is " +
               printable(token, 24) +
               ", which is no index: glTF's are whole numbers from 0 to 2147483647";
    }

    // The element that holds the object at `depth`, as messages name it:
    // "node 3", "mesh 0 primitive 1", "material 2 pbrMetallicRoughness".
    std::string element_name(size_t depth) const {
        std::string name;
        for (size_t d = 1; d < depth; ++d) {
            const Frame& f = stack_[d];
            if (f.array) continue;
            const Frame& parent = stack_[d - 1];
            std::string part =
                parent.array ? singular(parent.key) + " " + std::to_string(parent.elements - 1)
                             : parent.key;
            if (!name.empty()) name += ' ';
            name += printable(part, 60);
        }
        return name.empty() ? "the root object" : name;
    }

    std::string_view json_;
    std::vector<Frame> stack_;
    bool expect_key_ = false;
    std::optional<std::string> why_;
};

}  // namespace

std::optional<std::string> check_json_values(std::string_view json) {
    return ValueCheck(json).run();
}

}  // namespace vkt
