#include "vk_deferred.hpp"

namespace grass::vk {

void DeferredDeletion::promise(uint32_t count) {
    items_.reserve(items_.size() + promised_ + count);
    promised_ += count;
}

void DeferredDeletion::push(const Item& item) {
    items_.push_back(item); // within the capacity promise() reserved: cannot throw
    forgo(1);
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

void DeferredDeletion::destroy(Item* item) {
    memory_.destroy_buffer(&item->buffer);
    memory_.destroy_image(&item->image);
    descriptors_.free(&item->set);
}

void DeferredDeletion::collect(uint64_t frame) {
    size_t done = 0;
    while (done < items_.size() && items_[done].last_use_frame + frames_in_flight_ <= frame) {
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
