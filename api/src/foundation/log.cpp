// The messages of a context: the host's log callback and the last error.
#include "foundation/log.hpp"

#include <cassert>
#include <cstdio>
#include <cstring>

namespace grass {

void Log::emit(grass_log_level level, grass_message_id id, const char* format, va_list args) {
    // Errors and warnings carry a stable id (grass.h); GRASS_MSG_NONE there is a bug in grass.
    // The test fixtures' log functions fail any test that sees one; debug builds stop here.
    assert(id != GRASS_MSG_NONE || level == GRASS_LOG_INFO);
    char message[sizeof(last_error)];
    std::vsnprintf(message, sizeof(message), format, args);
    if (level == GRASS_LOG_ERROR) std::memcpy(last_error, message, sizeof(last_error));
    // Never from inside the log callback: a call it makes is refused, and that refusal is
    // kept as the last error only (no recursion).
    if (log_fn_ && level <= log_level_ && log_callbacks_running == 0) {
        CallbackScope scope(log_callbacks_running);
        log_fn_(log_user_data_, level, id, message);
    }
}

grass_result Log::fail(grass_result result, grass_message_id id, const char* format, ...) {
    va_list args;
    va_start(args, format);
    emit(GRASS_LOG_ERROR, id, format, args);
    va_end(args);
    return result;
}

void Log::warn(grass_message_id id, const char* format, ...) {
    va_list args;
    va_start(args, format);
    emit(GRASS_LOG_WARNING, id, format, args);
    va_end(args);
}

void Log::info(grass_message_id id, const char* format, ...) {
    va_list args;
    va_start(args, format);
    emit(GRASS_LOG_INFO, id, format, args);
    va_end(args);
}

} // namespace grass
