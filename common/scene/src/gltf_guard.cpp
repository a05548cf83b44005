// The checks made on a model's bytes before tinygltf sees them (chapter 10):
// see vkt/scene/gltf_guard.hpp for what tinygltf 2.7 would do without them.

#include "vkt/scene/gltf_guard.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"

#include <cstring>

namespace vkt {

namespace {

uint32_t read_u32(std::span<const uint8_t> bytes, size_t offset) {
    // Little-endian, as glTF's binary container is on every machine.
    return uint32_t(bytes[offset]) | uint32_t(bytes[offset + 1]) << 8 |
           uint32_t(bytes[offset + 2]) << 16 | uint32_t(bytes[offset + 3]) << 24;
}

constexpr uint32_t glb_json = 0x4E4F534A;  // "JSON"
constexpr uint32_t glb_bin = 0x004E4942;   // "BIN\0"

// A chunk type as text: "JSON", "BIN", or its four bytes printed.
std::string chunk_type_name(uint32_t type) {
    if (type == glb_json) return "JSON";
    if (type == glb_bin) return "BIN";
    std::string text;
    for (int i = 0; i < 4; ++i) text += char((type >> (8 * i)) & 0xFFu);
    return printable(text, 16);
}

// Calls visit(i, c) for each character of `json` outside its strings (the
// quotes and escapes included in the strings), until visit returns false.
// JSON allows no raw line break inside a string, so every one is seen.
template <class Visit>
void for_each_outside_strings(std::string_view json, Visit visit) {
    bool in_string = false, escaped = false;
    for (size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (in_string) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (!visit(i, c)) {
            return;
        }
    }
}

// A structural reader of JSON, enough to find the root's members and an
// array's elements; it trusts the syntax (tinygltf's parser judges that) and
// never recurses: skip_value counts brackets in a loop, outside the strings
// that for_each_outside_strings steps over (the one place that knows them).
struct Reader {
    std::string_view text;
    size_t at = 0;

    bool done() const { return at >= text.size(); }
    void skip_space() {
        while (!done() &&
               (text[at] == ' ' || text[at] == '\t' || text[at] == '\n' || text[at] == '\r'))
            ++at;
    }
    bool take(char c) {
        skip_space();
        if (done() || text[at] != c) return false;
        ++at;
        return true;
    }
    // A string starting at `at` (its quote), its raw contents; `at` after it.
    std::optional<std::string_view> raw_string() {
        skip_space();
        if (done() || text[at] != '"') return std::nullopt;
        const size_t start = ++at;
        while (!done() && text[at] != '"') at += text[at] == '\\' ? 2 : 1;
        if (done()) return std::nullopt;
        return text.substr(start, at++ - start);
    }
    // Moves past one value of any kind; false where the text ends first. A
    // scalar ends before the space, comma or bracket after it; an array or
    // object after its closing bracket.
    bool skip_value() {
        skip_space();
        if (done()) return false;
        if (text[at] == '"') return raw_string().has_value();
        size_t depth = 0;
        std::optional<size_t> end;  // from `at`
        for_each_outside_strings(text.substr(at), [&](size_t i, char c) {
            if (c == '[' || c == '{') {
                ++depth;
            } else if (c == ']' || c == '}' || c == ',') {
                if (depth == 0)
                    end = i;  // the end of a scalar
                else if (c != ',' && --depth == 0)
                    end = i + 1;
            } else if (depth == 0 && (c == ' ' || c == '\n' || c == '\r' || c == '\t')) {
                end = i;
            }
            return !end;
        });
        at = end ? at + *end : text.size();
        return end || depth == 0;
    }
    // Finds member `name` of the object starting here; `at` on its value.
    bool find_member(std::string_view name) {
        if (!take('{') || take('}')) return false;
        for (bool more = true; more; more = take(',')) {
            const std::optional<std::string_view> key = raw_string();
            if (!key || !take(':')) return false;
            if (*key == name) {
                skip_space();
                return true;
            }
            if (!skip_value()) return false;
        }
        return false;
    }
    // Moves to element `index` of the array starting here.
    bool find_element(size_t index) {
        if (!take('[') || take(']')) return false;
        for (size_t i = 0; i < index; ++i)
            if (!skip_value() || !take(',')) return false;
        skip_space();
        return true;
    }
    // Counts the elements of the array starting here; nullopt where it breaks off.
    std::optional<size_t> count_elements() {
        if (!take('[')) return std::nullopt;
        if (take(']')) return 0;
        size_t count = 0;
        for (bool more = true; more; more = take(',')) {
            if (!skip_value()) return std::nullopt;
            ++count;
        }
        return take(']') ? std::optional<size_t>(count) : std::nullopt;
    }
};

std::string unescape(std::string_view raw) {
    std::string out;
    for (size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] != '\\' || i + 1 == raw.size()) {
            out += raw[i];
            continue;
        }
        const char c = raw[++i];
        switch (c) {
            case 'n':
                out += '\n';
                break;
            case 't':
                out += '\t';
                break;
            case 'r':
                out += '\r';
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'u':
                out += "\\u";
                break;  // kept as written
            default:
                out += c;  // \" \\ \/
        }
    }
    return out;
}

}  // namespace

std::optional<std::string> check_json_depth(std::string_view json, size_t limit) {
    size_t depth = 0, line = 1, line_start = 0;
    std::optional<std::string> too_deep;
    for_each_outside_strings(json, [&](size_t i, char c) {
        if (c == '\n') {
            ++line;
            line_start = i + 1;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) {
                too_deep = "JSON: arrays and objects nest more than " + std::to_string(limit) +
                           " deep (at line " + std::to_string(line) + ", column " +
                           std::to_string(i - line_start + 1) + "); this loader's limit is " +
                           std::to_string(limit) +
                           " levels (glTF itself needs about 7), because tinygltf recurses "
                           "once per level and a file nested deep enough overflows its stack";
                return false;
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
        return true;
    });
    return too_deep;
}

GlbLayout check_glb_layout(std::span<const uint8_t> file) {
    const size_t size = file.size();
    auto fail = [](const std::string& what) { throw Error(".glb " + what); };
    if (size < 4 || std::memcmp(file.data(), "glTF", 4) != 0)
        fail("header: a .glb begins with \"glTF\", and this does not");
    if (size < 12)
        fail("header: the file holds " + std::to_string(size) +
             " bytes, fewer than the header's 12 (\"glTF\", version, length)");
    if (const uint32_t version = read_u32(file, 4); version != 2)
        fail("header: version " + std::to_string(version) + ", where glTF 2.0's is 2");
    if (const uint32_t length = read_u32(file, 8); length != size)
        fail("header: its length field says " + std::to_string(length) +
             " bytes, but the file holds " + std::to_string(size));
    GlbLayout layout;
    for (size_t at = 12; at < size; ++layout.chunk_count) {
        const std::string chunk = "chunk " + std::to_string(layout.chunk_count);
        if (size - at < 8)
            fail(chunk + ": " + std::to_string(size - at) + " bytes are left at byte " +
                 std::to_string(at) + ", too few for a chunk's 8-byte header");
        const size_t length = read_u32(file, at);
        const uint32_t type = read_u32(file, at + 4);
        const std::string named = chunk + " (" + chunk_type_name(type) + ")";
        if (length > size - at - 8)
            fail(named + ": its length, " + std::to_string(length) + " bytes from byte " +
                 std::to_string(at + 8) + ", runs " + std::to_string(length - (size - at - 8)) +
                 " bytes past the end of the file (" + std::to_string(size) + " bytes)");
        if (length % 4 != 0)
            fail(named + ": its length, " + std::to_string(length) +
                 ", is not a multiple of 4 (every chunk starts and ends on a 4-byte boundary)");
        if (layout.chunk_count == 0) {
            if (type != glb_json) fail(named + ": the first chunk of a .glb must be JSON");
            if (length == 0) fail(named + ": the JSON chunk is empty");
            layout.json_offset = at + 8;
            layout.json_length = length;
        } else if (layout.chunk_count == 1 && type != glb_bin) {
            fail(named + ": the second chunk must be BIN (tinygltf reads no other kind)");
        } else if (layout.chunk_count == 1 && length == 0) {
            // tinygltf 2.7's words for it: "Insufficient storage space for
            // Chunk1(BIN data) ... Must have 4 bytes or more bytes, but got 4".
            fail(named +
                 ": it is empty, and a buffer is at least 1 byte long (a .glb with no "
                 "binary data leaves its BIN chunk out)");
        }
        at += 8 + length;
    }
    if (layout.chunk_count == 0) fail("header: the file ends after its header: no JSON chunk");
    return layout;
}

std::optional<std::string> check_gltf_bytes(std::span<const char> file) {
    std::string_view json(file.data(), file.size());
    if (file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0) {
        try {
            const GlbLayout layout =
                check_glb_layout({reinterpret_cast<const uint8_t*>(file.data()), file.size()});
            json = json.substr(layout.json_offset, layout.json_length);
        } catch (const Error& e) {
            return std::string(e.what());
        }
    }
    return check_json_depth(json);
}

std::string_view gltf_json_text(std::span<const char> file) {
    const std::string_view all(file.data(), file.size());
    if (file.size() < 4 || std::memcmp(file.data(), "glTF", 4) != 0) return all;
    try {
        const GlbLayout layout =
            check_glb_layout({reinterpret_cast<const uint8_t*>(file.data()), file.size()});
        return all.substr(layout.json_offset, layout.json_length);
    } catch (const Error&) {
        return {};
    }
}

std::optional<size_t> json_array_size(std::string_view json, std::string_view member) {
    Reader reader{json};
    if (!reader.find_member(member)) return std::nullopt;
    return reader.count_elements();
}

std::vector<JsonDataUri> json_data_uris(std::string_view json) {
    std::vector<JsonDataUri> found;
    Reader root{json};
    if (!root.take('{') || root.take('}')) return found;
    // Every member of the root: a "buffers" given twice is looked at twice.
    for (bool more = true; more; more = root.take(',')) {
        const std::optional<std::string_view> key = root.raw_string();
        if (!key || !root.take(':')) return found;
        const bool buffers = *key == "buffers", images = *key == "images";
        if (!buffers && !images) {
            if (!root.skip_value()) return found;
            continue;
        }
        Reader array = root;
        if (!root.skip_value()) return found;
        if (!array.take('[') || array.take(']')) continue;
        for (size_t index = 0;; ++index) {
            Reader element = array;
            if (!array.skip_value()) break;
            JsonDataUri uri{.image = images, .index = index};
            bool has_uri = false;
            if (element.take('{') && !element.take('}')) {
                for (bool member = true; member; member = element.take(',')) {
                    const std::optional<std::string_view> name = element.raw_string();
                    if (!name || !element.take(':')) break;
                    element.skip_space();
                    const size_t start = element.at;
                    if (*name == "uri" && !element.done() && element.text[start] == '"') {
                        const std::optional<std::string_view> value = element.raw_string();
                        if (!value) break;
                        has_uri = value->starts_with("data:") &&
                                  value->find('\\') == std::string_view::npos;
                        uri.begin = start + 1;
                        uri.end = start + 1 + value->size();
                        continue;
                    }
                    if (*name == "byteLength") {
                        size_t at = start;
                        int64_t value = 0;
                        while (at < json.size() && json[at] >= '0' && json[at] <= '9' &&
                               value < (int64_t(1) << 40))
                            value = value * 10 + (json[at++] - '0');
                        const bool whole =
                            at > start && at < json.size() &&
                            (json[at] == ',' || json[at] == '}' || json[at] == ' ' ||
                             json[at] == '\n' || json[at] == '\r' || json[at] == '\t');
                        uri.byte_length = whole ? value : -1;
                    }
                    if (!element.skip_value()) break;
                }
            }
            if (has_uri) found.push_back(uri);
            if (!array.take(',')) break;
        }
    }
    return found;
}

size_t json_value_count(std::string_view json) {
    size_t count = 1;
    for_each_outside_strings(json, [&](size_t, char c) {
        if (c == ',' || c == '[' || c == '{' || c == ':') ++count;
        return true;
    });
    return count;
}

std::string json_element_name(std::string_view json, std::string_view member, size_t index) {
    Reader reader{json};
    if (!reader.find_member(member) || !reader.find_element(index) || !reader.find_member("name"))
        return {};
    const std::optional<std::string_view> name = reader.raw_string();
    return name ? unescape(*name) : std::string();
}

}  // namespace vkt
