#pragma once
// Chapter 27's pipeline cache on disk: what a file must hold before its bytes
// are handed to vkCreatePipelineCache, and how the cache is written back.
// The check is plain C++ on the bytes (tests/unit/test_threads.cpp feeds it
// good, short, foreign and garbled headers); the rest calls Vulkan.

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"

#include <vulkan/vulkan.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace ch27 {

inline std::string hex_uuid(const uint8_t (&uuid)[VK_UUID_SIZE]) {
    std::string out;
    char digits[3];
    for (uint8_t byte : uuid) {
        std::snprintf(digits, sizeof digits, "%02x", byte);
        out += digits;
    }
    return out;
}

// [check-header]
// Why a file may not be used as this device's pipeline cache, in words; empty
// when it may. Every cache begins with the same 32-byte header (the
// specification fixes its layout, VkPipelineCacheHeaderVersionOne): its own
// size, its version, then the vendor and device it was made by and the
// driver's pipelineCacheUUID, which changes with every driver build that
// would read old data differently. A driver checks these too, and must treat
// a mismatch as an empty cache; but a driver is the last place to find out
// that a file is garbage, and only the application can say so to the user.
inline std::string cache_header_problem(const std::vector<char>& data,
                                        const VkPhysicalDeviceProperties& device) {
    VkPipelineCacheHeaderVersionOne header{};
    if (data.size() < sizeof header)
        return "not a pipeline cache (" + std::to_string(data.size()) +
               " bytes, shorter than the 32-byte header)";
    std::memcpy(&header, data.data(), sizeof header);
    if (header.headerSize != sizeof header ||
        header.headerVersion != VK_PIPELINE_CACHE_HEADER_VERSION_ONE)
        return "not a pipeline cache (header size " + std::to_string(header.headerSize) +
               ", version " + std::to_string(int(header.headerVersion)) + "; expected 32, 1)";
    char ids[96];
    std::snprintf(ids, sizeof ids, "vendor 0x%x, device 0x%x", header.vendorID, header.deviceID);
    if (header.vendorID != device.vendorID || header.deviceID != device.deviceID ||
        std::memcmp(header.pipelineCacheUUID, device.pipelineCacheUUID, VK_UUID_SIZE) != 0)
        return std::string("made by another device or driver (") + ids + ", cache UUID " +
               hex_uuid(header.pipelineCacheUUID) + "; this one is " + device.deviceName +
               ", cache UUID " + hex_uuid(device.pipelineCacheUUID) + ")";
    return {};
}
// [/check-header]

// [load]
// The bytes to start the cache with: the file's, where its header says this
// device made it; else none (a cold start). One line says which.
inline std::vector<char> load_cache_file(const std::string& path,
                                         const VkPhysicalDeviceProperties& device) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
        std::fprintf(stderr, "27_threads: pipeline cache %s: no file yet, starting cold\n",
                     path.c_str());
        return {};
    }
    std::vector<char> data;
    std::string problem;
    try {
        data = vkt::read_file(path);
        problem = cache_header_problem(data, device);
    } catch (const vkt::Error& e) {
        problem = e.what();
    }
    if (!problem.empty()) {
        std::fprintf(stderr, "27_threads: pipeline cache %s ignored, starting cold: %s\n",
                     path.c_str(), problem.c_str());
        return {};
    }
    std::fprintf(stderr, "27_threads: pipeline cache %s: loaded %zu bytes made by this device\n",
                 path.c_str(), data.size());
    return data;
}
// [/load]

// [save]
// Writes the cache's current contents to `path`: first to a file of its own
// beside it, then renamed over `path` in one step, so that a run that stops
// half-way, or two runs saving at once, never leave half a cache behind. A
// cache is only a speed-up: failing to save it is said in one line, not fatal.
inline void save_cache_file(const std::string& path, VkDevice device, VkPipelineCache cache) {
    size_t size = 0;
    VKT_CHECK(vkGetPipelineCacheData(device, cache, &size, nullptr));
    std::vector<char> data(size);
    VKT_CHECK(vkGetPipelineCacheData(device, cache, &size, data.data()));
    data.resize(size);
    const std::string temporary =
        path + ".tmp" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
    std::ofstream out(temporary, std::ios::binary);
    out.write(data.data(), std::streamsize(data.size()));
    out.close();
    std::error_code error, ignored;
    if (out) std::filesystem::rename(temporary, path, error);
    if (!out || error) {
        std::filesystem::remove(temporary, ignored);
        std::fprintf(stderr, "27_threads: pipeline cache %s: could not save it (%s)\n",
                     path.c_str(), out ? error.message().c_str() : "cannot write there");
        return;
    }
    std::fprintf(stderr, "27_threads: pipeline cache %s: saved %zu bytes\n", path.c_str(),
                 data.size());
}
// [/save]

}  // namespace ch27
