#include "foundation/owner_tags.hpp"

#include <mutex>

namespace grass {

namespace {

struct Registry {
    std::mutex mutex;
    uint16_t last = 0;              // the tag handed out last
    uint32_t live_count = 0;        // tags live now
    uint64_t live[65536 / 64] = {}; // bit t: tag t is live
};

Registry& registry() {
    static Registry r; // made on first use: no order of static initialisation to get wrong
    return r;
}

bool is_live(const Registry& r, uint16_t tag) { return (r.live[tag / 64] >> (tag % 64)) & 1u; }

} // namespace

uint16_t acquire_owner_tag() noexcept {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    if (r.live_count >= 65535u) return 0;
    uint16_t tag = r.last;
    do {
        tag = static_cast<uint16_t>(tag + 1);
    } while (tag == 0 || is_live(r, tag)); // ends: fewer than 65,535 tags are live
    r.live[tag / 64] |= uint64_t{1} << (tag % 64);
    r.live_count += 1;
    r.last = tag;
    return tag;
}

void release_owner_tag(uint16_t tag) noexcept {
    if (tag == 0) return;
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    if (!is_live(r, tag)) return;
    r.live[tag / 64] &= ~(uint64_t{1} << (tag % 64));
    r.live_count -= 1;
}

} // namespace grass
