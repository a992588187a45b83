// Which GL programs grass creates and binds, seen through the host's GL loader
// (grass_host::TargetDesc::gl_proc_filter = &gl_program_spy_filter): the tests that a view
// without a feature keeps its programs and one with it compiles its own (ShadowReceiveTest,
// MotionVectorsTest, HostLightsTest).
#pragma once

#include <GL/glcorearb.h>

#include <cstdint>
#include <set>

namespace grass_test {

struct GlProgramSpy {
    std::set<GLuint> used; // every program grass bound with glUseProgram since cleared
    int64_t created = 0;   // glCreateProgram calls
    PFNGLUSEPROGRAMPROC use_program = nullptr;
    PFNGLCREATEPROGRAMPROC create_program = nullptr;
};

// The spy every test of the process shares (one GL host at a time).
GlProgramSpy& gl_program_spy();

// A gl_proc_filter: hands grass glUseProgram and glCreateProgram through the spy.
void (*gl_program_spy_filter(const char* name, void (*real)(void)))(void);

} // namespace grass_test
