// GPU timings per tier kind (grass_get_tier_gpu_ms): GL_TIMESTAMP queries written with
// glQueryCounter around each kind's draws, one per stamp of the core's ring of kTimerSets
// frames (timing/tier_timer_ring.hpp), read once their results are available and never
// waited for. glQueryCounter changes no binding, so the draw state guard is not involved;
// reading a result does depend on GL_QUERY_BUFFER (a bound query buffer turns the result
// pointer into an offset), which collect_timers unbinds and restores around its reads.
#include "gl_backend.hpp"

namespace grass {

void GlBackend::create_timers() {
    GLint bits = 0;
    gl_.GetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    if (bits <= 0) return; // no timer queries: grass_get_tier_gpu_ms says unavailable
    gl_.CreateQueries(GL_TIMESTAMP, static_cast<GLsizei>(kTimerQueries), timer_queries_);
    for (const GLuint query : timer_queries_) label(GL_QUERY, query, "grass tier timer query");
    timer_ring_.set_clock(static_cast<uint32_t>(bits), 1.0); // GL_TIMESTAMP counts nanoseconds
    timers_ = true;
}

void GlBackend::delete_timers() {
    if (timer_queries_[0] != 0) gl_.DeleteQueries(static_cast<GLsizei>(kTimerQueries), timer_queries_);
    for (GLuint& q : timer_queries_) q = 0;
    timers_ = false;
}

const GLuint* GlBackend::timer_stamps() {
    if (!timers_) return nullptr;
    if (!frame_timer_opened_) {
        frame_timer_opened_ = true;
        collect_timers();
        timer_ring_.open_frame();
    }
    const uint32_t first = timer_ring_.next_pass();
    return first == TierTimerRing::kUntimed ? nullptr : &timer_queries_[first];
}

void GlBackend::collect_timers() {
    if (!timers_) return;
    GLint query_buffer = 0;
    gl_.GetIntegerv(GL_QUERY_BUFFER_BINDING, &query_buffer);
    if (query_buffer != 0) gl_.BindBuffer(GL_QUERY_BUFFER, 0);
    timer_ring_.collect([&](uint32_t first, uint32_t count, uint64_t* stamps) {
        for (uint32_t q = count; q-- > 0;) { // the last stamp first: it is the latest
            GLint ready = 0;
            gl_.GetQueryObjectiv(timer_queries_[first + q], GL_QUERY_RESULT_AVAILABLE, &ready);
            if (ready == 0) return false;
        }
        for (uint32_t q = 0; q < count; ++q) {
            GLuint64 stamp = 0;
            gl_.GetQueryObjectui64v(timer_queries_[first + q], GL_QUERY_RESULT, &stamp);
            stamps[q] = stamp;
        }
        return true;
    });
    if (query_buffer != 0) gl_.BindBuffer(GL_QUERY_BUFFER, static_cast<GLuint>(query_buffer));
}

bool GlBackend::tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) {
    collect_timers();
    return timer_ring_.latest(out_ms);
}

} // namespace grass
