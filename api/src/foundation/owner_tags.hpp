// Owner tags of live contexts: the 16 bits of an id that tell one context's ids from
// another's (grass.h "Ids"). Process-wide and thread-safe: contexts may be made and
// destroyed on any thread.
#pragma once

#include <cstdint>

namespace grass {

// A tag no live context holds: the next value of a process-wide counter (1..65535, 0 is
// never a tag), skipping the tags still live. So a released tag comes back only after the
// counter went round all 65,535 values, i.e. after 65,534 more acquisitions. Returns 0 when
// all 65,535 tags are live.
uint16_t acquire_owner_tag() noexcept;
// Makes `tag` (from acquire_owner_tag, not 0) free again; its context is gone.
void release_owner_tag(uint16_t tag) noexcept;

} // namespace grass
