// The soak tests' counter: a library preloaded into a chapter (LD_PRELOAD)
// that counts, without touching the chapter or common/, what a frame loop
// must not accumulate. It defines the Vulkan entry points that create and
// destroy objects and device memory; each counts, then calls the loader's own
// (dlsym RTLD_NEXT). The chapters call Vulkan directly, so every call they
// and common/ make passes through here.
//
// Frames are counted by vkQueuePresentKHR (one per frame, headless too).
// From frame VKT_SOAK_FROM (default 500) on, each present samples resident
// memory (from /proc/self/status) and the heap in use (mallinfo2). Resident
// memory is judged by its anonymous part (RssAnon: heaps, stacks, private
// mappings), which is where anything kept per frame lands; the file-backed
// part (RssFile) is reported only: it is program and library code read in on
// first use (07 and 08 read in 48-64 KiB more of libm around frame 3,700,
// when their angles grow past where sin and cos change method), bounded by
// the size of the files. Each block of 50 frames keeps its least sample;
// the frames measured are cut into eight segments, and growth is the least
// of the six rises from one segment's least sample to the next one's (the
// first segment is warm-up), per frame times the frames measured
// (soak_growth.hpp says why: a steady leak reads at its full size, memory
// kept once or given back later as none). Live Vulkan objects and
// device allocations are exact counts, compared at frame VKT_SOAK_FROM and at the last frame. At
// exit it prints
//   vkt_soak: frames 500..10000: resident +0 KiB (limit 64; file-backed +0
//   KiB), heap +272 bytes (limit 16 KiB), Vulkan objects 18 -> 18, device
//   allocations 1 -> 1 (16384 -> 16384 bytes): pass
// or the same ending in "FAIL: <what grew>"; the test expects "pass".
// VKT_SOAK_TRACE=N also prints resident memory and the heap every N frames.
// VKT_SOAK_LEAK=N makes this library itself keep N bytes a frame (written,
// so resident): the soak's own test, that a steady leak fails it.
#include "soak_growth.hpp"

#include <vulkan/vulkan.h>

#include <dlfcn.h>
#include <fcntl.h>
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace {

struct Counts {
    int64_t objects = 0;
    int64_t allocations = 0;
    int64_t allocated_bytes = 0;
};
struct Memory {
    int64_t resident_kib = 0;  // anonymous and file-backed
    int64_t anonymous_kib = 0;
    int64_t heap_bytes = 0;
};
constexpr uint64_t block = 50;  // frames per block: each block keeps its least sample

std::mutex mutex;
int64_t objects = 0;      // live Vulkan objects created through here
int64_t allocations = 0;  // live VkDeviceMemory
int64_t allocated_bytes = 0;
std::map<uint64_t, int64_t> memory_sizes;   // VkDeviceMemory -> size
std::map<uint64_t, int64_t> pool_children;  // command or descriptor pool -> live children
std::map<uint64_t, uint64_t> child_pools;   // command buffer or set -> its pool
uint64_t presents = 0;
uint64_t from = 500;
uint64_t trace = 0;
size_t leak_bytes = 0;
void* leaked = nullptr;  // VKT_SOAK_LEAK's blocks, each pointing to the one before
Counts counts_first, counts_last;
std::vector<Memory> block_minima;  // from frame `from` on, one per block (the last may be partial)

// Resident memory, in KiB: anonymous (heaps, stacks, mappings of our own)
// and file-backed (the code and data of the program and its libraries).
struct Resident {
    int64_t anon = 0, file = 0;
};
// Read with open and read into a buffer on the stack, not stdio: the
// measuring must not allocate (fopen and fgets do).
Resident resident() {
    Resident out;
    char text[4096];
    const int fd = open("/proc/self/status", O_RDONLY);
    if (fd < 0) return out;
    const ssize_t size = read(fd, text, sizeof text - 1);
    close(fd);
    if (size <= 0) return out;
    text[size] = '\0';
    if (const char* anon = std::strstr(text, "RssAnon:")) out.anon = std::atoll(anon + 8);
    if (const char* file = std::strstr(text, "RssFile:")) out.file = std::atoll(file + 8);
    return out;
}

Memory memory() {
    const struct mallinfo2 heap = mallinfo2();
    const Resident now = resident();
    return {now.anon + now.file, now.anon, int64_t(heap.uordblks + heap.hblkhd)};
}

Counts counts() {
    return {objects, allocations, allocated_bytes};
}

template <typename T>
uint64_t key(T handle) {
    return uint64_t(handle);
}

template <typename Fn>
Fn next(const char* name) {
    void* real = dlsym(RTLD_NEXT, name);
    if (!real) {
        std::fprintf(stderr, "vkt_soak: no %s after this library\n", name);
        std::abort();
    }
    return reinterpret_cast<Fn>(real);
}

void created(int64_t n) {
    std::lock_guard lock(mutex);
    objects += n;
}

void add_children(uint64_t pool, uint32_t count, const void* handles, size_t size) {
    std::lock_guard lock(mutex);
    pool_children[pool] += count;
    objects += count;
    for (uint32_t i = 0; i < count; ++i) {
        uint64_t handle = 0;
        std::memcpy(&handle, static_cast<const char*>(handles) + i * size, size);
        child_pools[handle] = pool;
    }
}

void remove_children(uint64_t pool, uint32_t count, const void* handles, size_t size) {
    std::lock_guard lock(mutex);
    for (uint32_t i = 0; i < count; ++i) {
        uint64_t handle = 0;
        std::memcpy(&handle, static_cast<const char*>(handles) + i * size, size);
        if (handle == 0 || child_pools.erase(handle) == 0) continue;
        --pool_children[pool];
        --objects;
    }
}

// A pool's children go with it (destroyed, or reset for descriptor pools).
void drop_pool_children(uint64_t pool) {
    std::lock_guard lock(mutex);
    objects -= pool_children[pool];
    pool_children.erase(pool);
    for (auto it = child_pools.begin(); it != child_pools.end();)
        it = it->second == pool ? child_pools.erase(it) : std::next(it);
}

__attribute__((destructor)) void report() {
    // Preloaded into a program that made no Vulkan object (the test's own
    // checker, which starts the chapter): nothing to say.
    if (presents == 0 && objects == 0 && allocations == 0) return;
    if (block_minima.size() < 4) {
        std::fprintf(stderr, "vkt_soak: FAIL: only %llu frames presented, not %llu or more\n",
                     (unsigned long long)presents, (unsigned long long)(from + 3 * block));
        return;
    }
    // The growth over the frames measured, per kind of memory.
    const uint64_t frames = presents - from;
    std::vector<int64_t> anonymous, file_backed, heap;
    for (const Memory& min : block_minima) {
        anonymous.push_back(min.anonymous_kib);
        file_backed.push_back(min.resident_kib - min.anonymous_kib);
        heap.push_back(min.heap_bytes);
    }
    auto growth = [&](const std::vector<int64_t>& minima) {
        return int64_t(vkt::soak::least_rise_growth(minima, block, frames));
    };
    const char* rss_text = std::getenv("VKT_SOAK_RSS_KIB");
    const int64_t rss_limit = rss_text ? std::atoll(rss_text) : 64;
    const char* heap_text = std::getenv("VKT_SOAK_HEAP_KIB");
    const int64_t heap_limit = heap_text ? std::atoll(heap_text) : 16;
    const int64_t anonymous_growth = growth(anonymous);
    const int64_t file_growth = growth(file_backed);
    const int64_t heap_growth = growth(heap);
    std::string failures;
    if (anonymous_growth > rss_limit) failures += " resident memory grew;";
    if (heap_growth > heap_limit * 1024) failures += " the heap grew;";
    if (counts_last.objects != counts_first.objects) failures += " Vulkan objects changed;";
    if (counts_last.allocations != counts_first.allocations ||
        counts_last.allocated_bytes != counts_first.allocated_bytes)
        failures += " device allocations changed;";
    std::fprintf(stderr,
                 "vkt_soak: frames %llu..%llu: resident %+lld KiB (limit %lld; file-backed %+lld "
                 "KiB), heap %+lld bytes (limit %lld KiB), Vulkan objects %lld -> %lld, device "
                 "allocations %lld -> %lld (%lld -> %lld bytes): %s%s\n",
                 (unsigned long long)from, (unsigned long long)presents,
                 (long long)anonymous_growth, (long long)rss_limit, (long long)file_growth,
                 (long long)heap_growth, (long long)heap_limit, (long long)counts_first.objects,
                 (long long)counts_last.objects, (long long)counts_first.allocations,
                 (long long)counts_last.allocations, (long long)counts_first.allocated_bytes,
                 (long long)counts_last.allocated_bytes,
                 failures.empty() ? "pass" : "FAIL:", failures.c_str());
}

__attribute__((constructor)) void start() {
    if (const char* text = std::getenv("VKT_SOAK_FROM")) from = std::strtoull(text, nullptr, 10);
    if (from == 0) from = 1;
    if (const char* every = std::getenv("VKT_SOAK_TRACE"))
        trace = std::strtoull(every, nullptr, 10);
    if (const char* leak = std::getenv("VKT_SOAK_LEAK"))
        leak_bytes = std::max<size_t>(std::strtoull(leak, nullptr, 10), sizeof(void*));
    block_minima.reserve(4096);  // 200,000 frames: the list must not grow the heap it measures
}

}  // namespace

// Objects made one at a time: vkCreateX(parent, info, allocator, &handle) and
// vkDestroyX(parent, handle, allocator).
#define VKT_SOAK_OBJECT(Type, Info)                                                                \
    extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkCreate##Type(                                      \
        VkDevice device, const Info* info, const VkAllocationCallbacks* alloc, Vk##Type* handle) { \
        static const auto real = next<PFN_vkCreate##Type>("vkCreate" #Type);                       \
        const VkResult result = real(device, info, alloc, handle);                                 \
        if (result == VK_SUCCESS) created(1);                                                      \
        return result;                                                                             \
    }                                                                                              \
    extern "C" VKAPI_ATTR void VKAPI_CALL vkDestroy##Type(VkDevice device, Vk##Type handle,        \
                                                          const VkAllocationCallbacks* alloc) {    \
        static const auto real = next<PFN_vkDestroy##Type>("vkDestroy" #Type);                     \
        if (handle != VK_NULL_HANDLE) created(-1);                                                 \
        real(device, handle, alloc);                                                               \
    }

VKT_SOAK_OBJECT(Buffer, VkBufferCreateInfo)
VKT_SOAK_OBJECT(BufferView, VkBufferViewCreateInfo)
VKT_SOAK_OBJECT(Image, VkImageCreateInfo)
VKT_SOAK_OBJECT(ImageView, VkImageViewCreateInfo)
VKT_SOAK_OBJECT(Sampler, VkSamplerCreateInfo)
VKT_SOAK_OBJECT(ShaderModule, VkShaderModuleCreateInfo)
VKT_SOAK_OBJECT(PipelineLayout, VkPipelineLayoutCreateInfo)
VKT_SOAK_OBJECT(PipelineCache, VkPipelineCacheCreateInfo)
VKT_SOAK_OBJECT(DescriptorSetLayout, VkDescriptorSetLayoutCreateInfo)
VKT_SOAK_OBJECT(Fence, VkFenceCreateInfo)
VKT_SOAK_OBJECT(Semaphore, VkSemaphoreCreateInfo)
VKT_SOAK_OBJECT(Event, VkEventCreateInfo)
VKT_SOAK_OBJECT(QueryPool, VkQueryPoolCreateInfo)
VKT_SOAK_OBJECT(SwapchainKHR, VkSwapchainCreateInfoKHR)
#undef VKT_SOAK_OBJECT

extern "C" VKAPI_ATTR VkResult VKAPI_CALL
vkCreateGraphicsPipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                          const VkGraphicsPipelineCreateInfo* infos,
                          const VkAllocationCallbacks* alloc, VkPipeline* pipelines) {
    static const auto real = next<PFN_vkCreateGraphicsPipelines>("vkCreateGraphicsPipelines");
    const VkResult result = real(device, cache, count, infos, alloc, pipelines);
    for (uint32_t i = 0; i < count; ++i)
        if (pipelines[i] != VK_NULL_HANDLE) created(1);
    return result;
}

extern "C" VKAPI_ATTR VkResult VKAPI_CALL
vkCreateComputePipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                         const VkComputePipelineCreateInfo* infos,
                         const VkAllocationCallbacks* alloc, VkPipeline* pipelines) {
    static const auto real = next<PFN_vkCreateComputePipelines>("vkCreateComputePipelines");
    const VkResult result = real(device, cache, count, infos, alloc, pipelines);
    for (uint32_t i = 0; i < count; ++i)
        if (pipelines[i] != VK_NULL_HANDLE) created(1);
    return result;
}

extern "C" VKAPI_ATTR void VKAPI_CALL vkDestroyPipeline(VkDevice device, VkPipeline pipeline,
                                                        const VkAllocationCallbacks* alloc) {
    static const auto real = next<PFN_vkDestroyPipeline>("vkDestroyPipeline");
    if (pipeline != VK_NULL_HANDLE) created(-1);
    real(device, pipeline, alloc);
}

// Pools and what is allocated from them.
extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkCreateCommandPool(VkDevice device,
                                                              const VkCommandPoolCreateInfo* info,
                                                              const VkAllocationCallbacks* alloc,
                                                              VkCommandPool* pool) {
    static const auto real = next<PFN_vkCreateCommandPool>("vkCreateCommandPool");
    const VkResult result = real(device, info, alloc, pool);
    if (result == VK_SUCCESS) created(1);
    return result;
}

extern "C" VKAPI_ATTR void VKAPI_CALL vkDestroyCommandPool(VkDevice device, VkCommandPool pool,
                                                           const VkAllocationCallbacks* alloc) {
    static const auto real = next<PFN_vkDestroyCommandPool>("vkDestroyCommandPool");
    if (pool != VK_NULL_HANDLE) {
        drop_pool_children(key(pool));
        created(-1);
    }
    real(device, pool, alloc);
}

extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkAllocateCommandBuffers(
    VkDevice device, const VkCommandBufferAllocateInfo* info, VkCommandBuffer* buffers) {
    static const auto real = next<PFN_vkAllocateCommandBuffers>("vkAllocateCommandBuffers");
    const VkResult result = real(device, info, buffers);
    if (result == VK_SUCCESS)
        add_children(key(info->commandPool), info->commandBufferCount, buffers,
                     sizeof(VkCommandBuffer));
    return result;
}

extern "C" VKAPI_ATTR void VKAPI_CALL vkFreeCommandBuffers(VkDevice device, VkCommandPool pool,
                                                           uint32_t count,
                                                           const VkCommandBuffer* buffers) {
    static const auto real = next<PFN_vkFreeCommandBuffers>("vkFreeCommandBuffers");
    remove_children(key(pool), count, buffers, sizeof(VkCommandBuffer));
    real(device, pool, count, buffers);
}

extern "C" VKAPI_ATTR VkResult VKAPI_CALL
vkCreateDescriptorPool(VkDevice device, const VkDescriptorPoolCreateInfo* info,
                       const VkAllocationCallbacks* alloc, VkDescriptorPool* pool) {
    static const auto real = next<PFN_vkCreateDescriptorPool>("vkCreateDescriptorPool");
    const VkResult result = real(device, info, alloc, pool);
    if (result == VK_SUCCESS) created(1);
    return result;
}

extern "C" VKAPI_ATTR void VKAPI_CALL vkDestroyDescriptorPool(VkDevice device,
                                                              VkDescriptorPool pool,
                                                              const VkAllocationCallbacks* alloc) {
    static const auto real = next<PFN_vkDestroyDescriptorPool>("vkDestroyDescriptorPool");
    if (pool != VK_NULL_HANDLE) {
        drop_pool_children(key(pool));
        created(-1);
    }
    real(device, pool, alloc);
}

extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkResetDescriptorPool(VkDevice device,
                                                                VkDescriptorPool pool,
                                                                VkDescriptorPoolResetFlags flags) {
    static const auto real = next<PFN_vkResetDescriptorPool>("vkResetDescriptorPool");
    drop_pool_children(key(pool));
    return real(device, pool, flags);
}

extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkAllocateDescriptorSets(
    VkDevice device, const VkDescriptorSetAllocateInfo* info, VkDescriptorSet* sets) {
    static const auto real = next<PFN_vkAllocateDescriptorSets>("vkAllocateDescriptorSets");
    const VkResult result = real(device, info, sets);
    if (result == VK_SUCCESS)
        add_children(key(info->descriptorPool), info->descriptorSetCount, sets,
                     sizeof(VkDescriptorSet));
    return result;
}

extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkFreeDescriptorSets(VkDevice device,
                                                               VkDescriptorPool pool,
                                                               uint32_t count,
                                                               const VkDescriptorSet* sets) {
    static const auto real = next<PFN_vkFreeDescriptorSets>("vkFreeDescriptorSets");
    remove_children(key(pool), count, sets, sizeof(VkDescriptorSet));
    return real(device, pool, count, sets);
}

// Device memory: how many allocations, and how many bytes.
extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkAllocateMemory(VkDevice device,
                                                           const VkMemoryAllocateInfo* info,
                                                           const VkAllocationCallbacks* alloc,
                                                           VkDeviceMemory* memory) {
    static const auto real = next<PFN_vkAllocateMemory>("vkAllocateMemory");
    const VkResult result = real(device, info, alloc, memory);
    if (result == VK_SUCCESS) {
        std::lock_guard lock(mutex);
        ++allocations;
        allocated_bytes += int64_t(info->allocationSize);
        memory_sizes[key(*memory)] = int64_t(info->allocationSize);
    }
    return result;
}

extern "C" VKAPI_ATTR void VKAPI_CALL vkFreeMemory(VkDevice device, VkDeviceMemory memory,
                                                   const VkAllocationCallbacks* alloc) {
    static const auto real = next<PFN_vkFreeMemory>("vkFreeMemory");
    if (memory != VK_NULL_HANDLE) {
        std::lock_guard lock(mutex);
        --allocations;
        allocated_bytes -= memory_sizes[key(memory)];
        memory_sizes.erase(key(memory));
    }
    real(device, memory, alloc);
}

// One present per frame: the soak's clock.
extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkQueuePresentKHR(VkQueue queue,
                                                            const VkPresentInfoKHR* info) {
    static const auto real = next<PFN_vkQueuePresentKHR>("vkQueuePresentKHR");
    const VkResult result = real(queue, info);
    std::lock_guard lock(mutex);
    ++presents;
    // The first sample costs 64 KiB of resident memory once (stdio's and
    // mallinfo2's own first use): a throwaway one at frame 1 keeps the
    // measuring from counting itself.
    if (presents == 1) memory();
    if (leak_bytes != 0) {
        void* block_kept = std::malloc(leak_bytes);
        if (block_kept) {
            std::memset(block_kept, 1, leak_bytes);
            *static_cast<void**>(block_kept) = leaked;
            leaked = block_kept;
        }
    }
    const bool tracing = trace != 0 && presents % trace == 0;
    if (presents < from && !tracing) return result;
    const Memory now = memory();
    if (tracing)
        std::fprintf(stderr,
                     "vkt_soak: frame %llu: resident %lld KiB (anonymous %lld), heap %lld bytes\n",
                     (unsigned long long)presents, (long long)now.resident_kib,
                     (long long)now.anonymous_kib, (long long)now.heap_bytes);
    if (presents < from) return result;
    if (presents == from) counts_first = counts();
    counts_last = counts();
    if ((presents - from) % block == 0) block_minima.push_back(now);
    Memory& min = block_minima.back();
    min.resident_kib = std::min(min.resident_kib, now.resident_kib);
    min.anonymous_kib = std::min(min.anonymous_kib, now.anonymous_kib);
    min.heap_bytes = std::min(min.heap_bytes, now.heap_bytes);
    return result;
}
