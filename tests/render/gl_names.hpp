// GL object names in use among the first 4096 of each kind (glIs* in the host's context):
// what a GL test counts to see that grass deleted everything it made.
#pragma once

#include "headless_host.hpp"

namespace grass_test {

inline long gl_live_names(const grass_host::Host& host) {
    using IsFn = unsigned char (*)(unsigned);
    long n = 0;
    for (const char* name : {"glIsBuffer", "glIsTexture", "glIsVertexArray", "glIsQuery", "glIsProgram", "glIsShader",
                             "glIsFramebuffer", "glIsSampler"}) {
        const auto is = reinterpret_cast<IsFn>(host.gl_proc_address(name));
        if (!is) continue;
        for (unsigned id = 1; id <= 4096; ++id) n += is(id) ? 1 : 0;
    }
    return n;
}

} // namespace grass_test
