#include "vk_memory.hpp"

#include "vk_labels.hpp"

namespace grass::vk {

namespace {

struct TypeRule {
    VkMemoryPropertyFlags required;
    VkMemoryPropertyFlags preferred[2]; // most important first
    VkMemoryPropertyFlags avoided;      // a tie-break: leaves scarce memory to other uses
};

TypeRule rule_for(MemoryUse use) {
    switch (use) {
    case MemoryUse::device_local:
        // Plain VRAM before the host-visible window onto it (resizable BAR).
        return {0, {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0}, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT};
    case MemoryUse::staging:
        // System memory, leaving the BAR window to the per-frame buffers.
        return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT,
                {VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0},
                VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT};
    case MemoryUse::streaming:
        // Coherent first (no flushes), then device-local (resizable BAR, unified memory).
        return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT,
                {VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT},
                0};
    }
    return {0, {0, 0}, 0};
}

// Higher is better; -1: the type cannot hold this resource.
int score(const VkMemoryType& type, uint32_t index, uint32_t type_bits, const TypeRule& rule) {
    if (!(type_bits & (1u << index))) return -1;
    if ((type.propertyFlags & rule.required) != rule.required) return -1;
    // Lazily allocated and protected memory cannot back these resources.
    if (type.propertyFlags & (VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT | VK_MEMORY_PROPERTY_PROTECTED_BIT)) return -1;
    int s = 0;
    if (rule.preferred[0] && (type.propertyFlags & rule.preferred[0]) == rule.preferred[0]) s += 4;
    if (rule.preferred[1] && (type.propertyFlags & rule.preferred[1]) == rule.preferred[1]) s += 2;
    if (!(type.propertyFlags & rule.avoided)) s += 1;
    return s;
}

// The requirements of `buffer` or `image` (one of them), and whether the driver requires or
// prefers it on a dedicated allocation (Vulkan 1.1; without the 2 functions, no).
void requirements_of(const Functions& fn, VkDevice device, VkBuffer buffer, VkImage image, AllocationRequest* out) {
    out->buffer = buffer;
    out->image = image;
    const bool two =
        buffer ? fn.vkGetBufferMemoryRequirements2 != nullptr : fn.vkGetImageMemoryRequirements2 != nullptr;
    if (!two) {
        if (buffer) fn.vkGetBufferMemoryRequirements(device, buffer, &out->requirements);
        if (image) fn.vkGetImageMemoryRequirements(device, image, &out->requirements);
        return;
    }
    VkMemoryDedicatedRequirements dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_REQUIREMENTS};
    VkMemoryRequirements2 requirements{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
    requirements.pNext = &dedicated;
    if (buffer) {
        VkBufferMemoryRequirementsInfo2 info{VK_STRUCTURE_TYPE_BUFFER_MEMORY_REQUIREMENTS_INFO_2};
        info.buffer = buffer;
        fn.vkGetBufferMemoryRequirements2(device, &info, &requirements);
    } else {
        VkImageMemoryRequirementsInfo2 info{VK_STRUCTURE_TYPE_IMAGE_MEMORY_REQUIREMENTS_INFO_2};
        info.image = image;
        fn.vkGetImageMemoryRequirements2(device, &info, &requirements);
    }
    out->requirements = requirements.memoryRequirements;
    out->dedicated = dedicated.requiresDedicatedAllocation || dedicated.prefersDedicatedAllocation;
}

} // namespace

bool Memory::allocate(const AllocationRequest& request, MemoryUse use, Allocation* out,
                      VkMemoryPropertyFlags* out_flags, VkFailure* failure) {
    const TypeRule rule = rule_for(use);
    bool tried[VK_MAX_MEMORY_TYPES] = {};
    VkResult last = VK_ERROR_OUT_OF_DEVICE_MEMORY;
    const char* call = "vkAllocateMemory";
    for (;;) {
        int best = -1, best_score = -1;
        for (uint32_t i = 0; i < properties_.memoryTypeCount; ++i) {
            if (tried[i]) continue;
            const int s = score(properties_.memoryTypes[i], i, request.requirements.memoryTypeBits, rule);
            if (s > best_score) {
                best = static_cast<int>(i);
                best_score = s;
            }
        }
        if (best < 0) break;
        tried[best] = true;
        last = blocks_.allocate(static_cast<uint32_t>(best), request, out, &call);
        if (last == VK_SUCCESS) {
            *out_flags = properties_.memoryTypes[best].propertyFlags;
            return true;
        }
        // Another type may live on a heap with room; any other error is final.
        if (last != VK_ERROR_OUT_OF_DEVICE_MEMORY) break;
    }
    failure->call = call;
    failure->result = last;
    return false;
}

bool Memory::create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, Buffer* out,
                           VkFailure* failure) {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    if (!vk_ok(fn_.vkCreateBuffer(device_, &info, fn_.callbacks(), &b.buffer), "vkCreateBuffer", failure)) {
        return false;
    }
    name_object(fn_, device_, VK_OBJECT_TYPE_BUFFER, b.buffer,
                use == MemoryUse::device_local ? "grass buffer"
                : use == MemoryUse::staging    ? "grass staging buffer"
                                               : "grass streaming buffer");
    AllocationRequest request;
    request.tiling = Tiling::linear;
    request.mapped = use != MemoryUse::device_local;
    VkMemoryPropertyFlags flags = 0;
    bool ok = true;
    try {
        requirements_of(fn_, device_, b.buffer, VK_NULL_HANDLE, &request);
        ok = allocate(request, use, &b.memory, &flags, failure);
    } catch (...) {
        fn_.vkDestroyBuffer(device_, b.buffer, fn_.callbacks());
        throw;
    }
    if (!ok) {
        fn_.vkDestroyBuffer(device_, b.buffer, fn_.callbacks());
        return false;
    }
    b.allocated = request.requirements.size;
    b.mapped = b.memory.mapped;
    b.coherent = (flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
    if (!vk_ok(fn_.vkBindBufferMemory(device_, b.buffer, b.memory.memory, b.memory.offset), "vkBindBufferMemory",
               failure)) {
        destroy_buffer(&b);
        return false;
    }
    *out = b;
    return true;
}

void Memory::destroy_buffer(Buffer* b) {
    if (b->buffer) fn_.vkDestroyBuffer(device_, b->buffer, fn_.callbacks());
    blocks_.free(&b->memory);
    *b = Buffer{};
}

bool Memory::create_image(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage, Image* out,
                          VkFailure* failure) {
    return make_image(width, height, 1, 1, VK_IMAGE_VIEW_TYPE_2D, format, usage, out, failure);
}

bool Memory::create_array_image(uint32_t width, uint32_t height, uint32_t layers, uint32_t levels, VkFormat format,
                                VkImageUsageFlags usage, Image* out, VkFailure* failure) {
    return make_image(width, height, layers, levels, VK_IMAGE_VIEW_TYPE_2D_ARRAY, format, usage, out, failure);
}

bool Memory::make_image(uint32_t width, uint32_t height, uint32_t layers, uint32_t levels, VkImageViewType view_type,
                        VkFormat format, VkImageUsageFlags usage, Image* out, VkFailure* failure) {
    Image im;
    im.width = width;
    im.height = height;
    im.layers = layers;
    im.levels = levels;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = levels;
    info.arrayLayers = layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (!vk_ok(fn_.vkCreateImage(device_, &info, fn_.callbacks(), &im.image), "vkCreateImage", failure)) {
        return false;
    }
    const bool array = view_type == VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    name_object(fn_, device_, VK_OBJECT_TYPE_IMAGE, im.image, array ? "grass array image" : "grass image");
    AllocationRequest request;
    request.tiling = Tiling::optimal;
    VkMemoryPropertyFlags flags = 0;
    bool ok = true;
    try {
        requirements_of(fn_, device_, VK_NULL_HANDLE, im.image, &request);
        ok = allocate(request, MemoryUse::device_local, &im.memory, &flags, failure);
    } catch (...) {
        fn_.vkDestroyImage(device_, im.image, fn_.callbacks());
        throw;
    }
    if (!ok) {
        fn_.vkDestroyImage(device_, im.image, fn_.callbacks());
        return false;
    }
    im.allocated = request.requirements.size;
    ok = vk_ok(fn_.vkBindImageMemory(device_, im.image, im.memory.memory, im.memory.offset), "vkBindImageMemory",
               failure);
    if (ok) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = im.image;
        view.viewType = view_type;
        view.format = format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, layers};
        ok = vk_ok(fn_.vkCreateImageView(device_, &view, fn_.callbacks(), &im.view), "vkCreateImageView", failure);
        if (ok) {
            name_object(fn_, device_, VK_OBJECT_TYPE_IMAGE_VIEW, im.view, array ? "grass array view" : "grass view");
        }
    }
    if (!ok) {
        destroy_image(&im);
        return false;
    }
    *out = im;
    return true;
}

void Memory::destroy_image(Image* im) {
    if (im->view) fn_.vkDestroyImageView(device_, im->view, fn_.callbacks());
    if (im->image) fn_.vkDestroyImage(device_, im->image, fn_.callbacks());
    blocks_.free(&im->memory);
    *im = Image{};
}

bool Memory::flush(const Buffer& b, VkDeviceSize offset, VkDeviceSize size, VkFailure* failure) {
    if (b.coherent || size == 0) return true;
    // The range must start and end on nonCoherentAtomSize: the buffer's memory starts on one
    // and owns whole atoms (MemoryBlocks::allocate), so rounding out stays inside it.
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
    range.memory = b.memory.memory;
    range.offset = b.memory.offset + offset / atom_ * atom_;
    const VkDeviceSize end = b.memory.offset + (offset + size + atom_ - 1) / atom_ * atom_;
    range.size = end - range.offset;
    return vk_ok(fn_.vkFlushMappedMemoryRanges(device_, 1, &range), "vkFlushMappedMemoryRanges", failure);
}

} // namespace grass::vk
