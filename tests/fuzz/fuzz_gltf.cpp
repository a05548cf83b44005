// libFuzzer target: vkt::load_gltf (chapter 10) on any bytes, as a .gltf or a
// .glb (the loader tells them apart by the first four bytes, so one target
// covers both; the seed corpus has each).
//
// load_gltf reads a file, so each input is written to model.gltf in a folder
// of this process's own, beside copies of the repository's scene.bin and
// textures: a mutated scene.gltf still finds its buffer and images there.
//
// The contract under test (vkt/scene/gltf.hpp): any input either loads or
// throws vkt::Error. Anything else is a finding: a crash, an ASan or UBSan
// report, another exception escaping, a hang (-timeout), a huge allocation
// (-malloc_limit_mb, -rss_limit_mb). Each input may make the loader count
// 128 MiB (its --max-memory, vkt/core/memory_budget.hpp), so an input that
// makes the process pass the fuzz test's 2 GiB has found memory the budget
// does not count.
#include "vkt/core/check.hpp"
#include "vkt/scene/gltf.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace fs = std::filesystem;

namespace {

// A folder of this process's own, removed when the process ends normally (a
// crashing run leaves it in the temporary folder, beside its input).
struct Folder {
    fs::path dir;
    Folder() {
        std::string name = (fs::temp_directory_path() / "vkt_fuzz_gltf.XXXXXX").string();
        if (!mkdtemp(name.data())) std::abort();
        dir = name;
        for (const char* file : {"scene.bin", "bricks.png", "checker.png", "stripes.png"})
            fs::copy_file(fs::path(VKT_SOURCE_DIR) / "assets/gltf" / file, dir / file);
    }
    ~Folder() {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
    Folder(const Folder&) = delete;
    Folder& operator=(const Folder&) = delete;
};

fs::path model_path() {
    static const Folder folder;
    return folder.dir / "model.gltf";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const fs::path path = model_path();
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, file) != size) std::abort();
    std::fclose(file);
    try {
        const vkt::GltfScene scene = vkt::load_gltf(path, uint64_t(128) << 20);
        // What a chapter relies on: every index names a vertex, every
        // primitive's range lies inside the index array, every material index
        // is valid, every material's image exists.
        for (uint32_t index : scene.indices)
            if (index >= scene.vertices.size()) std::abort();
        for (const vkt::GltfPrimitive& p : scene.primitives) {
            if (size_t(p.first_index) + p.index_count > scene.indices.size()) std::abort();
            if (p.material >= scene.materials.size()) std::abort();
        }
        for (const vkt::GltfDraw& d : scene.draws)
            if (d.primitive >= scene.primitives.size()) std::abort();
        for (const vkt::GltfMaterial& m : scene.materials)
            if (m.base_color_image >= int32_t(scene.images.size())) std::abort();
        for (const vkt::RgbaImage& image : scene.images)
            if (image.pixels.size() != size_t(image.width) * image.height * 4) std::abort();
    } catch (const vkt::Error&) {
        // A clear refusal: what the loader promises for a bad file.
    }
    return 0;
}
