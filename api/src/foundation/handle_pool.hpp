// Objects addressed by id handles with a generation (after Box2D's id pools): a slot
// array whose freed slots are reused with a bumped generation, so stale ids are caught. A
// slot whose 16-bit generation would wrap is retired instead (never reused), so no stale
// id of the pool is ever accepted again (grass.h "Ids").
#pragma once

#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

enum class HandleCheck { ok, null_id, foreign, stale };

template <class T>
class HandlePool {
public:
    explicit HandlePool(HostAllocator* host)
        : host_(host), slots_(StlAllocator<Slot>(host)), free_(StlAllocator<uint32_t>(host)) {}
    ~HandlePool() {
        for (Slot& s : slots_) host_->destroy(s.object);
    }
    HandlePool(const HandlePool&) = delete;
    HandlePool& operator=(const HandlePool&) = delete;

    // Takes ownership of `object` (made with host->create) and returns its slot. When the
    // pool cannot grow (std::bad_alloc) it destroys `object` before the exception leaves.
    uint32_t insert(T* object) {
        if (!free_.empty()) {
            const uint32_t slot = free_.back();
            free_.pop_back();
            slots_[slot].object = object;
            return slot;
        }
        try {
            // Room in free_ for every slot, so that erase() never allocates (and never fails
            // after destroying its object).
            free_.reserve(slots_.size() + 1);
            slots_.push_back(Slot{object, 1});
        } catch (...) {
            host_->destroy(object);
            throw;
        }
        return static_cast<uint32_t>(slots_.size() - 1);
    }
    void erase(uint32_t slot) {
        host_->destroy(slots_[slot].object);
        slots_[slot].object = nullptr;
        if (slots_[slot].generation == kLastGeneration) return; // retired: 16 bytes kept for good
        slots_[slot].generation = static_cast<uint16_t>(slots_[slot].generation + 1);
        free_.push_back(slot);
    }
    // The generation of a slot's last object: the slot is retired when it is erased.
    static constexpr uint16_t kLastGeneration = 0xffff;
    uint16_t generation(uint32_t slot) const { return slots_[slot].generation; }

    // index is slot + 1 (0 is the null id).
    HandleCheck check(uint32_t index, uint16_t generation, uint16_t owner, uint16_t expected_owner) const {
        if (index == 0) return HandleCheck::null_id;
        if (owner != expected_owner) return HandleCheck::foreign;
        if (index > slots_.size()) return HandleCheck::stale;
        const Slot& s = slots_[index - 1];
        if (!s.object || s.generation != generation) return HandleCheck::stale;
        return HandleCheck::ok;
    }
    T* get(uint32_t slot) const { return slot < slots_.size() ? slots_[slot].object : nullptr; }
    uint32_t capacity() const { return static_cast<uint32_t>(slots_.size()); }

private:
    struct Slot {
        T* object;
        uint16_t generation;
    };
    HostAllocator* host_;
    Vector<Slot> slots_;
    Vector<uint32_t> free_;
};

} // namespace grass
