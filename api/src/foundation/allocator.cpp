#include "foundation/allocator.hpp"

#include <cstdlib>

namespace grass {

namespace {
// The header before each block: the block's size and the offset back to the raw pointer.
struct BlockHeader {
    uint64_t size;
    uint64_t offset;
};
constexpr size_t kHeaderSpace = HostAllocator::kMaxAlignment; // keeps the user pointer 64-aligned
static_assert(sizeof(BlockHeader) <= kHeaderSpace, "header fits");
} // namespace

void* HostAllocator::allocate(size_t size, size_t alignment) {
    (void)alignment; // every block is kMaxAlignment-aligned
    const size_t total = size + kHeaderSpace;
    void* raw = nullptr;
    if (hooks_.alloc_fn) {
        ++hooks_running_;
        raw = hooks_.alloc_fn(hooks_.user_data, total, kMaxAlignment);
        --hooks_running_;
    } else {
        raw = std::aligned_alloc(kMaxAlignment, (total + kMaxAlignment - 1) / kMaxAlignment * kMaxAlignment);
    }
    if (!raw) throw std::bad_alloc();
    auto* user = static_cast<unsigned char*>(raw) + kHeaderSpace;
    auto* header = reinterpret_cast<BlockHeader*>(user - sizeof(BlockHeader));
    header->size = size;
    header->offset = kHeaderSpace;
    bytes_ += size;
    if (bytes_ > bytes_peak_) bytes_peak_ = bytes_;
    allocations_ += 1;
    return user;
}

void HostAllocator::deallocate(void* ptr) noexcept {
    if (!ptr) return;
    auto* user = static_cast<unsigned char*>(ptr);
    const auto* header = reinterpret_cast<const BlockHeader*>(user - sizeof(BlockHeader));
    bytes_ -= header->size;
    allocations_ -= 1;
    void* raw = user - header->offset;
    if (hooks_.free_fn) {
        ++hooks_running_;
        hooks_.free_fn(hooks_.user_data, raw);
        --hooks_running_;
    } else {
        std::free(raw);
    }
}

} // namespace grass
