#pragma once
// Chapter 23's materials on the GPU: each glTF material's five textures as
// one descriptor set (set 1 of the scene pipeline), and its factors as the
// draw's push constants. Where a material has no texture for a slot, a 1x1
// texture that leaves the factor as it is stands in: white for the colours,
// metallic-roughness and occlusion, (0.5, 0.5, 1), "straight out", for the
// normal map (which the shader then skips).

#include "blocks.hpp"

#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/texture.hpp"
#include "vkt/scene/gltf.hpp"

#include <map>
#include <utility>
#include <vector>

class MaterialSets {
public:
    // The scene's materials; with none (the sphere grid) one set of the
    // stand-in textures, whose factors the grid pushes itself.
    MaterialSets(const vkt::Gpu& gpu, const std::vector<vkt::GltfMaterial>& materials,
                 const std::vector<vkt::RgbaImage>& images)
        : device_(gpu.device), materials_(materials) {
        const vkt::RgbaImage white{1, 1, {255, 255, 255, 255}}, flat{1, 1, {128, 128, 255, 255}};
        white_srgb_ = vkt::create_texture(gpu, white, true, 0.0f);
        white_linear_ = vkt::create_texture(gpu, white, false, 0.0f);
        flat_normal_ = vkt::create_texture(gpu, flat, false, 0.0f);

        // [material-sets]
        VkDescriptorSetLayoutBinding bindings[5];
        for (uint32_t b = 0; b < 5; ++b)
            bindings[b] = {b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                           VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
        layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const uint32_t count = uint32_t(std::max<size_t>(materials.size(), 1));
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 5 * count};
        pool_ = vkt::create_descriptor_pool(device_, count, {&size, 1});
        for (uint32_t m = 0; m < count; ++m) {
            const vkt::GltfMaterial material =
                materials.empty() ? vkt::GltfMaterial{} : materials[m];
            // [material-slots]
            // Colours are stored sRGB-encoded, the rest as plain numbers.
            const std::pair<int32_t, bool> slots[5] = {{material.base_color_image, true},
                                                       {material.metallic_roughness_image, false},
                                                       {material.normal_image, false},
                                                       {material.occlusion_image, false},
                                                       {material.emissive_image, true}};
            // [/material-slots]
            VkDescriptorSet set = vkt::allocate_descriptor_set(device_, pool_, layout_);
            for (uint32_t b = 0; b < 5; ++b) {
                const vkt::Texture& texture = slots[b].first >= 0 ? image(gpu, images, slots[b])
                                              : b == 2            ? flat_normal_
                                              : slots[b].second   ? white_srgb_
                                                                  : white_linear_;
                vkt::write_image_descriptor(device_, set, b, texture.image.view, texture.sampler,
                                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            }
            sets_.push_back(set);
        }
        // [/material-sets]
    }

    VkDescriptorSetLayout layout() const { return layout_; }
    VkDescriptorSet set(uint32_t material) const { return sets_[material]; }

    // [material-push]
    // A glTF material's factors, as the scene shader reads them.
    DrawPush push(uint32_t material, const glm::mat4& world) const {
        const vkt::GltfMaterial& m = materials_[material];
        return {
            world, m.base_color_factor,
            glm::vec4(m.metallic_factor, m.roughness_factor, m.normal_scale, m.occlusion_strength),
            glm::vec4(m.emissive_factor, m.normal_image >= 0 ? 1.0f : 0.0f)};
    }
    // [/material-push]

private:
    // Each image once per encoding (an image a material reads as a colour
    // and another reads as numbers becomes two textures).
    const vkt::Texture& image(const vkt::Gpu& gpu, const std::vector<vkt::RgbaImage>& images,
                              std::pair<int32_t, bool> key) {
        auto found = textures_.find(key);
        if (found == textures_.end())
            found = textures_
                        .emplace(key, vkt::create_texture(gpu, images[size_t(key.first)],
                                                          key.second, 0.0f))
                        .first;
        return found->second;
    }

    VkDevice device_;
    std::vector<vkt::GltfMaterial> materials_;
    vkt::Texture white_srgb_, white_linear_, flat_normal_;
    std::map<std::pair<int32_t, bool>, vkt::Texture> textures_;
    vkt::DescriptorSetLayout layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;
};
