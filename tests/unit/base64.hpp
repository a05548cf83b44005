#pragma once
// What the glTF unit tests (test_gltf.cpp, test_gltf_files.cpp) and the
// fuzzers' seed writer (tests/fuzz/make_seeds.cpp) share to write glTF files:
// base64 for data: URIs.

#include <cstdint>
#include <string>
#include <vector>

namespace vkt_test {

inline std::string base64(const std::vector<uint8_t>& data) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
        uint32_t n = uint32_t(data[i]) << 16;
        if (i + 1 < data.size()) n |= uint32_t(data[i + 1]) << 8;
        if (i + 2 < data.size()) n |= data[i + 2];
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < data.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < data.size() ? digits[n & 63] : '=';
    }
    return out;
}

}  // namespace vkt_test
