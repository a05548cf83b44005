// The glTF loader's materials (chapter 10's base colour, chapter 23's
// metallic-roughness model): each material's factors, and the images its
// textures name, decoded once each by vkt::decode_image.

#include "gltf_internal.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"

#include <map>

namespace vkt::gltf_detail {

namespace {

class MaterialReader {
public:
    MaterialReader(const tinygltf::Model& model, const std::filesystem::path& path,
                   const Accessors& data, MemoryBudget& budget, GltfScene& scene,
                   const std::function<void(const std::string&)>& warn)
        : model_(model), path_(path), data_(data), budget_(budget), scene_(scene), warn_(warn) {}

    void read(GltfMaterials which) {
        if (model_.materials.size() > gltf_max_materials)
            fail("materials: " + std::to_string(model_.materials.size()) +
                 " of them, past this loader's limit of " + std::to_string(gltf_max_materials) +
                 " (each becomes a descriptor set of its own)");
        budget_.charge(model_.materials.size() * sizeof(GltfMaterial),
                       shown_path(path_) + ": its materials");
        for (size_t m = 0; m < model_.materials.size(); ++m) {
            const tinygltf::Material& source = model_.materials[m];
            const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
            const std::string what = "material " + std::to_string(m);
            const std::vector<double>& f = pbr.baseColorFactor;
            if (f.size() != 4)
                fail(what + ": baseColorFactor has " + std::to_string(f.size()) +
                     " numbers, not 4");
            const std::vector<double>& e = source.emissiveFactor;
            if (e.size() != 3)
                fail(what + ": emissiveFactor has " + std::to_string(e.size()) + " numbers, not 3");
            GltfMaterial material;
            material.base_color_factor =
                glm::vec4(float(f[0]), float(f[1]), float(f[2]), float(f[3]));
            material.metallic_factor = float(pbr.metallicFactor);
            material.roughness_factor = float(pbr.roughnessFactor);
            material.emissive_factor = glm::vec3(float(e[0]), float(e[1]), float(e[2]));
            material.normal_scale = float(source.normalTexture.scale);
            material.occlusion_strength = float(source.occlusionTexture.strength);
            material.base_color_image =
                texture(what, "baseColorTexture", pbr.baseColorTexture.index,
                        pbr.baseColorTexture.texCoord);
            if (which == GltfMaterials::metallic_roughness) {
                material.metallic_roughness_image =
                    texture(what, "metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
                            pbr.metallicRoughnessTexture.texCoord);
                material.normal_image = texture(what, "normalTexture", source.normalTexture.index,
                                                source.normalTexture.texCoord);
                material.occlusion_image =
                    texture(what, "occlusionTexture", source.occlusionTexture.index,
                            source.occlusionTexture.texCoord);
                material.emissive_image =
                    texture(what, "emissiveTexture", source.emissiveTexture.index,
                            source.emissiveTexture.texCoord);
            } else if (source.normalTexture.index >= 0 || source.occlusionTexture.index >= 0 ||
                       source.emissiveTexture.index >= 0 ||
                       pbr.metallicRoughnessTexture.index >= 0) {
                warn_(
                    "normal, occlusion, emissive and metallic-roughness textures are ignored "
                    "(lighting is chapter 12's)");
            }
            if (source.alphaMode == "BLEND" || source.alphaMode == "MASK")
                warn_("alphaMode " + source.alphaMode +
                      " is ignored: every material is drawn opaque");
            scene_.materials.push_back(material);
        }
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(shown_path(path_) + ": " + what);
    }

    // The image of texture `index` named by a material's `slot`, or -1.
    int32_t texture(const std::string& what, const char* slot, int index, int tex_coord) {
        if (index < 0) return -1;
        if (size_t(index) >= model_.textures.size())
            fail(what + ": " + slot + " " + std::to_string(index) + " does not exist");
        if (tex_coord != 0)
            warn_(std::string("a ") + slot + " uses TEXCOORD_" + std::to_string(tex_coord) +
                  ": only TEXCOORD_0 is read, so it is drawn with TEXCOORD_0");
        const tinygltf::Texture& texture = model_.textures[size_t(index)];
        int32_t found = -1;
        if (texture.source < 0)
            warn_("a texture has no PNG or JPEG source (an extension's image?): drawn untextured");
        else
            found = image(texture.source);
        check_sampler(texture.sampler);
        return found;
    }

    void check_sampler(int index) {
        if (index < 0) return;
        if (size_t(index) >= model_.samplers.size())
            fail("sampler " + std::to_string(index) + " does not exist");
        const tinygltf::Sampler& s = model_.samplers[size_t(index)];
        if (s.wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT || s.wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT)
            warn_(
                "samplers are not mapped: every texture repeats and filters linearly, with "
                "mipmaps");
    }

    // Decodes glTF image `index` once; returns its index in scene_.images.
    int32_t image(int index) {
        if (size_t(index) >= model_.images.size())
            fail("image " + std::to_string(index) + " does not exist");
        if (auto found = slots_.find(index); found != slots_.end()) return found->second;
        const tinygltf::Image& source = model_.images[size_t(index)];
        // "image 2", "image 2 (\"bricks\")", "image 2 (bricks.png)", "image 2 (\"bricks\",
        // bricks.png)"
        const bool file = !source.uri.empty() && source.uri.rfind("data:", 0) != 0;
        std::string what = shown_path(path_) + ": image " + std::to_string(index);
        if (!source.name.empty() || file) {
            std::string label;
            if (!source.name.empty())
                label.append("\"").append(printable(source.name, 60)).append("\"");
            if (!source.name.empty() && file) label.append(", ");
            if (file) label.append(printable(source.uri));
            what.append(" (").append(label).append(")");
        }
        RgbaImage decoded;
        if (source.bufferView >= 0) {
            std::span<const uint8_t> bytes =
                data_.view_bytes(source.bufferView, "image " + std::to_string(index));
            decoded = decode_image(bytes, what, budget_);
        } else if (!source.image.empty()) {
            decoded = decode_image(source.image, what, budget_);
        } else if (file) {
            // The file was not there, or empty: a file refused (outside the
            // folder, too large) has already failed in parse_gltf_file.
            fail("image " + std::to_string(index) + " (" + printable(source.uri) +
                 "): cannot open it, or it is empty");
        } else {
            fail("image " + std::to_string(index) + " has no data (an unsupported data: URI?)");
        }
        if (decoded.width == 0 || decoded.height == 0)
            fail("image " + std::to_string(index) + " is empty");
        scene_.images.push_back(std::move(decoded));
        const int32_t slot = int32_t(scene_.images.size() - 1);
        slots_[index] = slot;
        return slot;
    }

    const tinygltf::Model& model_;
    const std::filesystem::path& path_;
    const Accessors& data_;
    MemoryBudget& budget_;
    GltfScene& scene_;
    const std::function<void(const std::string&)>& warn_;
    std::map<int, int32_t> slots_;
};

}  // namespace

void load_materials(const tinygltf::Model& model, const std::filesystem::path& path,
                    const Accessors& data, MemoryBudget& budget, GltfMaterials which,
                    GltfScene& scene, const std::function<void(const std::string&)>& warn) {
    MaterialReader(model, path, data, budget, scene, warn).read(which);
}

}  // namespace vkt::gltf_detail
