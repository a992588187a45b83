// Deferred deletion: resources the GPU may still read (a destroyed patch or field, a
// staging buffer whose copy was recorded, a per-frame buffer that grew) wait here until
// frames_in_flight more frames have begun. The host promises that when frame N begins,
// frame N - frames_in_flight has finished on the GPU.
#pragma once

#include "context/allocator.hpp"
#include "vk_descriptors.hpp"
#include "vk_memory.hpp"

#include <cstdint>

namespace grass::vk {

class DeferredDeletion {
public:
    DeferredDeletion(Memory& memory, DescriptorAllocator& descriptors, HostAllocator* host, uint32_t frames_in_flight)
        : memory_(memory), descriptors_(descriptors), frames_in_flight_(frames_in_flight),
          items_(StlAllocator<Item>(host)) {}
    ~DeferredDeletion() { collect_all(); }
    DeferredDeletion(const DeferredDeletion&) = delete;
    DeferredDeletion& operator=(const DeferredDeletion&) = delete;

    // Reserves room for `count` later retire() calls, so that those cannot fail: every
    // owner promises, when it creates a resource, the retire() its release will make
    // (release cannot report errors). Throws std::bad_alloc.
    void promise(uint32_t count);
    // Gives back promises that will not be used (a resource destroyed at once instead).
    void forgo(uint32_t count) { promised_ -= count < promised_ ? count : promised_; }

    // `last_use_frame`: the newest frame whose command buffers may use the resource. The
    // handle is taken over and *resource cleared; empty resources are ignored. Each call
    // on a non-empty resource uses one promised place and cannot fail.
    void retire(Buffer* buffer, uint64_t last_use_frame);
    void retire(Image* image, uint64_t last_use_frame);
    void retire(DescriptorSet* set, uint64_t last_use_frame);

    // Called when `frame` begins: destroys what frame - frames_in_flight was the last to use.
    void collect(uint64_t frame);
    // The device is idle for grass work (context destruction): destroys everything.
    void collect_all();

private:
    struct Item {
        uint64_t last_use_frame;
        Buffer buffer;
        Image image;
        DescriptorSet set;
    };
    void push(const Item& item);
    void destroy(Item* item);

    Memory& memory_;
    DescriptorAllocator& descriptors_;
    uint32_t frames_in_flight_;
    size_t promised_ = 0;
    Vector<Item> items_; // in retirement order, so frames are non-decreasing
};

} // namespace grass::vk
