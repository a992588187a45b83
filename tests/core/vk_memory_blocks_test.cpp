// The device-memory blocks of a context (backend_vk/src/vk_memory_blocks.hpp) on a fake device:
// vkAllocateMemory, vkFreeMemory and vkMapMemory are functions of this test, so a block
// allocation can fail on demand and every allocation is seen. No GPU.
#include "vk_memory_blocks.hpp"

#include <gtest/gtest.h>

#include <map>
#include <vector>

namespace {

using grass::vk::Allocation;
using grass::vk::AllocationRequest;
using grass::vk::MemoryBlocks;
using grass::vk::Tiling;

// The fake device: live allocations by handle, with their sizes and mappings.
struct FakeDevice {
    std::map<uint64_t, VkDeviceSize> live;
    std::map<uint64_t, std::vector<char>> mapped;
    uint64_t next = 1;
    int calls = 0, fail_next = 0;
    const VkAllocationCallbacks* callbacks_seen = nullptr;
} fake;

VKAPI_ATTR VkResult VKAPI_CALL fake_allocate(VkDevice, const VkMemoryAllocateInfo* info,
                                             const VkAllocationCallbacks* callbacks, VkDeviceMemory* out) {
    fake.calls += 1;
    fake.callbacks_seen = callbacks;
    if (fake.fail_next > 0) {
        fake.fail_next -= 1;
        return VK_ERROR_OUT_OF_DEVICE_MEMORY;
    }
    const uint64_t handle = fake.next++;
    fake.live[handle] = info->allocationSize;
    *out = reinterpret_cast<VkDeviceMemory>(handle);
    return VK_SUCCESS;
}
VKAPI_ATTR void VKAPI_CALL fake_free(VkDevice, VkDeviceMemory memory, const VkAllocationCallbacks*) {
    const uint64_t handle = reinterpret_cast<uint64_t>(memory);
    EXPECT_EQ(fake.live.count(handle), 1u) << "freed twice or never allocated";
    fake.live.erase(handle);
    fake.mapped.erase(handle);
}
VKAPI_ATTR VkResult VKAPI_CALL fake_map(VkDevice, VkDeviceMemory memory, VkDeviceSize, VkDeviceSize, VkMemoryMapFlags,
                                        void** out) {
    const uint64_t handle = reinterpret_cast<uint64_t>(memory);
    EXPECT_EQ(fake.mapped.count(handle), 0u) << "a block is mapped once";
    std::vector<char>& bytes = fake.mapped[handle];
    bytes.resize(16);
    *out = bytes.data();
    return VK_SUCCESS;
}

class VkMemoryBlocksTest : public ::testing::Test {
protected:
    void SetUp() override {
        fake = FakeDevice{};
        fn.vkAllocateMemory = &fake_allocate;
        fn.vkFreeMemory = &fake_free;
        fn.vkMapMemory = &fake_map;
        // One heap of 1 GiB (full blocks of 32 MiB), one host-visible coherent type.
        properties.memoryHeapCount = 1;
        properties.memoryHeaps[0].size = VkDeviceSize{1} << 30;
        properties.memoryTypeCount = 1;
        properties.memoryTypes[0].propertyFlags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT |
                                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                  VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    }
    AllocationRequest request(VkDeviceSize size, Tiling tiling = Tiling::linear, bool mapped = false) const {
        AllocationRequest r;
        r.requirements.size = size;
        r.requirements.alignment = 256;
        r.requirements.memoryTypeBits = 1;
        r.tiling = tiling;
        r.mapped = mapped;
        return r;
    }
    grass::vk::Functions fn;
    VkPhysicalDeviceMemoryProperties properties{};
    grass_allocator hooks{};
    grass::HostAllocator host{hooks};
};

constexpr VkDeviceSize kMiB = VkDeviceSize{1} << 20;

TEST_F(VkMemoryBlocksTest, ManyResourcesShareFewBlocksThatGrow) {
    MemoryBlocks blocks(fn, VK_NULL_HANDLE, properties, 1024, 64, &host);
    std::vector<Allocation> all(200);
    const char* call = nullptr;
    for (Allocation& a : all) ASSERT_EQ(blocks.allocate(0, request(200 * 1024), &a, &call), VK_SUCCESS);
    // 40 MB: blocks of 8, 16 and 32 MiB.
    EXPECT_EQ(fake.calls, 3);
    EXPECT_EQ(blocks.device_allocations(), 3u);
    uint64_t allocated[VK_MAX_MEMORY_HEAPS], in_use[VK_MAX_MEMORY_HEAPS];
    blocks.heap_bytes(allocated, in_use);
    EXPECT_EQ(allocated[0], 56 * kMiB);
    EXPECT_EQ(in_use[0], 200u * 200 * 1024);
    for (Allocation& a : all) blocks.free(&a);
    EXPECT_EQ(blocks.device_allocations(), 1u) << "emptied blocks are released but one spare";
    EXPECT_EQ(fake.live.size(), 1u);
    blocks.heap_bytes(allocated, in_use);
    EXPECT_EQ(in_use[0], 0u);
}

TEST_F(VkMemoryBlocksTest, AFailedBlockAllocationLeavesTheBlocksAsTheyWere) {
    MemoryBlocks blocks(fn, VK_NULL_HANDLE, properties, 1, 64, &host);
    Allocation a, b, c;
    const char* call = nullptr;
    ASSERT_EQ(blocks.allocate(0, request(6 * kMiB), &a, &call), VK_SUCCESS); // the first block: 8 MiB
    uint64_t allocated[VK_MAX_MEMORY_HEAPS], in_use[VK_MAX_MEMORY_HEAPS];
    blocks.heap_bytes(allocated, in_use);
    fake.fail_next = 1;
    EXPECT_EQ(blocks.allocate(0, request(6 * kMiB), &b, &call), VK_ERROR_OUT_OF_DEVICE_MEMORY) << "needs a new block";
    EXPECT_STREQ(call, "vkAllocateMemory");
    EXPECT_EQ(b.memory, VK_NULL_HANDLE);
    uint64_t allocated_after[VK_MAX_MEMORY_HEAPS], in_use_after[VK_MAX_MEMORY_HEAPS];
    blocks.heap_bytes(allocated_after, in_use_after);
    EXPECT_EQ(allocated_after[0], allocated[0]);
    EXPECT_EQ(in_use_after[0], in_use[0]);
    EXPECT_EQ(blocks.device_allocations(), 1u);
    // The earlier block still serves what fits in it, and the next block comes as if nothing failed.
    ASSERT_EQ(blocks.allocate(0, request(1 * kMiB), &c, &call), VK_SUCCESS);
    EXPECT_EQ(c.memory, a.memory);
    ASSERT_EQ(blocks.allocate(0, request(6 * kMiB), &b, &call), VK_SUCCESS);
    EXPECT_EQ(fake.live.at(reinterpret_cast<uint64_t>(b.memory)), 16 * kMiB) << "the second block is half a full one";
    blocks.free(&a);
    blocks.free(&b);
    blocks.free(&c);
}

TEST_F(VkMemoryBlocksTest, LargeResourcesGetTheirOwnAllocation) {
    MemoryBlocks blocks(fn, VK_NULL_HANDLE, properties, 1, 64, &host);
    Allocation big, asked, small;
    const char* call = nullptr;
    ASSERT_EQ(blocks.allocate(0, request(17 * kMiB), &big, &call), VK_SUCCESS); // over half of 32 MiB
    EXPECT_TRUE(big.dedicated);
    EXPECT_EQ(fake.live.at(reinterpret_cast<uint64_t>(big.memory)), 17 * kMiB);
    AllocationRequest r = request(4096);
    r.dedicated = true; // the driver prefers it
    ASSERT_EQ(blocks.allocate(0, r, &asked, &call), VK_SUCCESS);
    EXPECT_TRUE(asked.dedicated);
    ASSERT_EQ(blocks.allocate(0, request(4096), &small, &call), VK_SUCCESS);
    EXPECT_FALSE(small.dedicated);
    EXPECT_EQ(blocks.device_allocations(), 3u);
    blocks.free(&big);
    blocks.free(&asked);
    EXPECT_EQ(blocks.device_allocations(), 1u);
    blocks.free(&small);
}

TEST_F(VkMemoryBlocksTest, MappedResourcesPointIntoTheBlocksOneMapping) {
    MemoryBlocks blocks(fn, VK_NULL_HANDLE, properties, 1, 64, &host);
    Allocation a, b;
    const char* call = nullptr;
    ASSERT_EQ(blocks.allocate(0, request(1000, Tiling::linear, true), &a, &call), VK_SUCCESS);
    ASSERT_EQ(blocks.allocate(0, request(1000, Tiling::linear, true), &b, &call), VK_SUCCESS);
    ASSERT_EQ(a.memory, b.memory);
    EXPECT_EQ(b.offset % 256, 0u);
    EXPECT_EQ(static_cast<char*>(b.mapped) - static_cast<char*>(a.mapped),
              static_cast<std::ptrdiff_t>(b.offset - a.offset));
    EXPECT_EQ(fake.mapped.size(), 1u);
    blocks.free(&a);
    blocks.free(&b);
}

TEST_F(VkMemoryBlocksTest, TheHostCallbacksArePassed) {
    fn.host_callbacks.pfnAllocation = [](void*, size_t, size_t, VkSystemAllocationScope) -> void* { return nullptr; };
    fn.has_host_callbacks = true;
    MemoryBlocks blocks(fn, VK_NULL_HANDLE, properties, 1, 64, &host);
    Allocation a;
    const char* call = nullptr;
    ASSERT_EQ(blocks.allocate(0, request(1000), &a, &call), VK_SUCCESS);
    EXPECT_EQ(fake.callbacks_seen, &fn.host_callbacks);
    blocks.free(&a);
}

} // namespace
