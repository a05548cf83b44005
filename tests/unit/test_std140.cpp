// The C++ mirrors of the std140 uniform blocks of chapters 07 and 08 against
// the compiled shaders: a tiny SPIR-V reader finds each block's struct type by
// name (OpName), its members' names (OpMemberName) and their byte offsets
// (OpMemberDecorate ... Offset), and the test compares them with offsetof.
#include "../../chapters/07_uniform_buffers/uniforms.hpp"
#include "../../chapters/08_depth/uniforms.hpp"

#include <catch2/catch_test_macros.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace {

std::vector<uint32_t> read_spirv(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    REQUIRE(file);
    std::vector<char> bytes((std::istreambuf_iterator<char>(file)), {});
    REQUIRE(bytes.size() % 4 == 0);
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    REQUIRE(words.size() > 5);
    REQUIRE(words[0] == 0x07230203u);  // the magic number
    return words;
}

// A literal string in SPIR-V: UTF-8 bytes, NUL-terminated, padded to words.
std::string spirv_string(const uint32_t* words, size_t count) {
    std::string s(reinterpret_cast<const char*>(words), count * 4);
    return s.substr(0, s.find('\0'));
}

// Member name -> Offset decoration of the struct type called `block`.
std::map<std::string, uint32_t> block_offsets(const std::vector<uint32_t>& words,
                                              const std::string& block) {
    constexpr uint32_t op_name = 5, op_member_name = 6, op_member_decorate = 72;
    constexpr uint32_t decoration_offset = 35;
    uint32_t type = 0;
    std::map<uint32_t, std::string> names;  // member index -> name
    std::map<uint32_t, uint32_t> offsets;   // member index -> offset
    // Two passes: OpName of the type may come after nothing else we need, but
    // member instructions refer to the type id, so find it first.
    for (int pass = 0; pass < 2; ++pass) {
        for (size_t i = 5; i < words.size();) {  // after the 5-word header
            const uint32_t count = words[i] >> 16, opcode = words[i] & 0xffffu;
            REQUIRE(count > 0);
            REQUIRE(i + count <= words.size());
            // An instruction may have no operands (OpFunctionEnd, the last
            // one, is a single word): read operands[0] only when there is one.
            const uint32_t* operands = words.data() + i + 1;
            if (pass == 0 && opcode == op_name && count >= 3 &&
                spirv_string(operands + 1, count - 2) == block)
                type = operands[0];
            if (pass == 1 && type != 0 && count >= 2 && operands[0] == type) {
                if (opcode == op_member_name)
                    names[operands[1]] = spirv_string(operands + 2, count - 3);
                if (opcode == op_member_decorate && operands[2] == decoration_offset)
                    offsets[operands[1]] = operands[3];
            }
            i += count;
        }
    }
    REQUIRE(type != 0);
    std::map<std::string, uint32_t> out;
    for (const auto& [index, name] : names) {
        REQUIRE(offsets.count(index) == 1);
        out[name] = offsets[index];
    }
    return out;
}

std::string spv(const char* chapter, const char* file) {
    return std::string(VKT_BINARY_DIR "/shaders/") + chapter + "/" + file + ".spv";
}

}  // namespace

TEST_CASE("the SPIR-V reader finds a block's members and offsets", "[std140]") {
    const auto words = read_spirv(spv("07_uniform_buffers", "cube.vert"));
    const auto frame = block_offsets(words, "FrameUniforms");
    CHECK(frame.size() == 2);
}

TEST_CASE("chapter 07's C++ uniform structs match the shader's std140 blocks", "[std140]") {
    const auto words = read_spirv(spv("07_uniform_buffers", "cube.vert"));
    using ch07::FrameUniforms;
    using ch07::ObjectUniforms;
    const std::map<std::string, uint32_t> frame{
        {"view", offsetof(FrameUniforms, view)},
        {"proj", offsetof(FrameUniforms, proj)},
    };
    CHECK(block_offsets(words, "FrameUniforms") == frame);
    const std::map<std::string, uint32_t> object{
        {"world", offsetof(ObjectUniforms, world)},
        {"tint", offsetof(ObjectUniforms, tint)},
        {"tint_amount", offsetof(ObjectUniforms, tint_amount)},
    };
    CHECK(block_offsets(words, "ObjectUniforms") == object);
    // std140 by hand: tint is a vec3 at 64 and tint_amount fills its 4th word.
    CHECK(block_offsets(words, "ObjectUniforms").at("tint_amount") == 76);
}

TEST_CASE("chapter 08's C++ uniform structs match the shader's std140 blocks", "[std140]") {
    const auto words = read_spirv(spv("08_depth", "scene.vert"));
    using ch08::FrameUniforms;
    using ch08::ObjectUniforms;
    const std::map<std::string, uint32_t> frame{
        {"view", offsetof(FrameUniforms, view)},
        {"proj", offsetof(FrameUniforms, proj)},
    };
    CHECK(block_offsets(words, "FrameUniforms") == frame);
    const std::map<std::string, uint32_t> object{
        {"world", offsetof(ObjectUniforms, world)},
        {"tint", offsetof(ObjectUniforms, tint)},
        {"tint_amount", offsetof(ObjectUniforms, tint_amount)},
    };
    CHECK(block_offsets(words, "ObjectUniforms") == object);
}
