// GPU timings per tier kind (grass_get_tier_gpu_ms): GL_TIMESTAMP queries written with
// glQueryCounter around each kind's draws, in a ring of kTimerSets frames, read once their
// results are available and never waited for. glQueryCounter changes no binding, so the
// draw state guard is not involved; reading a result does depend on GL_QUERY_BUFFER (a
// bound query buffer turns the result pointer into an offset), which collect_timers
// unbinds and restores around its reads.
#include "gl_backend.hpp"

namespace grass {

void GlBackend::create_timers() {
    timer_bits_ = 0;
    gl_.GetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &timer_bits_);
    if (timer_bits_ <= 0) return; // no timer queries: grass_get_tier_gpu_ms says unavailable
    for (TimerSet& set : timer_sets_) {
        gl_.CreateQueries(GL_TIMESTAMP, static_cast<GLsizei>(kTimedRenders * kStampsPerRender), set.queries);
    }
    timers_ = true;
}

void GlBackend::delete_timers() {
    for (TimerSet& set : timer_sets_) {
        if (set.queries[0] != 0) gl_.DeleteQueries(static_cast<GLsizei>(kTimedRenders * kStampsPerRender), set.queries);
        set = TimerSet{};
    }
    timers_ = false;
}

const GLuint* GlBackend::timer_stamps() {
    if (!timers_) return nullptr;
    if (!frame_timer_chosen_) {
        frame_timer_chosen_ = true;
        frame_timer_ = -1;
        collect_timers();
        TimerSet& next = timer_sets_[next_timer_];
        if (next.pending) return nullptr; // kTimerSets frames unfinished: skip this one rather than wait
        next.renders = 0;
        next.pending = true;
        next.closed = false;
        next.complete = true;
        frame_timer_ = static_cast<int32_t>(next_timer_);
        next_timer_ = (next_timer_ + 1) % kTimerSets;
    }
    if (frame_timer_ < 0) return nullptr;
    TimerSet& set = timer_sets_[frame_timer_];
    if (set.renders == kTimedRenders) {
        set.complete = false;
        return nullptr;
    }
    return &set.queries[kStampsPerRender * set.renders++];
}

void GlBackend::collect_timers() {
    if (!timers_) return;
    GLint query_buffer = 0;
    gl_.GetIntegerv(GL_QUERY_BUFFER_BINDING, &query_buffer);
    if (query_buffer != 0) gl_.BindBuffer(GL_QUERY_BUFFER, 0);
    const GLuint64 mask = timer_bits_ >= 64 ? ~GLuint64(0) : (GLuint64(1) << timer_bits_) - 1;
    // next_timer_ is the oldest set; sets finish in order.
    for (uint32_t i = 0; i < kTimerSets; ++i) {
        TimerSet& set = timer_sets_[(next_timer_ + i) % kTimerSets];
        if (!set.pending) continue;
        if (!set.closed) break; // its frame is still drawing
        const GLsizei count = static_cast<GLsizei>(kStampsPerRender * set.renders);
        bool available = true;
        for (GLsizei q = count; q-- > 0 && available;) { // the last stamp first: it is the latest
            GLint ready = 0;
            gl_.GetQueryObjectiv(set.queries[q], GL_QUERY_RESULT_AVAILABLE, &ready);
            available = ready != 0;
        }
        if (!available) break;
        double ms[GRASS_TIER_KIND_COUNT] = {};
        for (uint32_t r = 0; r < set.renders; ++r) {
            GLuint64 stamps[kStampsPerRender] = {};
            for (uint32_t s = 0; s < kStampsPerRender; ++s) {
                gl_.GetQueryObjectui64v(set.queries[kStampsPerRender * r + s], GL_QUERY_RESULT, &stamps[s]);
            }
            // Stamps 0-1 bracket the blades, 1-2 the volumes, 2-3 the images (gl_draw.cpp).
            static const grass_tier_kind kinds[kStampsPerRender - 1] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME,
                                                                        GRASS_TIER_IMAGE};
            for (uint32_t k = 0; k + 1 < kStampsPerRender; ++k) {
                const GLuint64 ns = (stamps[k + 1] - stamps[k]) & mask;
                ms[kinds[k]] += static_cast<double>(ns) * 1e-6;
            }
        }
        set.pending = false;
        if (set.complete && set.renders > 0) {
            for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) timings_ms_[k] = ms[k];
            timings_valid_ = true;
        }
    }
    if (query_buffer != 0) gl_.BindBuffer(GL_QUERY_BUFFER, static_cast<GLuint>(query_buffer));
}

bool GlBackend::tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) {
    collect_timers();
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) out_ms[k] = timings_valid_ ? timings_ms_[k] : 0.0;
    return timings_valid_;
}

} // namespace grass
