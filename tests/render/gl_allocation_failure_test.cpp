// GL allocation failure. GL cannot be asked to fail an allocation, but grass reaches GL only
// through the loader its host hands it: this test's loader wraps every call that allocates
// GPU memory (glNamedBufferStorage, glNamedBufferData, glTextureStorage2D,
// glTextureStorage3D). The chosen call does nothing and leaves GL_OUT_OF_MEMORY for grass's
// next glGetError, as a driver that could not allocate does; the object stays without
// storage, so that grass's later calls on it raise the errors they would.
// Every allocation of the scenario of allocation_scenario.hpp fails in turn: the call that
// made it returns GRASS_ERROR_OUT_OF_MEMORY, repeated it succeeds, the last frame draws
// grass, and destroying the context leaves no GL object behind. Frames are checked in a
// debug context only (grass calls glGetError on the draw path there, docs/api.md): the
// headless host asks EGL for one.
#include "allocation_scenario.hpp"
#include "gl_names.hpp"

#include <GL/glcorearb.h>

#include <cstring>

namespace grass_test {
namespace {

struct Injection {
    int calls = 0;        // allocating calls so far
    int fail_at = 0;      // the call that fails (1-based; 0: none)
    int injected = 0;     // failures injected
    bool pending = false; // GL_OUT_OF_MEMORY waits for grass's glGetError
    PFNGLGETERRORPROC get_error = nullptr;
    PFNGLNAMEDBUFFERSTORAGEPROC buffer_storage = nullptr;
    PFNGLNAMEDBUFFERDATAPROC buffer_data = nullptr;
    PFNGLTEXTURESTORAGE2DPROC storage_2d = nullptr;
    PFNGLTEXTURESTORAGE3DPROC storage_3d = nullptr;
} g;

// True when this allocating call is the one to fail.
bool fails() {
    if (++g.calls != g.fail_at) return false;
    g.injected += 1;
    g.pending = true;
    return true;
}

GLenum APIENTRY get_error() {
    if (g.pending) {
        g.pending = false;
        return GL_OUT_OF_MEMORY;
    }
    return g.get_error();
}
void APIENTRY buffer_storage(GLuint buffer, GLsizeiptr size, const void* data, GLbitfield flags) {
    if (!fails()) g.buffer_storage(buffer, size, data, flags);
}
void APIENTRY buffer_data(GLuint buffer, GLsizeiptr size, const void* data, GLenum usage) {
    if (!fails()) g.buffer_data(buffer, size, data, usage);
}
void APIENTRY storage_2d(GLuint texture, GLsizei levels, GLenum format, GLsizei width, GLsizei height) {
    if (!fails()) g.storage_2d(texture, levels, format, width, height);
}
void APIENTRY storage_3d(GLuint texture, GLsizei levels, GLenum format, GLsizei width, GLsizei height, GLsizei depth) {
    if (!fails()) g.storage_3d(texture, levels, format, width, height, depth);
}

template <typename Fn>
void (*wrap(void (*real)(void), Fn* keep, Fn wrapper))(void) {
    *keep = reinterpret_cast<Fn>(real);
    return reinterpret_cast<void (*)(void)>(wrapper);
}

void (*filter(const char* name, void (*real)(void)))(void) {
    if (std::strcmp(name, "glGetError") == 0) return wrap(real, &g.get_error, &get_error);
    if (std::strcmp(name, "glNamedBufferStorage") == 0) return wrap(real, &g.buffer_storage, &buffer_storage);
    if (std::strcmp(name, "glNamedBufferData") == 0) return wrap(real, &g.buffer_data, &buffer_data);
    if (std::strcmp(name, "glTextureStorage2D") == 0) return wrap(real, &g.storage_2d, &storage_2d);
    if (std::strcmp(name, "glTextureStorage3D") == 0) return wrap(real, &g.storage_3d, &storage_3d);
    return real;
}

class GlAllocationFailure : public ::testing::Test {
protected:
    void SetUp() override {
        grass_host::TargetDesc t;
        t.width = t.height = 96;
        t.ground = true;
        t.gl_proc_filter = &filter;
        std::string error;
        host = grass_host::Host::create(GRASS_BACKEND_GL, t, &error);
        ASSERT_TRUE(host) << error;
        GLint flags = 0;
        reinterpret_cast<PFNGLGETINTEGERVPROC>(host->gl_proc_address("glGetIntegerv"))(GL_CONTEXT_FLAGS, &flags);
        if (!(flags & GL_CONTEXT_FLAG_DEBUG_BIT)) GTEST_SKIP() << "the host has no debug context (OSMesa)";
        names_before = gl_live_names(*host);
    }

    // One run with the `fail_at`th allocating call failing (0: none); then the context is
    // destroyed and every GL object grass made must be gone.
    ScenarioResult run(int fail_at, bool responsive) {
        g.calls = 0;
        g.fail_at = fail_at;
        g.pending = false;
        AllocationProbe probe;
        probe.failures_injected = [] { return g.injected; };
        probe.allocations_made = [] { return static_cast<int64_t>(g.calls); };
        probe.create_function = "grass_gl_create_context";
        ScenarioResult result = run_allocation_scenario(*host, probe, fail_at, responsive);
        if (result.context) grass_destroy_context(result.context);
        EXPECT_FALSE(g.pending) << "allocation " << fail_at << ": grass never looked at the error";
        EXPECT_EQ(gl_live_names(*host), names_before) << "allocation " << fail_at << ": GL objects left behind";
        g.fail_at = 0;
        return result;
    }

    // Fails each allocation from `first` (1-based) to the scenario's last, in turn.
    int fail_each(bool responsive, int first) {
        const int total = run(0, responsive).allocations;
        EXPECT_GE(total, first);
        for (int n = first; n <= total && !HasFailure(); ++n) run(n, responsive);
        return total;
    }

    std::unique_ptr<grass_host::Host> host;
    long names_before = 0;
};

TEST_F(GlAllocationFailure, EveryGpuAllocationFailingInTurnGivesOutOfMemory) {
    const int total = fail_each(false, 1);
    ASSERT_GT(total, 5) << "programs, patch, slices and per-frame buffers allocate";
    std::printf("[ gl       ] %d GPU allocations, each failed once\n", total);
}

TEST_F(GlAllocationFailure, EveryAllocationOfResponsiveGrassFailingInTurnGivesOutOfMemory) {
    const int still = run(0, false).allocations;
    const ScenarioResult responsive = run(0, true);
    ASSERT_GT(responsive.allocations, still) << "wind and a collider allocate more";
    // Responsive grass allocates in its frames; the setup is that of still grass, tested above.
    const int total = fail_each(true, responsive.setup_allocations + 1);
    std::printf("[ gl       ] %d GPU allocations with wind and a collider; the %d of its frames each failed once\n",
                total, total - responsive.setup_allocations);
}

} // namespace
} // namespace grass_test
