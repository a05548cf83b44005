#pragma once
// Loading a glTF 2.0 scene into plain CPU-side arrays: chapter 10.
//
// tinygltf (Debian's libtinygltf) parses the JSON, the .glb container and the
// buffers; this loader walks what it parsed, checks every index, offset and
// size, and flattens the scene into one vertex array, one index array, a list
// of primitives and a list of draws (a primitive and its node's world matrix).
// Images are decoded by vkt::decode_image (chapter 09), not by tinygltf, so
// there is one decoder and one message for a broken image. Nothing here
// touches the GPU, so the unit tests load files without a device.
//
// Supported: .gltf (external or data: URI buffers and images) and .glb;
// triangle lists, strips and fans (the last two turned into lists); 8, 16
// and 32-bit indices and non-indexed primitives; POSITION, NORMAL (flat
// normals are made where it is missing) and TEXCOORD_0 (float, or normalised
// unsigned byte/short); interleaved, offset and sparse accessors; materials'
// baseColorFactor and baseColorTexture (texCoord 0, PNG or JPEG), and with
// GltfMaterials::metallic_roughness (chapter 23) also the metallic and
// roughness factors, emissiveFactor, normal scale, occlusion strength, their
// four textures and TANGENT; the node
// tree with matrix or TRS; the default scene, else scene 0, else every root.
// Skipped with a warning: skins, morph targets, animations, cameras, sparse
// index accessors, points and lines, other texture coordinates and material
// properties, every extension in extensionsUsed, samplers (every texture is
// drawn with a linear, repeating sampler). Refused with one clear line:
// anything out of bounds, a type glTF does not allow, an undecodable image,
// an extension in extensionsRequired, a scene with nothing to draw (the
// line then lists what was skipped, which is usually why), and a URI that
// leads out of the model's folder, names a directory or a file past 1 GiB
// (the model's own files are all it may read: see vkt::resolve_inside).

#include "vkt/core/memory_budget.hpp"
#include "vkt/resources/image_io.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vkt {

struct GltfVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f};
    // Chapter 23: the file's TANGENT, xyz and the bitangent's sign in w
    // (+1 or -1); w = 0 where the file has none (the shader makes its own).
    glm::vec4 tangent{0.0f};
};

// One glTF primitive as a range of GltfScene::indices. The indices are
// absolute (they already count from the start of GltfScene::vertices), so a
// draw needs no vertex offset; first_vertex/vertex_count say which vertices
// the range uses (for bounds, or a vertex offset of one's own).
struct GltfPrimitive {
    uint32_t first_index = 0;
    uint32_t index_count = 0;
    uint32_t first_vertex = 0;
    uint32_t vertex_count = 0;
    uint32_t material = 0;  // always a valid index into GltfScene::materials
};

// A primitive placed in the world by its node: one draw call.
struct GltfDraw {
    uint32_t primitive = 0;
    glm::mat4 world{1.0f};
};

struct GltfMaterial {
    glm::vec4 base_color_factor{1.0f};  // linear RGBA, multiplies the texture
    int32_t base_color_image = -1;      // index into GltfScene::images, or -1: none
    // Chapter 23's metallic-roughness model. The images are read only with
    // GltfMaterials::metallic_roughness (else -1, and a warning says so).
    float metallic_factor = 1.0f, roughness_factor = 1.0f;
    glm::vec3 emissive_factor{0.0f};
    float normal_scale = 1.0f, occlusion_strength = 1.0f;
    int32_t metallic_roughness_image = -1;  // roughness in G, metallic in B (linear)
    int32_t normal_image = -1;              // tangent-space normal, linear
    int32_t occlusion_image = -1;           // ambient occlusion in R, linear
    int32_t emissive_image = -1;            // sRGB, like the base colour
};

// Which of a material's textures load_gltf reads: the base colour only
// (chapters 10-16), or every texture of the metallic-roughness model and the
// TANGENT attribute (chapter 23).
enum class GltfMaterials { base_colour, metallic_roughness };

struct GltfScene {
    std::vector<GltfVertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<GltfPrimitive> primitives;
    std::vector<GltfDraw> draws;
    // Every material a primitive uses; a primitive without one gets glTF's
    // default material (white, factor 1), appended at the end when needed.
    std::vector<GltfMaterial> materials;
    std::vector<RgbaImage> images;                 // decoded RGBA8, only those a material uses
    glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};  // world space, over every draw
    // What was skipped, one line each ("skins are not supported: ..."), without
    // the file name; load_gltf does not print them. Each distinct line once,
    // the first 20, then one line "and N more warnings, not listed ...".
    std::vector<std::string> warnings;
    // What the load charged to its memory budget: a chapter that makes more
    // of the scene (26 flattens it) charges on from here.
    uint64_t memory_charged = 0;
};

// What a file may ask for, each refused past its limit with the limit named:
// materials (each becomes a descriptor set), draws (one per primitive of
// every node with a mesh) and vertices drawn (a mesh's vertices once for each
// node that draws it: the chapters transform, bound and draw them that often).
inline constexpr size_t gltf_max_materials = 4096;
inline constexpr size_t gltf_max_draws = 65536;
inline constexpr uint64_t gltf_max_drawn_vertices = uint64_t(1) << 26;

// Loads a .gltf or .glb file (told apart by the file's first four bytes, not
// its name). Throws vkt::Error with one line, "FILE: what is wrong", when the
// file is missing, is not glTF, or holds anything this loader cannot draw
// safely (see the top of this header). Everything large the file makes it
// allocate (the file, buffers, decoded data: URIs, images decoded, staged and
// mipmapped, accessors read, the scene's vertices and indices with their
// staging and GPU copies) is counted against `max_memory` before it is
// allocated, and refused by name with the numbers past it (--max-memory;
// vkt/core/memory_budget.hpp).
GltfScene load_gltf(const std::filesystem::path& path, uint64_t max_memory = default_max_memory,
                    GltfMaterials materials = GltfMaterials::base_colour);

// The local matrix of a node as glTF defines it: `matrix` (16 numbers, column
// by column) if given, else T * R * S from translation (x, y, z), rotation (a
// unit quaternion x, y, z, w) and scale; a missing part is the identity.
// Throws vkt::Error for a matrix that is not 16 numbers and so on.
glm::mat4 gltf_node_matrix(const std::vector<double>& matrix,
                           const std::vector<double>& translation,
                           const std::vector<double>& rotation, const std::vector<double>& scale);

}  // namespace vkt
