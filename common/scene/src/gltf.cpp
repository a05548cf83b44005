// The glTF scene (chapter 10): what tinygltf parsed (gltf_files.cpp), read
// through bounds-checked accessors (gltf_accessors.cpp), flattened into the
// CPU-side arrays of GltfScene. The GPU upload is the chapter's own.

#include "vkt/scene/gltf.hpp"

#include "gltf_internal.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"
#include "vkt/resources/texture.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <ranges>
#include <span>
#include <unordered_set>

namespace vkt {

namespace {

// The most warnings a scene lists; past it, one line says how many more.
constexpr size_t kListedWarnings = 20;

class Loader {
public:
    Loader(std::filesystem::path path, uint64_t max_memory, GltfMaterials materials)
        : path_(std::move(path)), budget_(max_memory), materials_(materials) {}

    GltfScene load() {
        model_ = gltf_detail::parse_gltf_file(path_, budget_,
                                              [this](const std::string& what) { warn(what); });
        check_extensions();
        gltf_detail::load_materials(model_, path_, data_, budget_, materials_, scene_,
                                    [this](const std::string& what) { warn(what); });
        walk_nodes();
        if (unlisted_warnings_ > 0)
            scene_.warnings.push_back("and " + std::to_string(unlisted_warnings_) +
                                      " more warnings, not listed (this loader lists the first " +
                                      std::to_string(kListedWarnings) + ")");
        if (scene_.draws.empty()) {
            // Say why: what was skipped is often the reason nothing is left
            // (a sparse accessor, points or lines), and the warnings would
            // otherwise never be printed.
            std::string why = "nothing to draw: no node of the scene has a mesh with triangles";
            for (size_t i = 0; i < scene_.warnings.size(); ++i)
                why += (i == 0 ? " (" : "; ") + scene_.warnings[i];
            fail(scene_.warnings.empty() ? why : why + ")");
        }
        compute_bounds();
        scene_.memory_charged = budget_.used();
        return std::move(scene_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(shown_path(path_) + ": " + what);
    }
    // Each distinct warning once (a hash set: a file may make hundreds of
    // thousands), the first kListedWarnings listed, the rest counted.
    void warn(const std::string& what) {
        if (warned_.contains(what)) return;
        budget_.charge(what.size() + 64, shown_path(path_) + ": its warnings");
        warned_.insert(what);
        if (scene_.warnings.size() < kListedWarnings)
            scene_.warnings.push_back(what);
        else
            ++unlisted_warnings_;
    }

    void check_extensions() {
        for (const std::string& name : model_.extensionsRequired)
            fail("requires extension " + name + ", which this loader does not support");
        for (const std::string& name : model_.extensionsUsed)
            warn("uses extension " + name + ", which this loader ignores");
        if (!model_.skins.empty()) warn("skins are not supported: meshes are drawn unskinned");
        if (!model_.animations.empty())
            warn("animations are not supported: the scene stands still");
        if (!model_.cameras.empty())
            warn("cameras are ignored: the chapter frames the scene itself");
    }

    uint32_t default_material() {
        if (default_material_ < 0) {
            scene_.materials.push_back(GltfMaterial{});
            default_material_ = int32_t(scene_.materials.size() - 1);
        }
        return uint32_t(default_material_);
    }

    // --- Meshes ------------------------------------------------------------
    // The primitives of mesh `index`, built once however many nodes use it.
    const std::vector<uint32_t>& mesh(int index) {
        if (auto found = mesh_primitives_.find(index); found != mesh_primitives_.end())
            return found->second;
        std::vector<uint32_t>& built = mesh_primitives_[index];
        const tinygltf::Mesh& m = model_.meshes[size_t(index)];
        for (size_t p = 0; p < m.primitives.size(); ++p) {
            const std::string what =
                "mesh " + std::to_string(index) + " primitive " + std::to_string(p);
            if (auto primitive = load_primitive(m.primitives[p], what)) built.push_back(*primitive);
        }
        return built;
    }

    std::optional<uint32_t> load_primitive(const tinygltf::Primitive& source,
                                           const std::string& what) {
        const int mode = source.mode;
        if (mode < TINYGLTF_MODE_TRIANGLES || mode > TINYGLTF_MODE_TRIANGLE_FAN) {
            warn("points and lines are not supported: such primitives are skipped");
            return std::nullopt;
        }
        if (!source.targets.empty())
            warn("morph targets are not supported: meshes are drawn unmorphed");
        const auto position = source.attributes.find("POSITION");
        if (position == source.attributes.end()) {
            warn("a primitive without POSITION is skipped");
            return std::nullopt;
        }
        // Sparse vertex attributes are read (read_floats); sparse indices,
        // which no exporter we know writes, are not.
        if (source.indices >= 0 && data_.accessor(source.indices, what).sparse.isSparse) {
            warn("sparse index accessors are not supported: primitives using one are skipped");
            return std::nullopt;
        }
        for (const auto& [name, accessor_index] : source.attributes)
            if (name != "POSITION" && name != "NORMAL" && name != "TEXCOORD_0" &&
                (name != "TANGENT" || materials_ != GltfMaterials::metallic_roughness))
                warn("attribute " + name + " is ignored");

        const int F = TINYGLTF_COMPONENT_TYPE_FLOAT;
        const std::vector<float> positions = data_.read_floats(position->second, what + " POSITION",
                                                               {{TINYGLTF_TYPE_VEC3, {F}, false}});
        const size_t count = positions.size() / 3;
        std::vector<float> normals, uvs, tangents;
        if (auto n = source.attributes.find("NORMAL"); n != source.attributes.end())
            normals =
                data_.read_floats(n->second, what + " NORMAL", {{TINYGLTF_TYPE_VEC3, {F}, false}});
        if (auto t = source.attributes.find("TEXCOORD_0"); t != source.attributes.end())
            uvs = data_.read_floats(t->second, what + " TEXCOORD_0",
                                    {{TINYGLTF_TYPE_VEC2,
                                      {F, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                      true}});
        // Chapter 23's normal maps: TANGENT (xyz, and w the bitangent's sign).
        if (auto t = source.attributes.find("TANGENT");
            t != source.attributes.end() && materials_ == GltfMaterials::metallic_roughness)
            tangents =
                data_.read_floats(t->second, what + " TANGENT", {{TINYGLTF_TYPE_VEC4, {F}, false}});
        if (!tangents.empty() && (tangents.size() / 4 != count || normals.empty())) {
            warn("a TANGENT that does not match POSITION and NORMAL is ignored");
            tangents.clear();
        }
        if (!normals.empty() && normals.size() / 3 != count)
            fail(what + ": NORMAL has " + std::to_string(normals.size() / 3) +
                 " elements but POSITION has " + std::to_string(count));
        if (!uvs.empty() && uvs.size() / 2 != count)
            fail(what + ": TEXCOORD_0 has " + std::to_string(uvs.size() / 2) +
                 " elements but POSITION has " + std::to_string(count));

        std::vector<uint32_t> indices;
        if (source.indices >= 0) {
            indices = data_.read_indices(source.indices, what);
            for (size_t i = 0; i < indices.size(); ++i)
                if (indices[i] >= count)
                    fail(what + ": index " + std::to_string(i) + " is " +
                         std::to_string(indices[i]) + ", past the end of the vertex data (" +
                         std::to_string(count) + " vertices)");
        } else {
            budget_.charge(uint64_t(count) * sizeof(uint32_t),
                           shown_path(path_) + ": " + what + ": its index list, generated");
            indices.resize(count);  // non-indexed: 0, 1, 2, ...
            for (size_t i = 0; i < count; ++i) indices[i] = uint32_t(i);
        }
        // The list is a copy: 3 indices a triangle (a strip's or a fan's n - 2).
        const uint64_t listed = mode == TINYGLTF_MODE_TRIANGLES
                                    ? indices.size() / 3 * 3
                                    : 3 * uint64_t(std::max<size_t>(indices.size(), 2) - 2);
        budget_.charge(listed * sizeof(uint32_t),
                       shown_path(path_) + ": " + what + ": its triangle list");
        indices = to_triangle_list(indices, mode);
        if (indices.empty()) {
            warn("a primitive with no whole triangle is skipped");
            return std::nullopt;
        }

        // What the scene will hold for this primitive, each vertex and index
        // three times: in GltfScene, in a staging buffer, in the GPU's (the
        // machine's memory, on lavapipe). Without normals every corner of
        // every triangle becomes a vertex of its own.
        const uint64_t kept = (normals.empty() ? indices.size() : count) * sizeof(GltfVertex) +
                              indices.size() * sizeof(uint32_t);
        budget_.charge(3 * kept, shown_path(path_) + ": " + what + ": its vertices and indices");
        std::vector<GltfVertex> vertices(count);
        for (size_t v = 0; v < count; ++v) {
            vertices[v].position = {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
            if (!normals.empty())
                vertices[v].normal = {normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]};
            if (!uvs.empty()) vertices[v].uv = {uvs[2 * v], uvs[2 * v + 1]};
            if (!tangents.empty())
                vertices[v].tangent = {tangents[4 * v], tangents[4 * v + 1], tangents[4 * v + 2],
                                       tangents[4 * v + 3] < 0.0f ? -1.0f : 1.0f};
        }
        if (normals.empty()) {
            // glTF: without normals, draw flat shaded. Each triangle gets its
            // own three vertices carrying the triangle's normal.
            std::vector<GltfVertex> flat;
            flat.reserve(indices.size());
            for (size_t t = 0; t + 2 < indices.size(); t += 3) {
                GltfVertex a = vertices[indices[t]], b = vertices[indices[t + 1]],
                           c = vertices[indices[t + 2]];
                glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
                const float length = glm::length(n);
                n = length > 0.0f ? n / length : glm::vec3(0, 0, 1);
                a.normal = b.normal = c.normal = n;
                flat.push_back(a);
                flat.push_back(b);
                flat.push_back(c);
            }
            vertices = std::move(flat);
            for (size_t i = 0; i < indices.size(); ++i) indices[i] = uint32_t(i);
        }

        if (scene_.vertices.size() + vertices.size() > (size_t(1) << 31) ||
            scene_.indices.size() + indices.size() > (size_t(1) << 31))
            fail("more than 2^31 vertices or indices in all");
        GltfPrimitive primitive;
        primitive.first_vertex = uint32_t(scene_.vertices.size());
        primitive.vertex_count = uint32_t(vertices.size());
        primitive.first_index = uint32_t(scene_.indices.size());
        primitive.index_count = uint32_t(indices.size());
        if (source.material >= 0) {
            if (size_t(source.material) >= model_.materials.size())
                fail(what + ": material " + std::to_string(source.material) + " does not exist");
            primitive.material = uint32_t(source.material);
        } else {
            primitive.material = default_material();
        }
        scene_.vertices.insert(scene_.vertices.end(), vertices.begin(), vertices.end());
        for (uint32_t i : indices) scene_.indices.push_back(primitive.first_vertex + i);
        scene_.primitives.push_back(primitive);
        return uint32_t(scene_.primitives.size() - 1);
    }

    // Strips and fans become lists; a list keeps only whole triangles.
    static std::vector<uint32_t> to_triangle_list(const std::vector<uint32_t>& in, int mode) {
        std::vector<uint32_t> out;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            out.assign(in.begin(), in.begin() + std::ptrdiff_t(in.size() / 3 * 3));
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // Every second triangle swaps two corners to keep the winding.
            for (size_t i = 2; i < in.size(); ++i) {
                if (i % 2 == 0)
                    out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
                else
                    out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
            }
        } else {  // fan
            for (size_t i = 2; i < in.size(); ++i) out.insert(out.end(), {in[0], in[i - 1], in[i]});
        }
        return out;
    }

    // --- The node tree -----------------------------------------------------
    void walk_nodes() {
        std::vector<int> roots;
        const int chosen =
            model_.defaultScene >= 0 ? model_.defaultScene : (model_.scenes.empty() ? -1 : 0);
        if (chosen >= 0) {
            if (size_t(chosen) >= model_.scenes.size())
                fail("scene " + std::to_string(chosen) + " does not exist");
            roots = model_.scenes[size_t(chosen)].nodes;
        } else {
            // No scenes: draw every node that is nobody's child.
            std::vector<bool> is_child(model_.nodes.size(), false);
            for (const tinygltf::Node& node : model_.nodes)
                for (int child : node.children)
                    if (child >= 0 && size_t(child) < is_child.size())
                        is_child[size_t(child)] = true;
            for (size_t n = 0; n < model_.nodes.size(); ++n)
                if (!is_child[n]) roots.push_back(int(n));
        }
        visited_.assign(model_.nodes.size(), false);
        for (int root : roots) walk(root);
    }

    // Depth first, children in their order, on a stack of our own: a file
    // decides how deep its tree goes (a chain of 100,000 nodes is 1.5 MB),
    // and one call per level would overflow the thread's stack.
    void walk(int root) {
        struct Pending {
            int index;
            glm::mat4 parent;
        };
        std::vector<Pending> stack{{root, glm::mat4(1.0f)}};
        while (!stack.empty()) {
            const Pending at = stack.back();
            stack.pop_back();
            const glm::mat4 world = visit(at.index, at.parent);
            const std::vector<int>& children = model_.nodes[size_t(at.index)].children;
            // Pushed last to first, so that the first child is visited first.
            for (int child : std::views::reverse(children)) stack.push_back({child, world});
        }
    }

    // One node: its mesh's draws, and the world transform its children inherit.
    glm::mat4 visit(int index, const glm::mat4& parent) {
        if (index < 0 || size_t(index) >= model_.nodes.size())
            fail("node " + std::to_string(index) + " does not exist");
        // glTF's nodes form trees: a node reached twice is a cycle or a shared
        // child, either way not a tree (and a cycle would never end).
        if (visited_[size_t(index)])
            fail("node " + std::to_string(index) + " appears twice in the node tree (a cycle?)");
        visited_[size_t(index)] = true;
        const tinygltf::Node& node = model_.nodes[size_t(index)];
        glm::mat4 local;
        try {
            local = gltf_node_matrix(node.matrix, node.translation, node.rotation, node.scale);
        } catch (const Error& e) {
            fail("node " + std::to_string(index) + ": " + e.what());
        }
        const glm::mat4 world = parent * local;  // the parent's transform applies last
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model_.meshes.size())
                fail("node " + std::to_string(index) + ": mesh " + std::to_string(node.mesh) +
                     " does not exist");
            add_draws(index, node.mesh, world);
        }
        return world;
    }

    // Node `node`'s draws of mesh `index`, within the limits on draws and on
    // vertices drawn (gltf.hpp): a mesh shared by many nodes is drawn, bounded
    // and, in 26, copied once for each.
    void add_draws(int node, int index, const glm::mat4& world) {
        const std::vector<uint32_t>& primitives = mesh(index);
        const std::string what = "node " + std::to_string(node) + ": mesh " + std::to_string(index);
        if (scene_.draws.size() + primitives.size() > gltf_max_draws)
            fail(what + ": its " + std::to_string(primitives.size()) +
                 " draws would bring the scene's to " +
                 std::to_string(scene_.draws.size() + primitives.size()) +
                 ", past this loader's limit of " + std::to_string(gltf_max_draws) +
                 " (one per primitive of every node with a mesh)");
        for (uint32_t primitive : primitives)
            drawn_vertices_ += scene_.primitives[primitive].vertex_count;
        if (drawn_vertices_ > gltf_max_drawn_vertices)
            fail(what + ": drawn here too, it brings the vertices drawn to " +
                 std::to_string(drawn_vertices_) + ", past this loader's limit of " +
                 std::to_string(gltf_max_drawn_vertices) +
                 " (2^26: each node draws its mesh's vertices again)");
        budget_.charge(primitives.size() * sizeof(GltfDraw),
                       shown_path(path_) + ": " + what + ": its draws");
        for (uint32_t primitive : primitives) scene_.draws.push_back({primitive, world});
    }

    void compute_bounds() {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const GltfDraw& draw : scene_.draws) {
            const GltfPrimitive& p = scene_.primitives[draw.primitive];
            for (uint32_t v = p.first_vertex; v < p.first_vertex + p.vertex_count; ++v) {
                const glm::vec3 w =
                    glm::vec3(draw.world * glm::vec4(scene_.vertices[v].position, 1.0f));
                lo = glm::min(lo, w);
                hi = glm::max(hi, w);
            }
        }
        if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z) ||
            !std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z))
            fail("the scene's positions are not finite numbers");
        scene_.bounds_min = lo;
        scene_.bounds_max = hi;
    }

    std::filesystem::path path_;
    MemoryBudget budget_;
    GltfMaterials materials_;
    tinygltf::Model model_;
    gltf_detail::Accessors data_{model_, path_, budget_};
    GltfScene scene_;
    std::map<int, std::vector<uint32_t>> mesh_primitives_;
    int32_t default_material_ = -1;
    std::vector<bool> visited_;
    std::unordered_set<std::string> warned_;
    uint64_t unlisted_warnings_ = 0;
    uint64_t drawn_vertices_ = 0;
};

}  // namespace

glm::mat4 gltf_node_matrix(const std::vector<double>& matrix,
                           const std::vector<double>& translation,
                           const std::vector<double>& rotation, const std::vector<double>& scale) {
    if (!matrix.empty()) {
        if (matrix.size() != 16)
            throw Error("matrix has " + std::to_string(matrix.size()) + " numbers, not 16");
        glm::mat4 m;
        for (int i = 0; i < 16; ++i)
            glm::value_ptr(m)[i] = float(matrix[size_t(i)]);  // column-major, like glm
        return m;
    }
    if (!translation.empty() && translation.size() != 3)
        throw Error("translation has " + std::to_string(translation.size()) + " numbers, not 3");
    if (!rotation.empty() && rotation.size() != 4)
        throw Error("rotation has " + std::to_string(rotation.size()) + " numbers, not 4");
    if (!scale.empty() && scale.size() != 3)
        throw Error("scale has " + std::to_string(scale.size()) + " numbers, not 3");
    glm::mat4 t(1.0f), r(1.0f), s(1.0f);
    if (!translation.empty())
        t[3] = glm::vec4(float(translation[0]), float(translation[1]), float(translation[2]), 1.0f);
    if (!rotation.empty()) {
        // glTF stores x, y, z, w; glm::quat's constructor takes w first.
        const glm::quat q{float(rotation[3]), float(rotation[0]), float(rotation[1]),
                          float(rotation[2])};
        const float length = glm::length(q);
        if (length > 0.0f) r = glm::mat4_cast(q / length);
    }
    if (!scale.empty())
        s = glm::scale(glm::mat4(1.0f),
                       glm::vec3(float(scale[0]), float(scale[1]), float(scale[2])));
    return t * r * s;
}

GltfScene load_gltf(const std::filesystem::path& path, uint64_t max_memory,
                    GltfMaterials materials) {
    return Loader(path, max_memory, materials).load();
}

}  // namespace vkt
