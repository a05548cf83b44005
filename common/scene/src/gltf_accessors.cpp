// Reading a glTF model's accessors and buffer views (chapter 10), each index,
// offset, stride and count checked against the bytes that are really there
// before one byte is read: a file from anywhere cannot make the loader read
// outside its buffers.

#include "gltf_internal.hpp"

#include "vkt/core/check.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vkt::gltf_detail {

namespace {

const char* component_name(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "FLOAT";
        default:
            return "an unknown component type";
    }
}

const char* type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "an unknown type";
    }
}

}  // namespace

void Accessors::fail(const std::string& what) const {
    throw Error(shown_path(path_) + ": " + what);
}

std::span<const uint8_t> Accessors::view_bytes(int index, const std::string& what) const {
    if (index < 0 || size_t(index) >= model_.bufferViews.size())
        fail(what + ": bufferView " + std::to_string(index) + " does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[size_t(index)];
    const std::string view_name = "bufferView " + std::to_string(index) + quoted_name(view.name);
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
        fail(what + ": " + view_name + " names buffer " + std::to_string(view.buffer) +
             ", which does not exist");
    const std::vector<unsigned char>& data = model_.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        fail(what + ": " + view_name + " (offset " + std::to_string(view.byteOffset) + ", length " +
             std::to_string(view.byteLength) + ") runs past the end of buffer " +
             std::to_string(view.buffer) + quoted_name(model_.buffers[size_t(view.buffer)].name) +
             " (" + std::to_string(data.size()) + " bytes)");
    return {data.data() + view.byteOffset, view.byteLength};
}

const tinygltf::Accessor& Accessors::accessor(int index, const std::string& what) const {
    if (index < 0 || size_t(index) >= model_.accessors.size())
        fail(what + ": accessor " + std::to_string(index) + " does not exist");
    return model_.accessors[size_t(index)];
}

size_t Accessors::stride_of(const tinygltf::Accessor& a, size_t element_size) const {
    const size_t declared = model_.bufferViews[size_t(a.bufferView)].byteStride;
    return declared == 0 ? element_size : declared;
}

// The accessor's view, after checking that every element lies inside it.
std::span<const uint8_t> Accessors::element_range(const tinygltf::Accessor& a,
                                                  const std::string& name,
                                                  size_t element_size) const {
    std::span<const uint8_t> bytes = view_bytes(a.bufferView, name);
    const size_t stride = stride_of(a, element_size);
    if (stride < element_size)
        fail(name + ": byteStride " + std::to_string(stride) + " is smaller than one element (" +
             std::to_string(element_size) + " bytes)");
    // offset + stride * (count - 1) + element_size <= view length, without overflow
    // (count is at most 2^28 here and stride at most 2^32 in any file we read).
    const uint64_t end =
        a.count == 0 ? uint64_t(a.byteOffset)
                     : uint64_t(a.byteOffset) + uint64_t(stride) * (a.count - 1) + element_size;
    if (a.byteOffset > bytes.size() || end > bytes.size())
        fail(name + " (count " + std::to_string(a.count) + ", byteOffset " +
             std::to_string(a.byteOffset) + ", stride " + std::to_string(stride) +
             ") runs past the end of bufferView " + std::to_string(a.bufferView) + " (" +
             std::to_string(bytes.size()) + " bytes)");
    return bytes;
}

// A sparse accessor replaces some of its elements: `count` indices (which
// elements) and as many values, each tightly packed in its own view.
template <typename Decode>
void Accessors::apply_sparse(const tinygltf::Accessor& a, const std::string& name,
                             size_t element_size, Decode& decode) const {
    const auto& sparse = a.sparse;
    const std::string what = name + " (sparse)";
    if (sparse.count < 1 || size_t(sparse.count) > a.count)
        fail(what + ": count " + std::to_string(sparse.count) + " is not between 1 and " +
             std::to_string(a.count));
    const int ict = sparse.indices.componentType;
    if (ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(what + ": indices are " + component_name(ict) +
             ", not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    const size_t count = size_t(sparse.count);
    const size_t index_size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(ict)));
    // Each view must hold byteOffset + count elements (count * size <= 2^28 * 64: no overflow).
    auto packed = [&](int view, int offset, size_t size, const char* part) {
        std::span<const uint8_t> bytes = view_bytes(view, what + " " + part);
        if (offset < 0 || size_t(offset) > bytes.size() ||
            count * size > bytes.size() - size_t(offset))
            fail(what + ": " + part + " (count " + std::to_string(count) + ", byteOffset " +
                 std::to_string(offset) + ") run past the end of bufferView " +
                 std::to_string(view) + " (" + std::to_string(bytes.size()) + " bytes)");
        return bytes.data() + offset;
    };
    const uint8_t* indices =
        packed(sparse.indices.bufferView, sparse.indices.byteOffset, index_size, "indices");
    const uint8_t* values =
        packed(sparse.values.bufferView, sparse.values.byteOffset, element_size, "values");
    for (size_t i = 0; i < count; ++i) {
        uint32_t target = 0;
        if (index_size == 1) {
            target = indices[i];
        } else if (index_size == 2) {
            uint16_t v;
            std::memcpy(&v, indices + 2 * i, 2);
            target = v;
        } else {
            std::memcpy(&target, indices + 4 * i, 4);
        }
        if (target >= a.count)
            fail(what + ": index " + std::to_string(i) + " is " + std::to_string(target) +
                 ", past the end of the accessor (" + std::to_string(a.count) + " elements)");
        decode(values + i * element_size, target);
    }
}

std::vector<float> Accessors::read_floats(int index, const std::string& what,
                                          const std::vector<AllowedFormat>& allowed) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const std::string name = what + ": accessor " + std::to_string(index) + quoted_name(a.name);
    bool ok = false;
    for (const AllowedFormat& f : allowed)
        if (a.type == f.type &&
            std::find(f.components.begin(), f.components.end(), a.componentType) !=
                f.components.end() &&
            (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || !f.needs_normalized ||
             a.normalized))
            ok = true;
    if (!ok)
        fail(name + " is " + type_name(a.type) + " of " + component_name(a.componentType) +
             (a.normalized ? " (normalized)" : "") + ", which glTF does not allow here");
    const int components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    const int component_size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    std::vector<float> out;
    if (a.count > (size_t(1) << 28))
        fail(name + ": count " + std::to_string(a.count) + " is too large");
    // An accessor without a view is all zeros: a few bytes of JSON may ask for
    // 2^28 elements, so its floats are charged before they exist.
    budget_.charge(uint64_t(a.count) * uint64_t(components) * sizeof(float),
                   shown_path(path_) + ": " + name + ", read as floats");
    out.assign(a.count * size_t(components), 0.0f);
    const size_t element_size = size_t(components) * size_t(component_size);
    // One element's components, from `element`, into out[i].
    auto decode = [&](const uint8_t* element, size_t i) {
        for (int c = 0; c < components; ++c) {
            const uint8_t* p = element + ptrdiff_t(c) * component_size;
            float v = 0;
            switch (a.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT:
                    std::memcpy(&v, p, 4);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    v = float(*p) / 255.0f;
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    uint16_t s;
                    std::memcpy(&s, p, 2);
                    v = float(s) / 65535.0f;
                    break;
                }
                default:
                    break;  // excluded by `allowed`
            }
            out[i * size_t(components) + size_t(c)] = v;
        }
    };
    if (a.bufferView >= 0) {  // no view: all zeros, as glTF says
        std::span<const uint8_t> bytes = element_range(a, name, element_size);
        const size_t stride = stride_of(a, element_size);
        for (size_t i = 0; i < a.count; ++i) decode(bytes.data() + a.byteOffset + i * stride, i);
    }
    if (a.sparse.isSparse) apply_sparse(a, name, element_size, decode);
    // A NaN or an infinity would be drawn wrong, silently: a triangle with a
    // NaN corner vanishes, glm::min and max skip NaN in the bounds, a NaN
    // normal lights black. So any one of them refuses the attribute.
    for (size_t i = 0; i < out.size(); ++i)
        if (!std::isfinite(out[i]))
            fail(name + ": element " + std::to_string(i / size_t(components)) + ", component " +
                 std::to_string(i % size_t(components)) + ", is " +
                 (std::isnan(out[i]) ? "NaN" : "infinite") + ", not a finite number");
    return out;
}

std::vector<uint32_t> Accessors::read_indices(int index, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const std::string name =
        what + ": index accessor " + std::to_string(index) + quoted_name(a.name);
    const int ct = a.componentType;
    if (a.type != TINYGLTF_TYPE_SCALAR || (ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                           ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                           ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(name + " is " + type_name(a.type) + " of " + component_name(ct) +
             ", which glTF does not allow for indices (SCALAR of UNSIGNED_BYTE, "
             "UNSIGNED_SHORT or UNSIGNED_INT)");
    if (a.count > (size_t(1) << 28))
        fail(name + ": count " + std::to_string(a.count) + " is too large");
    // An accessor without a view reads as zeros, which glTF allows for
    // attributes but not for indices (their view must be an
    // ELEMENT_ARRAY_BUFFER). tinygltf 2.7 refuses it while it parses
    // (gltf_messages.cpp words that alike); 2.9 lets it through to here.
    if (a.bufferView < 0)
        fail(name +
             " has no bufferView (or one that does not exist): glTF requires one for "
             "indices");
    budget_.charge(uint64_t(a.count) * sizeof(uint32_t),
                   shown_path(path_) + ": " + name + ", read");
    std::vector<uint32_t> out(a.count, 0);
    const size_t size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(ct)));
    std::span<const uint8_t> bytes = element_range(a, name, size);
    const size_t stride = stride_of(a, size);
    for (size_t i = 0; i < a.count; ++i) {
        const uint8_t* p = bytes.data() + a.byteOffset + i * stride;
        if (size == 1) {
            out[i] = *p;
        } else if (size == 2) {
            uint16_t v;
            std::memcpy(&v, p, 2);
            out[i] = v;
        } else {
            std::memcpy(&out[i], p, 4);
        }
    }
    return out;
}

}  // namespace vkt::gltf_detail
