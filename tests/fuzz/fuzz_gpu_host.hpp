// fuzz_gpu_sequence's devices: a GL context (EGL surfaceless on llvmpipe) and a Vulkan
// device (lavapipe, validation layers on) for each of 1 and 4 samples, each made once per
// process by the sample's headless host with a small offscreen target (32 x 32; the 4-sample
// ones with the host's ground), on which the inputs' grass contexts draw.
#pragma once

#include "headless_host.hpp"

#include <EGL/egl.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace grass_fuzz {

// The host of `backend` with `samples` (1 or 4), made at the first call and current from
// this call on (two GL hosts are two GL contexts on one thread: the host makes its own
// current only when it is made, so the harness switches as an engine with two contexts
// does); nullptr when the device cannot be had here (said once on stderr). Never destroyed:
// at exit the Vulkan validation layer may be gone before a static host would be (it crashed
// in vkDestroyDevice).
inline grass_host::Host* gpu_host(grass_backend backend, uint32_t samples) {
    struct Made {
        grass_host::Host* host = nullptr;
        bool tried = false;
        EGLDisplay display = EGL_NO_DISPLAY; // GL: the host's EGL context (none: OSMesa)
        EGLContext context = EGL_NO_CONTEXT;
    };
    static Made made[2][2];
    const int b = backend == GRASS_BACKEND_GL ? 0 : 1, s = samples == 4 ? 1 : 0;
    Made& m = made[b][s];
    if (!m.tried) {
        m.tried = true;
        grass_host::TargetDesc t;
        t.width = t.height = 32;
        t.samples = samples;
        t.ground = s == 1; // with and without the host's ground
        std::string error;
        m.host = grass_host::Host::create(backend, t, &error).release();
        if (!m.host) std::fprintf(stderr, "fuzz_gpu_sequence: no %s device: %s\n", b ? "Vulkan" : "GL", error.c_str());
        if (m.host && b == 0) {
            m.display = eglGetCurrentDisplay();
            m.context = eglGetCurrentContext();
            if (m.context == EGL_NO_CONTEXT && (made[0][0].host && made[0][1].host)) {
                std::fprintf(stderr, "fuzz_gpu_sequence: two GL hosts without EGL cannot take turns\n");
                std::abort();
            }
        }
    }
    if (m.context != EGL_NO_CONTEXT && eglGetCurrentContext() != m.context &&
        !eglMakeCurrent(m.display, EGL_NO_SURFACE, EGL_NO_SURFACE, m.context)) {
        std::fprintf(stderr, "fuzz_gpu_sequence: eglMakeCurrent failed with 0x%x\n", eglGetError());
        std::abort();
    }
    return m.host;
}

} // namespace grass_fuzz
