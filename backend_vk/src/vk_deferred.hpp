// Deferred deletion: resources the GPU may still read (a destroyed patch or field, a
// staging buffer whose copy was recorded, a per-frame buffer that grew) wait here until the
// host reports the last frame that may use them finished (grass_frame_desc's
// completed_frame_index; grass_begin_frame's host promises that when frame N begins, frame
// N - frames_in_flight has finished on the GPU). Frames are the host's frame indices.
//
// Retiring happens where errors cannot be reported (a release), so it must not allocate.
// Every resource that may be retired is therefore made here: each creator reserves the
// handle's place in the queue before making it, and each such handle ends in exactly one
// of retire() (which uses its place) or destroy_now() (which gives it back). Nobody counts
// places by hand.
#pragma once

#include "foundation/allocator.hpp"
#include "vk_descriptors.hpp"
#include "vk_memory.hpp"

#include <cstdint>

namespace grass::vk {

class DeferredDeletion {
public:
    DeferredDeletion(Memory& memory, DescriptorAllocator& descriptors, HostAllocator* host)
        : memory_(memory), descriptors_(descriptors), items_(StlAllocator<Item>(host)) {}
    ~DeferredDeletion() { collect_all(); }
    DeferredDeletion(const DeferredDeletion&) = delete;
    DeferredDeletion& operator=(const DeferredDeletion&) = delete;

    // Memory::create_buffer, create_image, create_array_image and
    // DescriptorAllocator::allocate, with the handle's place reserved first. No place
    // (host memory exhausted) fails like the allocation itself: VK_ERROR_OUT_OF_HOST_MEMORY,
    // nothing made. They never throw.
    bool create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, Buffer* out, VkFailure* failure);
    bool create_image(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage, Image* out,
                      VkFailure* failure);
    bool create_array_image(uint32_t width, uint32_t height, uint32_t layers, uint32_t levels, VkFormat format,
                            VkImageUsageFlags usage, Image* out, VkFailure* failure);
    bool allocate_set(VkDescriptorSetLayout layout, DescriptorSet* out, VkFailure* failure);

    // `last_use_frame`: the newest frame whose command buffers may use the resource. The
    // handle (made by a creator above) is taken over and *resource cleared; empty resources
    // are ignored. Uses the handle's place: cannot fail.
    void retire(Buffer* buffer, uint64_t last_use_frame);
    void retire(Image* image, uint64_t last_use_frame);
    void retire(DescriptorSet* set, uint64_t last_use_frame);

    // A handle made by a creator above that no GPU work can use (never recorded, or the
    // device is idle): destroyed at once, its place given back. Empty resources are ignored.
    void destroy_now(Buffer* buffer);
    void destroy_now(Image* image);
    void destroy_now(DescriptorSet* set);

    // A frame begins and the host reports every frame up to `completed_frame` finished:
    // destroys what those frames were the last to use.
    void collect(uint64_t completed_frame);
    // The device is idle for grass work (context destruction): destroys everything.
    void collect_all();

private:
    struct Item {
        uint64_t last_use_frame;
        Buffer buffer;
        Image image;
        DescriptorSet set;
    };
    // Room in items_ for the live handles' places and one more; false when it cannot be had.
    bool reserve_place(VkFailure* failure);
    // Counts a new handle's place (after reserve_place and a successful creation).
    bool placed(bool created);
    void push(const Item& item);
    void destroy(Item* item);

    Memory& memory_;
    DescriptorAllocator& descriptors_;
    size_t places_ = 0;  // live handles made by the creators: items_'s capacity holds them all
    Vector<Item> items_; // in retirement order, so frames are non-decreasing
};

} // namespace grass::vk
