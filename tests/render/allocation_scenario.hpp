// The allocation-failure scenario of both backends' tests (device_failure_test.cpp on
// Vulkan, gl_allocation_failure_test.cpp on GL): a context, a patch, a density map, a field
// with every tier and, optionally, wind and a collider, then two frames, with one chosen GPU allocation
// failing. Every call either succeeds, or fails with GRASS_ERROR_OUT_OF_MEMORY because of the
// injected failure and succeeds when repeated; the last frame draws grass. The runs of a
// process share a bake cache: only the first bakes the slices (they allocate no GPU memory).
#pragma once

#include "render_fixture.hpp"

#include <functional>
#include <memory>
#include <string>

namespace grass_test {

struct FailureLog {
    grass_message_id last_error = GRASS_MSG_NONE;
    std::string text;
};

grass_context_desc logged_desc(FailureLog* log);

// The backend's side: how many failures were injected so far, and how many allocations were
// made (so that a run without failures counts them).
struct AllocationProbe {
    std::function<int()> failures_injected;
    std::function<int64_t()> allocations_made;
    const char* create_function = "grass_create_context";
    // Optional: called right after a call failed (context: NULL when its creation failed), to
    // check what the failure left.
    std::function<void(grass_context* context, const char* what)> after_failure;
};

struct ScenarioResult {
    int allocations = -1;             // allocations the scenario made; -1 after a failed expectation
    int setup_allocations = 0;        // of them, those made before the first frame
    std::string failed_call;          // the call the injected failure failed ("" if none)
    grass_context* context = nullptr; // still alive: the caller checks what it left, then destroys it
    std::unique_ptr<FailureLog> log;  // the context's log (it writes here until destroyed)
};

// Runs the scenario; `fail_at` (1-based; 0: none) is only reported in messages: the caller
// arms its injection before.
ScenarioResult run_allocation_scenario(grass_host::Host& host, const AllocationProbe& probe, int fail_at,
                                       bool responsive);

} // namespace grass_test
