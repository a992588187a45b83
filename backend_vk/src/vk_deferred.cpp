#include "vk_deferred.hpp"

#include <cassert>
#include <new>

namespace grass::vk {

bool DeferredDeletion::reserve_place(VkFailure* failure) {
    const size_t needed = items_.size() + places_ + 1;
    if (items_.capacity() >= needed) return true;
    try {
        items_.reserve(needed > 2 * items_.capacity() ? needed : 2 * items_.capacity());
    } catch (const std::bad_alloc&) {
        failure->call = "reserving a place in the deferred deletion queue";
        failure->result = VK_ERROR_OUT_OF_HOST_MEMORY;
        return false;
    }
    return true;
}

bool DeferredDeletion::placed(bool created) {
    if (created) places_ += 1;
    return created;
}

bool DeferredDeletion::create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, Buffer* out,
                                     VkFailure* failure) {
    return reserve_place(failure) && placed(memory_.create_buffer(size, usage, use, out, failure));
}

bool DeferredDeletion::create_image(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                                    Image* out, VkFailure* failure) {
    return reserve_place(failure) && placed(memory_.create_image(width, height, format, usage, out, failure));
}

bool DeferredDeletion::create_array_image(uint32_t width, uint32_t height, uint32_t layers, uint32_t levels,
                                          VkFormat format, VkImageUsageFlags usage, Image* out, VkFailure* failure) {
    return reserve_place(failure) &&
           placed(memory_.create_array_image(width, height, layers, levels, format, usage, out, failure));
}

bool DeferredDeletion::allocate_set(VkDescriptorSetLayout layout, DescriptorSet* out, VkFailure* failure) {
    return reserve_place(failure) && placed(descriptors_.allocate(layout, out, failure));
}

void DeferredDeletion::push(const Item& item) {
    assert(places_ > 0 && items_.size() < items_.capacity()); // a handle made by a creator above
    items_.push_back(item);                                   // within the capacity its creator reserved: cannot throw
    places_ -= 1;
}

void DeferredDeletion::retire(Buffer* buffer, uint64_t last_use_frame) {
    if (!buffer->buffer) return;
    push(Item{last_use_frame, *buffer, Image{}, DescriptorSet{}});
    *buffer = Buffer{};
}

void DeferredDeletion::retire(Image* image, uint64_t last_use_frame) {
    if (!image->image) return;
    push(Item{last_use_frame, Buffer{}, *image, DescriptorSet{}});
    *image = Image{};
}

void DeferredDeletion::retire(DescriptorSet* set, uint64_t last_use_frame) {
    if (!set->set) return;
    push(Item{last_use_frame, Buffer{}, Image{}, *set});
    *set = DescriptorSet{};
}

void DeferredDeletion::destroy_now(Buffer* buffer) {
    if (!buffer->buffer) return;
    memory_.destroy_buffer(buffer);
    places_ -= 1;
}

void DeferredDeletion::destroy_now(Image* image) {
    if (!image->image) return;
    memory_.destroy_image(image);
    places_ -= 1;
}

void DeferredDeletion::destroy_now(DescriptorSet* set) {
    if (!set->set) return;
    descriptors_.free(set);
    places_ -= 1;
}

void DeferredDeletion::destroy(Item* item) {
    memory_.destroy_buffer(&item->buffer);
    memory_.destroy_image(&item->image);
    descriptors_.free(&item->set);
}

void DeferredDeletion::collect(uint64_t completed_frame) {
    size_t done = 0;
    while (done < items_.size() && items_[done].last_use_frame <= completed_frame) {
        destroy(&items_[done]);
        ++done;
    }
    items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(done));
}

void DeferredDeletion::collect_all() {
    for (Item& item : items_) destroy(&item);
    items_.clear();
}

} // namespace grass::vk
