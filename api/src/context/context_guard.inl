// Exception barrier of the C API (included by context.hpp).
#pragma once

#include <exception>
#include <new>

namespace grass {

template <class Body>
grass_result guarded(grass_context* ctx, const char* function, Body&& body) noexcept {
    if (ctx && ctx->in_callback()) return ctx->refuse_reentrant(function);
    try {
        return body();
    } catch (const std::bad_alloc&) {
        if (ctx)
            return ctx->fail(GRASS_ERROR_OUT_OF_MEMORY, GRASS_MSG_OUT_OF_MEMORY, "%s: out of host memory", function);
        return GRASS_ERROR_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        if (ctx) return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED, "%s: %s", function, e.what());
        return GRASS_ERROR_BACKEND;
    }
}

} // namespace grass
