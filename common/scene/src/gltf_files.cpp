// The glTF file and the files it names (chapter 10). tinygltf parses; every
// file it wants goes through FsCallbacks of our own, which hold it to three
// rules, because a model may come from anywhere:
//
//   - only files inside the model's own folder: a URI that is absolute, or
//     leads out of the folder with ".." or a symbolic link, is refused by
//     name (tinygltf alone would read "../../../etc/passwd");
//   - only regular files, of 1 GiB at most (vkt::read_file): tinygltf alone
//     asks a directory for its size and allocates 2^63 bytes, which is what
//     the image URI "%!QAAAQAAA5" of syoyo/tinygltf#416 leads to;
//   - the first refusal is the error, naming the model and the URI, even
//     where tinygltf would only have warned (it does for images).
//
// Data URIs are not files. tinygltf would decode those it knows (base64
// buffers and PNG, JPEG, BMP, GIF images) from a copy of a copy of the
// JSON's string, about eight times the URI at the peak (388 MB for 50 MB). So
// in a .gltf the loader decodes them itself, once, straight from the file's
// bytes, and hands tinygltf a JSON whose data: URIs are replaced by the
// names "vkt-data-uri-N", which the callbacks below answer with the decoded
// bytes (moved, not copied). tinygltf checks those as it checks any file;
// a buffer's byteLength is checked here first, to say what is wrong in
// words about the data: URI. A data: URI of any other kind would reach us
// as a file name, and is refused by name; one in a .glb's JSON (rare) is
// left to tinygltf, and the budget counts its copies.
//
// Every large allocation is charged to the load's MemoryBudget before it is
// made: the file, each decoded data: URI, the JSON as a JSON library builds
// it (json_value_bytes a value, and its strings' copies), each file a URI
// names, a .glb's BIN chunk copied into its buffer.

#include "gltf_internal.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>
#include <exception>
#include <optional>
#include <string_view>

namespace vkt::gltf_detail {

namespace {

// The name a data: URI decoded here goes by (see the top of this file).
constexpr std::string_view data_uri_stem = "vkt-data-uri-";

// What the callbacks share: where the model's folder is, and why a file was
// refused.
struct FileAccess {
    std::filesystem::path folder;
    std::string prefix;   // folder as tinygltf joins it to a URI: ".../folder/"
    std::string refusal;  // the first refusal, "URI "../x" leads out of ..."
    std::string uri;      // the URI last asked for, as tinygltf %-decoded it
    // tinygltf appends each image to the model as it reads it, so how many
    // it holds when a URI is refused is the index of the image it is reading.
    const tinygltf::Model* model = nullptr;
    size_t refused_image = SIZE_MAX;
    MemoryBudget* budget = nullptr;
    // The data: URIs decoded here, each handed to tinygltf (moved) when it
    // asks for the file data_uri_name(N).
    std::vector<std::vector<unsigned char>> decoded;

    // The decoded bytes tinygltf asks for under a name of ours, or null
    // where `joined` is another file.
    std::vector<unsigned char>* data_uri(const std::string& joined) {
        if (decoded.empty() || joined.compare(0, prefix.size(), prefix) != 0) return nullptr;
        const std::string_view name = std::string_view(joined).substr(prefix.size());
        if (!name.starts_with(data_uri_stem)) return nullptr;
        size_t n = 0;
        const std::string_view digits = name.substr(data_uri_stem.size());
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
        if (error != std::errc{} || end != digits.data() + digits.size() || n >= decoded.size())
            return nullptr;
        return &decoded[n];
    }

    void refuse(const std::string& why) {
        if (!refusal.empty()) return;
        refusal = why;
        if (model) refused_image = model->images.size();
    }

    // The file tinygltf asks for, if it may have it. tinygltf hands over
    // prefix + URI (%-decoded), and then "./" + URI, the working directory,
    // which we never look in.
    std::optional<std::filesystem::path> inside(const std::string& joined) {
        if (joined.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
        uri = joined.substr(prefix.size());
        if (uri.rfind("data:", 0) == 0) {
            refuse("URI \"" + printable(uri, 40) +
                   "\" is a data: URI of a kind tinygltf does not decode (base64 "
                   "application/octet-stream, application/gltf-buffer, image/png, image/jpeg, "
                   "image/bmp, image/gif or text/plain)");
            return std::nullopt;
        }
        try {
            return resolve_inside(folder, uri);
        } catch (const Error& e) {
            refuse(e.what());
            return std::nullopt;
        }
    }
};

std::string no_expansion(const std::string& path, void*) {
    return path;  // no "~", no environment variables: a URI is a file name
}

bool file_exists(const std::string& path, void* user) {
    if (static_cast<FileAccess*>(user)->data_uri(path)) return true;
    const std::optional<std::filesystem::path> file = static_cast<FileAccess*>(user)->inside(path);
    std::error_code error;
    return file && std::filesystem::exists(*file, error);  // a directory, too: read_file says so
}

// What read_whole_file and file_size share: the file tinygltf asks for, if it
// may have it, handed to `use`; otherwise the refusal, kept and told.
template <typename Use>
bool with_file(FileAccess* access, std::string* err, const std::string& path, Use use) {
    const std::optional<std::filesystem::path> file = access->inside(path);
    try {
        if (!file) throw Error(access->refusal.empty() ? "cannot open " + path : access->refusal);
        use(*file);
        return true;
    } catch (const Error& e) {
        // read_file names the path it tried ("/models/car: is a directory");
        // the URI that led there is what the reader must fix (".").
        access->refuse(file ? "URI \"" + printable(access->uri) + "\": " + e.what() : e.what());
        if (err) *err += std::string(e.what()) + "\n";
        return false;
    }
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
    auto* access = static_cast<FileAccess*>(user);
    if (std::vector<unsigned char>* decoded = access->data_uri(path)) {
        out->swap(*decoded);  // charged when it was decoded
        return true;
    }
    return with_file(access, err, path, [&](const std::filesystem::path& file) {
        // Its bytes, then tinygltf's copy of them (read_file's vector is freed
        // at once, but the budget counts every allocation of the load).
        access->budget->charge(2 * readable_file_size(file), "");
        const std::vector<char> bytes = read_file(file);  // regular, 1 GiB at most
        out->assign(bytes.begin(), bytes.end());
    });
}

#if VKT_TINYGLTF_FILE_SIZE_CALLBACK
// tinygltf 2.8 and later ask a file's size before they read it: the same
// rules, the same refusals, nothing read.
bool file_size(size_t* size, std::string* err, const std::string& path, void* user) {
    if (std::vector<unsigned char>* decoded = static_cast<FileAccess*>(user)->data_uri(path)) {
        *size = decoded->size();
        return true;
    }
    return with_file(static_cast<FileAccess*>(user), err, path,
                     [&](const std::filesystem::path& file) {
                         *size = static_cast<size_t>(readable_file_size(file));
                     });
}
#endif

#if VKT_TINYGLTF_URI_CALLBACKS
// tinygltf 2.9 %-decodes each URI through this callback. Decoded as tinygltf
// would, then held to the same rules as a file name before anything else
// sees it: tinygltf 2.9 on its own cuts a URI at a NUL byte (the "%!Q" of
// syoyo/tinygltf#416 decodes to one) and skips the image with only a warning; 2.7
// handed the decoded name to FileExists, where the same check refused it.
bool decode_uri(const std::string& uri, std::string* out, void* user) {
    auto* access = static_cast<FileAccess*>(user);
    if (!access->decoded.empty() && uri.starts_with(data_uri_stem)) {
        *out = uri;  // a data: URI decoded here: data_uri() answers for it
        return true;
    }
    if (!tinygltf::URIDecode(uri, out, nullptr)) return false;
    access->uri = *out;
    try {
        (void)resolve_inside(access->folder, *out);
        return true;
    } catch (const Error& e) {
        access->refuse(e.what());
        return false;
    }
}
#endif

bool write_nothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "the glTF loader writes no files\n";
    return false;
}

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

// The data: URIs tinygltf decodes, by what they begin with (tinygltf 2.7 to 2.9).
constexpr std::array<std::string_view, 7> base64_uri_prefixes = {
    "data:application/octet-stream;base64,",
    "data:application/gltf-buffer;base64,",
    "data:image/png;base64,",
    "data:image/jpeg;base64,",
    "data:image/bmp;base64,",
    "data:image/gif;base64,",
    "data:text/plain;base64,"};

int base64_value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

// Base64 as tinygltf decodes it: up to the first character outside the
// alphabet ('=' included), a last group of 2 or 3 characters giving 1 or 2
// bytes, so that a file decodes here exactly as it did there.
std::vector<unsigned char> decode_base64(std::string_view text) {
    size_t length = 0;
    while (length < text.size() && base64_value(text[length]) >= 0) ++length;
    std::vector<unsigned char> out;
    out.reserve(length / 4 * 3 + 2);
    uint32_t bits = 0;
    int held = 0;
    for (size_t i = 0; i < length; ++i) {
        bits = (bits << 6 | uint32_t(base64_value(text[i]))) & 0xFFFFFFu;
        held += 6;
        if (held >= 8) {
            held -= 8;
            out.push_back(uint8_t(bits >> held));
        }
    }
    return out;
}

// A data: URI decoded here, and where its element is.
struct DecodedUri {
    bool image;
    size_t index;
    std::string_view prefix;  // "data:image/png;base64,": what its "uri" becomes again
};

// Decodes a .gltf's base64 data: URIs into access.decoded (charged to the
// budget first) and returns its JSON with each URI replaced by its name,
// data_uri_stem + N; the file as it is where there is none (or where its
// text already holds that stem, so that no name of ours could be mistaken).
std::vector<char> decode_data_uris(std::vector<char> file, FileAccess& access,
                                   std::vector<DecodedUri>& uris, const std::string& path) {
    const std::string_view json(file.data(), file.size());
    if (json.starts_with("glTF") || json.find(data_uri_stem) != std::string_view::npos) return file;
    std::vector<char> out;
    size_t copied = 0;  // json[0, copied) is in `out`
    for (const JsonDataUri& found : json_data_uris(json)) {
        const std::string_view text = json.substr(found.begin, found.end - found.begin);
        const auto prefix = std::find_if(base64_uri_prefixes.begin(), base64_uri_prefixes.end(),
                                         [&](std::string_view p) { return text.starts_with(p); });
        if (prefix == base64_uri_prefixes.end()) continue;  // refused by name later
        const std::string what =
            path + ": " + (found.image ? "image " : "buffer ") + std::to_string(found.index) +
            quoted_name(json_element_name(json, found.image ? "images" : "buffers", found.index));
        const std::string_view payload = text.substr(prefix->size());
        // An image's bytes are copied once more, into tinygltf's Image.
        access.budget->charge((found.image ? 2 : 1) * (payload.size() / 4 * 3 + 2),
                              what + ": its data: URI, decoded");
        std::vector<unsigned char> bytes = decode_base64(payload);
        if (bytes.empty())
            throw Error(what + ": its data URI is invalid: its base64 decodes to no bytes");
        if (!found.image && found.byte_length >= 0 && bytes.size() != uint64_t(found.byte_length))
            throw Error(what + ": data URI \"" + printable(text, 60) +
                        "\" is invalid: its base64 decodes to " + std::to_string(bytes.size()) +
                        (bytes.size() == 1 ? " byte" : " bytes") +
                        ", not the buffer's byteLength " + std::to_string(found.byte_length));
        if (out.empty()) out.reserve(json.size() / 64 + 4096);
        out.insert(out.end(), json.begin() + ptrdiff_t(copied),
                   json.begin() + ptrdiff_t(found.begin));
        const std::string name = std::string(data_uri_stem) + std::to_string(access.decoded.size());
        out.insert(out.end(), name.begin(), name.end());
        copied = found.end;
        access.decoded.push_back(std::move(bytes));
        uris.push_back({found.image, found.index, *prefix});
    }
    if (uris.empty()) return file;
    out.insert(out.end(), json.begin() + ptrdiff_t(copied), json.end());
    return out;
}

}  // namespace

void use_fs_callbacks(tinygltf::TinyGLTF& gltf, const tinygltf::FsCallbacks& callbacks) {
#if VKT_TINYGLTF_FS_CALLBACKS_CHECKED
    // tinygltf 2.9 refuses callbacks with a null member, and then keeps
    // reading files its own way, from anywhere: never carry on after that.
    std::string why;
    if (!gltf.SetFsCallbacks(callbacks, &why))
        throw Error("tinygltf::SetFsCallbacks refused the loader's file callbacks (" +
                    (why.empty() ? std::string("it gave no reason") : first_line(why)) +
                    "); no file of the model is read without them");
#else
    gltf.SetFsCallbacks(callbacks);  // tinygltf 2.7 takes any, and cannot refuse
#endif
}

tinygltf::Model parse_gltf_file(const std::filesystem::path& path, MemoryBudget& budget,
                                const std::function<void(const std::string&)>& warn) {
    auto fail = [&](const std::string& what) { throw Error(shown_path(path) + ": " + what); };
    // "cannot open FILE", directories, 1 GiB: before anything is charged.
    // Its first bytes say whether it is glTF at all (a .glb's magic, or the
    // first character of JSON after white space), before it is read whole:
    // a gigabyte of NULs is refused at once, not after 20 s of reading.
    const std::vector<char> start = read_file_start(path, 4096);
    if (start.empty()) fail("not a glTF file: it is empty");
    const std::string_view head(start.data(), start.size());
    const size_t first =
        head.find_first_not_of(" \t\r\n", head.starts_with("\xEF\xBB\xBF") ? 3 : 0);
    if (!head.starts_with("glTF") && first != std::string_view::npos &&
        std::string_view("{[\"-0123456789tfn").find(head[first]) == std::string_view::npos)
        fail(
            "not a glTF file: a .gltf is a JSON object, beginning with '{', and this begins "
            "with \"" +
            printable(head.substr(first, 12), 12) + "\"");
    budget.charge(readable_file_size(path), shown_path(path) + ": the file itself");
    std::vector<char> file = read_file(path);
    if (file.empty()) fail("not a glTF file: it is empty");
    // The JSON's nesting and a .glb's chunks, before tinygltf trusts them (gltf_guard.cpp).
    if (const std::optional<std::string> unsafe = check_gltf_bytes(file)) fail(*unsafe);

    FileAccess access;
    access.folder = std::filesystem::absolute(path).parent_path();
    const std::string base_dir = access.folder.string();
    access.prefix = base_dir.ends_with('/') ? base_dir : base_dir + "/";
    access.budget = &budget;
    // A .gltf's data: URIs decoded here; `file` is then the JSON without them
    // (the file's own bytes are freed).
    std::vector<DecodedUri> decoded_uris;
    file = decode_data_uris(std::move(file), access, decoded_uris, shown_path(path));
    // What tinygltf builds from the JSON: its values, and copies of its
    // strings. A data: URI left to tinygltf (in a .glb's JSON) is the worst
    // string: nlohmann's copy, tinygltf's, the substring it decodes, then
    // the decoded bytes twice (3/4 each): 4.5 times its text, so 5.
    const std::string_view json = gltf_json_text(file);
    const uint64_t values = json_value_count(json);
    budget.charge(
        values * json_value_bytes + 5 * uint64_t(json.size()),
        shown_path(path) + ": its JSON, parsed (" + std::to_string(values) + " values at most)");
    // tinygltf's own object for each element of the root's arrays, far
    // larger than its JSON: "{}" in "materials" is a tinygltf::Material of
    // 2,144 bytes (tinygltf 2.7), so 3 MB of them would take 2 GiB.
    const std::pair<std::string_view, size_t> objects[] = {
        {"materials", sizeof(tinygltf::Material)},
        {"nodes", sizeof(tinygltf::Node)},
        {"meshes", sizeof(tinygltf::Mesh)},
        {"accessors", sizeof(tinygltf::Accessor)},
        {"bufferViews", sizeof(tinygltf::BufferView)},
        {"buffers", sizeof(tinygltf::Buffer)},
        {"images", sizeof(tinygltf::Image)},
        {"textures", sizeof(tinygltf::Texture)},
        {"samplers", sizeof(tinygltf::Sampler)},
        {"scenes", sizeof(tinygltf::Scene)},
        {"animations", sizeof(tinygltf::Animation)},
        {"skins", sizeof(tinygltf::Skin)},
        {"cameras", sizeof(tinygltf::Camera)},
        {"lights", sizeof(tinygltf::Light)}};
    uint64_t object_bytes = 0;
    for (const auto& [member, size] : objects)
        object_bytes += uint64_t(json_array_size(json, member).value_or(0)) * size;
    budget.charge(object_bytes, shown_path(path) + ": its elements, as tinygltf's objects");
    // tinygltf copies a .glb's BIN chunk into its buffer.
    budget.charge(file.size() - json.size(), shown_path(path) + ": its BIN chunk, copied");
    tinygltf::TinyGLTF gltf;
    // Named, not in order: tinygltf 2.8 added a member in the middle.
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = file_exists;
    callbacks.ExpandFilePath = no_expansion;
    callbacks.ReadWholeFile = read_whole_file;
    callbacks.WriteWholeFile = write_nothing;
#if VKT_TINYGLTF_FILE_SIZE_CALLBACK
    callbacks.GetFileSizeInBytes = file_size;
#endif
    callbacks.user_data = &access;
    use_fs_callbacks(gltf, callbacks);
#if VKT_TINYGLTF_URI_CALLBACKS
    const tinygltf::URICallbacks uri_callbacks{nullptr, decode_uri, &access};
    std::string why;
    if (!gltf.SetURICallbacks(uri_callbacks, &why))
        throw Error("tinygltf::SetURICallbacks refused the loader's URI decoder (" +
                    (why.empty() ? std::string("it gave no reason") : first_line(why)) + ")");
#endif
    gltf.SetImageLoader(keep_image_bytes, nullptr);

    tinygltf::Model model;
    access.model = &model;
    std::string err, warn_text;
    const bool glb = file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0;
    bool ok = false;
    try {
        // read_file's cap keeps the size within tinygltf's unsigned int.
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
    // Even where tinygltf only warned (it does for images), a refusal fails.
    if (!ok || !access.refusal.empty())
        fail(explain_load_failure({err, access.refusal, access.refused_image}, model, file));
    // What tinygltf read without a word: indices past an int, factors' lengths.
    if (const std::optional<std::string> wrong = check_json_values(gltf_json_text(file)))
        fail(*wrong);
    for (std::string_view rest = warn_text; !rest.empty();) {
        const size_t end = rest.find('\n');
        if (const std::string_view line = rest.substr(0, end); !line.empty())
            warn("tinygltf: " + std::string(line));
        rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    }
    // A data: URI decoded here is a data: URI again (without its text, which
    // no one reads): gltf.cpp tells an image's file from its data by it.
    for (size_t n = 0; n < decoded_uris.size(); ++n) {
        const DecodedUri& d = decoded_uris[n];
        std::string* uri =
            d.image ? (d.index < model.images.size() ? &model.images[d.index].uri : nullptr)
                    : (d.index < model.buffers.size() ? &model.buffers[d.index].uri : nullptr);
        if (uri && *uri == std::string(data_uri_stem) + std::to_string(n))
            *uri = std::string(d.prefix);
    }
    return model;
}

}  // namespace vkt::gltf_detail
