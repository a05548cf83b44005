// How the glTF loader hands its file callbacks to tinygltf (chapter 10,
// common/scene/src/gltf_files.cpp). tinygltf 2.9 (Debian 13) answers
// SetFsCallbacks with whether it took them, and refuses a set with a null
// member; refused, it would go on reading files its own way, from anywhere a
// URI points. The loader must stop there, by name.

#include "gltf_internal.hpp"  // common/scene/src: the loader's private parts
#include "vkt/core/check.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

using Catch::Matchers::ContainsSubstring;

TEST_CASE("a refused SetFsCallbacks is an error that names it", "[gltf]") {
#if VKT_TINYGLTF_FS_CALLBACKS_CHECKED
    tinygltf::TinyGLTF gltf;
    const tinygltf::FsCallbacks none{};  // every callback null: tinygltf 2.9 refuses these
    REQUIRE_THROWS_AS(vkt::gltf_detail::use_fs_callbacks(gltf, none), vkt::Error);
    REQUIRE_THROWS_WITH(vkt::gltf_detail::use_fs_callbacks(gltf, none),
                        ContainsSubstring("tinygltf::SetFsCallbacks refused") &&
                            ContainsSubstring("no file of the model is read without them"));
#else
    SKIP(
        "this tinygltf's SetFsCallbacks returns nothing and cannot refuse (tinygltf 2.7, Debian "
        "12); the check runs against tinygltf 2.9 (Debian 13: scripts/test-in-root.sh trixie)");
#endif
}

TEST_CASE("a full set of file callbacks is taken by this tinygltf", "[gltf]") {
    // Every member set, as the loader sets them: tinygltf 2.9 must take them
    // (on 2.7, which cannot refuse, this only shows the set compiles).
    tinygltf::TinyGLTF gltf;
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = [](const std::string&, void*) { return false; };
    callbacks.ExpandFilePath = [](const std::string& path, void*) { return path; };
    callbacks.ReadWholeFile = [](std::vector<unsigned char>*, std::string*, const std::string&,
                                 void*) { return false; };
    callbacks.WriteWholeFile = [](std::string*, const std::string&,
                                  const std::vector<unsigned char>&, void*) { return false; };
#if VKT_TINYGLTF_FILE_SIZE_CALLBACK
    callbacks.GetFileSizeInBytes = [](size_t*, std::string*, const std::string&, void*) {
        return false;
    };
#endif
    REQUIRE_NOTHROW(vkt::gltf_detail::use_fs_callbacks(gltf, callbacks));
}
