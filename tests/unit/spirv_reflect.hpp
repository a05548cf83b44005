#pragma once
// A tiny SPIR-V reader for the unit tests that check C++ mirrors of shader
// blocks against the compiled shaders (chapter 12 first; any test may use it).
// It finds a struct type by its OpName, its members' names (OpMemberName) and
// their decorations: Offset (OpMemberDecorate ... Offset), MatrixStride, and
// the ArrayStride of a member's array type. Errors throw std::runtime_error.
//
// SPIR-V is a stream of 32-bit words: a 5-word header (magic 0x07230203 first),
// then instructions, each starting with a word whose high 16 bits are its
// length in words and low 16 bits its opcode.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace spirv {

constexpr uint32_t op_name = 5, op_member_name = 6, op_type_struct = 30, op_decorate = 71,
                   op_member_decorate = 72;
constexpr uint32_t decoration_array_stride = 6, decoration_matrix_stride = 7,
                   decoration_offset = 35;

inline std::vector<uint32_t> read(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot open " + path);
    std::vector<char> bytes((std::istreambuf_iterator<char>(file)), {});
    if (bytes.size() % 4 != 0 || bytes.size() < 20)
        throw std::runtime_error(path + " is not SPIR-V (size)");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    if (words[0] != 0x07230203u) throw std::runtime_error(path + " is not SPIR-V (magic)");
    return words;
}

// A literal string: UTF-8 bytes, NUL-terminated, padded to whole words.
inline std::string literal(const uint32_t* words, size_t count) {
    std::string s(reinterpret_cast<const char*>(words), count * 4);
    return s.substr(0, s.find('\0'));
}

// Calls f(opcode, operands, operand_count) for every instruction.
template <typename F>
void for_each_instruction(const std::vector<uint32_t>& words, F&& f) {
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = words[i] >> 16, opcode = words[i] & 0xffffu;
        if (count == 0 || i + count > words.size())
            throw std::runtime_error("malformed SPIR-V instruction");
        f(opcode, words.data() + i + 1, count - 1);  // count - 1 may be 0
        i += count;
    }
}

// Everything the tests ask about one struct type.
struct Member {
    uint32_t offset = 0;
    uint32_t matrix_stride = 0;  // 0 unless a matrix
    uint32_t array_stride = 0;   // 0 unless an array
};

// The members of the struct type named `name` (a block's name, or a struct's):
// member name -> its decorations.
inline std::map<std::string, Member> struct_members(const std::vector<uint32_t>& words,
                                                    const std::string& name) {
    // A struct used both in a block and as a plain value (a function's
    // parameter, say) appears twice, with the same name: take the one whose
    // members have Offset decorations, the laid-out one.
    std::vector<uint32_t> named;
    std::vector<uint32_t> laid_out;
    for_each_instruction(words, [&](uint32_t op, const uint32_t* operands, uint32_t count) {
        if (op == op_name && literal(operands + 1, count - 1) == name) named.push_back(operands[0]);
        if (op == op_member_decorate && operands[2] == decoration_offset)
            laid_out.push_back(operands[0]);
    });
    uint32_t type = 0;
    for (uint32_t id : named)
        if (type == 0 && std::find(laid_out.begin(), laid_out.end(), id) != laid_out.end())
            type = id;
    if (type == 0) throw std::runtime_error("no laid-out struct type named " + name);
    std::map<uint32_t, std::string> names;
    std::map<uint32_t, Member> members;
    std::map<uint32_t, uint32_t> member_types;   // member index -> type id
    std::map<uint32_t, uint32_t> array_strides;  // array type id -> stride
    for_each_instruction(words, [&](uint32_t op, const uint32_t* operands, uint32_t count) {
        if (op == op_member_name && operands[0] == type)
            names[operands[1]] = literal(operands + 2, count - 2);
        if (op == op_member_decorate && operands[0] == type) {
            if (operands[2] == decoration_offset) members[operands[1]].offset = operands[3];
            if (operands[2] == decoration_matrix_stride)
                members[operands[1]].matrix_stride = operands[3];
        }
        if (op == op_type_struct && operands[0] == type)
            for (uint32_t m = 1; m < count; ++m) member_types[m - 1] = operands[m];
        if (op == op_decorate && operands[1] == decoration_array_stride)
            array_strides[operands[0]] = operands[2];
    });
    std::map<std::string, Member> out;
    for (const auto& [index, member_name] : names) {
        Member member = members[index];
        if (auto stride = array_strides.find(member_types[index]); stride != array_strides.end())
            member.array_stride = stride->second;
        out[member_name] = member;
    }
    return out;
}

// Just the offsets: member name -> Offset.
inline std::map<std::string, uint32_t> offsets(const std::vector<uint32_t>& words,
                                               const std::string& name) {
    std::map<std::string, uint32_t> out;
    for (const auto& [member_name, member] : struct_members(words, name))
        out[member_name] = member.offset;
    return out;
}

// The literal operands of the first OpExecutionMode (opcode 16) that sets
// `mode` on any entry point: e.g. LocalSize (17) gives x, y, z, OutputVertices
// (26) and OutputPrimitivesEXT (5270) one number each. Empty if none does.
constexpr uint32_t op_execution_mode = 16, mode_local_size = 17, mode_output_vertices = 26,
                   mode_output_primitives = 5270;
inline std::vector<uint32_t> execution_mode(const std::vector<uint32_t>& words, uint32_t mode) {
    for (size_t i = 5; i < words.size();) {
        const uint32_t length = words[i] >> 16, opcode = words[i] & 0xffffu;
        if (length == 0 || i + length > words.size())
            throw std::runtime_error("malformed SPIR-V instruction");
        if (opcode == op_execution_mode && length >= 3 && words[i + 2] == mode)
            return {words.begin() + long(i) + 3, words.begin() + long(i + length)};
        i += length;
    }
    return {};
}

// The workgroup size: LocalSize's three numbers, or, as glslang writes it for
// SPIR-V 1.4 and later, OpExecutionModeId (331) LocalSizeId (38) naming three
// constant ids: OpConstant (43), or OpSpecConstant (50) whose value is the
// default that a pipeline may replace. spec_ids gets, for each of x, y, z,
// the specialization constant's id (decoration SpecId, 1) or -1.
inline std::vector<uint32_t> local_size(const std::vector<uint32_t>& words,
                                        std::vector<int>* spec_ids = nullptr) {
    if (auto sizes = execution_mode(words, mode_local_size); !sizes.empty()) {
        if (spec_ids) spec_ids->assign(3, -1);
        return sizes;
    }
    constexpr uint32_t op_execution_mode_id = 331, mode_local_size_id = 38, op_constant = 43,
                       op_spec_constant = 50, decoration_spec_id = 1;
    std::map<uint32_t, uint32_t> constants;  // result id -> value (32-bit constants)
    std::map<uint32_t, int> spec_id_of;      // result id -> SpecId
    std::vector<uint32_t> ids;
    for (size_t i = 5; i < words.size();) {
        const uint32_t length = words[i] >> 16, opcode = words[i] & 0xffffu;
        if (length == 0 || i + length > words.size())
            throw std::runtime_error("malformed SPIR-V instruction");
        if ((opcode == op_constant || opcode == op_spec_constant) && length == 4)
            constants[words[i + 2]] = words[i + 3];
        if (opcode == op_decorate && length == 4 && words[i + 2] == decoration_spec_id)
            spec_id_of[words[i + 1]] = int(words[i + 3]);
        if (opcode == op_execution_mode_id && length == 6 && words[i + 2] == mode_local_size_id)
            ids.assign(words.begin() + long(i) + 3, words.begin() + long(i) + 6);
        i += length;
    }
    std::vector<uint32_t> sizes;
    if (spec_ids) spec_ids->clear();
    for (uint32_t id : ids) {
        if (!constants.count(id)) throw std::runtime_error("LocalSizeId names no constant");
        sizes.push_back(constants[id]);
        if (spec_ids) spec_ids->push_back(spec_id_of.count(id) ? spec_id_of[id] : -1);
    }
    return sizes;
}

}  // namespace spirv
