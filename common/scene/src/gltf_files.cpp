// The glTF file and the files it names (chapter 10). tinygltf parses; every
// file it wants goes through FsCallbacks of our own, which hold it to three
// rules, because a model may come from anywhere:
//
//   - only files inside the model's own folder: a URI that is absolute, or
//     leads out of the folder with ".." or a symbolic link, is refused by
//     name (tinygltf alone would read "../../../etc/passwd");
//   - only regular files, of 1 GiB at most (vkt::read_file): tinygltf alone
//     asks a directory for its size and allocates 2^63 bytes, which is what
//     the image URI "%!QAAAQAAA5" of tinygltf's issue 416 leads to;
//   - the first refusal is the error, naming the model and the URI, even
//     where tinygltf would only have warned (it does for images).
//
// Data URIs are not files: tinygltf decodes those it knows (base64 buffers
// and PNG, JPEG, BMP, GIF images), compares a buffer's decoded length with
// its byteLength, and our 1 GiB cap on the .gltf keeps its int lengths from
// overflowing. A data: URI of any other kind would reach us as a file name,
// and is refused by name.

#include "gltf_internal.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"

#include <cstring>
#include <exception>
#include <optional>

namespace vkt::gltf_detail {

namespace {

// What the callbacks share: where the model's folder is, and why a file was
// refused.
struct FileAccess {
    std::filesystem::path folder;
    std::string prefix;   // folder as tinygltf joins it to a URI: ".../folder/"
    std::string refusal;  // the first refusal, "URI "../x" leads out of ..."
    std::string uri;      // the URI last asked for, as tinygltf %-decoded it

    void refuse(const std::string& why) {
        if (refusal.empty()) refusal = why;
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
    return with_file(static_cast<FileAccess*>(user), err, path,
                     [&](const std::filesystem::path& file) {
                         const std::vector<char> bytes = read_file(file);  // regular, 1 GiB at most
                         out->assign(bytes.begin(), bytes.end());
                     });
}

#if VKT_TINYGLTF_FILE_SIZE_CALLBACK
// tinygltf 2.8 and later ask a file's size before they read it: the same
// rules, the same refusals, nothing read.
bool file_size(size_t* size, std::string* err, const std::string& path, void* user) {
    return with_file(static_cast<FileAccess*>(user), err, path,
                     [&](const std::filesystem::path& file) {
                         *size = static_cast<size_t>(readable_file_size(file));
                     });
}
#endif

#if VKT_TINYGLTF_URI_CALLBACKS
// tinygltf 2.9 %-decodes each URI through this callback. Decoded as tinygltf
// would, then held to the same rules as a file name before anything else
// sees it: tinygltf 2.9 on its own cuts a URI at a NUL byte (the "%!Q" of its
// issue 416 decodes to one) and skips the image with only a warning; 2.7
// handed the decoded name to FileExists, where the same check refused it.
bool decode_uri(const std::string& uri, std::string* out, void* user) {
    auto* access = static_cast<FileAccess*>(user);
    if (!tinygltf::URIDecode(uri, out, nullptr)) return false;
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

tinygltf::Model parse_gltf_file(const std::filesystem::path& path) {
    auto fail = [&](const std::string& what) { throw Error(path.string() + ": " + what); };
    std::vector<char> file = read_file(path);  // "cannot open FILE", directories, 1 GiB
    if (file.empty()) fail("not a glTF file: it is empty");
    // The JSON's nesting and a .glb's chunks, before tinygltf trusts them (gltf_guard.cpp).
    if (const std::optional<std::string> unsafe = check_gltf_bytes(file)) fail(*unsafe);

    FileAccess access;
    access.folder = std::filesystem::absolute(path).parent_path();
    const std::string base_dir = access.folder.string();
    access.prefix = base_dir.ends_with('/') ? base_dir : base_dir + "/";
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
        fail(explain_load_failure({err, access.refusal}, model, file));
    return model;
}

}  // namespace vkt::gltf_detail
