// The messages of a context (grass.h "Logging"): every error and warning carries a stable
// id and goes to the host's log callback when its level passes; an error is also kept as the
// last error (grass_get_last_error). Every concept reports through a Log; the context is one
// (context.hpp), so a check takes `Log*` and its caller passes the context.
#pragma once

#include <grass/grass.h>

#include <cstdarg>
#include <cstdint>

namespace grass {

// Counts a host callback in flight for its lifetime: `CallbackScope scope(ctx->lod_callbacks_running);`.
class CallbackScope {
public:
    explicit CallbackScope(uint32_t& counter) noexcept : counter_(counter) { ++counter_; }
    ~CallbackScope() { --counter_; }
    CallbackScope(const CallbackScope&) = delete;
    CallbackScope& operator=(const CallbackScope&) = delete;

private:
    uint32_t& counter_;
};

class Log {
public:
    // The host's log callback, its user data and level, from the context's desc.
    explicit Log(const grass_context_desc& desc) noexcept
        : log_fn_(desc.log_fn), log_user_data_(desc.log_user_data), log_level_(desc.log_level) {}

    // Logs `message` (printf format) at error level with `id`, keeps it as the last error,
    // and returns `result`: `return log->fail(GRASS_ERROR_..., GRASS_MSG_..., "...", ...);`
    grass_result fail(grass_result result, grass_message_id id, const char* format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 4, 5)))
#endif
        ;
    void warn(grass_message_id id, const char* format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 3, 4)))
#endif
        ;
    void info(grass_message_id id, const char* format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 3, 4)))
#endif
        ;

    char last_error[512] = {0};
    // The log callback is running: its calls on the context are refused, and what it makes
    // the context log is kept as the last error only (no recursion).
    uint32_t log_callbacks_running = 0;

private:
    void emit(grass_log_level level, grass_message_id id, const char* format, va_list args);

    grass_log_fn log_fn_;
    void* log_user_data_;
    grass_log_level log_level_;
};

} // namespace grass
