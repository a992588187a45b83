// Host memory of a context: every allocation goes through the host's hooks (or malloc)
// and is counted, so a host can see what grass holds (grass_get_memory_stats).
#pragma once

#include <grass/grass.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

namespace grass {

class HostAllocator {
public:
    explicit HostAllocator(const grass_allocator& hooks) : hooks_(hooks) {}

    // Alignment up to kMaxAlignment. Each block carries a small header with its size, so
    // deallocate needs no size and the byte count stays exact.
    static constexpr size_t kMaxAlignment = 64;
    void* allocate(size_t size, size_t alignment = alignof(std::max_align_t));
    void deallocate(void* ptr) noexcept;

    uint64_t bytes() const { return bytes_; }
    uint64_t bytes_peak() const { return bytes_peak_; } // the highest bytes() since construction
    uint64_t allocations() const { return allocations_; }
    // The host's alloc_fn or free_fn is running (its context refuses calls meanwhile).
    bool hook_running() const { return hooks_running_ > 0; }

    template <class T, class... Args>
    T* create(Args&&... args) {
        void* memory = allocate(sizeof(T), alignof(T));
        return new (memory) T(std::forward<Args>(args)...);
    }
    template <class T>
    void destroy(T* object) noexcept {
        if (!object) return;
        object->~T();
        deallocate(const_cast<void*>(static_cast<const volatile void*>(object)));
    }

private:
    grass_allocator hooks_;
    uint64_t bytes_ = 0;
    uint64_t bytes_peak_ = 0;
    uint64_t allocations_ = 0;
    uint32_t hooks_running_ = 0;
};

// Standard-library allocator that routes to a context's HostAllocator. Throws
// std::bad_alloc on failure; the C API boundary turns that into GRASS_ERROR_OUT_OF_MEMORY.
template <class T>
class StlAllocator {
public:
    using value_type = T;
    explicit StlAllocator(HostAllocator* host) noexcept : host_(host) {}
    template <class U>
    StlAllocator(const StlAllocator<U>& other) noexcept : host_(other.host()) {}

    T* allocate(size_t n) { return static_cast<T*>(host_->allocate(n * sizeof(T), alignof(T))); }
    void deallocate(T* p, size_t) noexcept { host_->deallocate(p); }

    HostAllocator* host() const noexcept { return host_; }
    template <class U>
    bool operator==(const StlAllocator<U>& o) const noexcept {
        return host_ == o.host();
    }
    template <class U>
    bool operator!=(const StlAllocator<U>& o) const noexcept {
        return host_ != o.host();
    }

private:
    HostAllocator* host_;
};

template <class T>
using Vector = std::vector<T, StlAllocator<T>>;

} // namespace grass
