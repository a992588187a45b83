// Backends for the core tests: hold nothing, draw nothing, and let a test see what the core
// asks of a backend. remake_with<B>() gives a CoreTest's context such a backend.
#pragma once

#include "context/backend.hpp"
#include "context/context.hpp"

#include <grass/grass.h>

#include <gtest/gtest.h>

// Every call succeeds and does nothing; kind() says which backend it pretends to be.
class HollowBackend : public grass::Backend {
public:
    grass_result upload_patch(uint32_t, const grass::PatchData&) override { return GRASS_SUCCESS; }
    grass_result upload_slices(uint32_t, const grass::SliceSet&) override { return GRASS_SUCCESS; }
    void release_patch(uint32_t) override {}
    grass_result upload_map(uint32_t, const grass::MapTexels&) override { return GRASS_SUCCESS; }
    grass_result update_map(uint32_t, const grass::MapTexels&, const grass::MapRegion&) override {
        return GRASS_SUCCESS;
    }
    void release_map(uint32_t) override {}
    grass_result upload_blade_curves(uint32_t, const grass::PatchData&) override { return GRASS_SUCCESS; }
    grass_result upload_field(uint32_t, const grass::FieldMaps&) override { return GRASS_SUCCESS; }
    void release_field(uint32_t) override {}
    void set_field_wind_map(uint32_t, uint32_t) override {}
    grass_result prepare_variants(const char*, const grass::ShaderVariant*, uint32_t, bool, bool,
                                  const grass::GBufferLayout*) override {
        return GRASS_SUCCESS;
    }
    grass_result seed_pipeline_cache(const char*, const void*, uint64_t) override { return GRASS_SUCCESS; }
    grass_result pipeline_cache_data(const char*, void*, uint64_t* size) override {
        *size = 0;
        return GRASS_SUCCESS;
    }
    grass::RenderTarget render_target() const override { return grass::RenderTarget{}; }
    grass_result begin_host_frame(const char*, const grass::HostFrame&, bool) override { return GRASS_SUCCESS; }
    grass_result begin_view(const char*, uint32_t, const grass::FramePlan&) override { return GRASS_SUCCESS; }
    void end_frame() override {}
    uint64_t gpu_bytes() const override { return 0; }
    uint64_t dynamics_gpu_bytes() const override { return 0; }
    bool runs_blade_window() const override { return false; }
    bool tier_gpu_ms(double out_ms[GRASS_TIER_KIND_COUNT]) override {
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) out_ms[k] = 0.0;
        return false;
    }
    grass_result check_current(const char*) override { return GRASS_SUCCESS; }
};

// Replaces *ctx with a context of the same desc (the fixture's log) whose backend is a new B.
template <class B>
void remake_with(grass_context** ctx) {
    const grass_context_desc d = (*ctx)->desc;
    grass_destroy_context(*ctx);
    *ctx = nullptr;
    const auto factory = [](grass_context* c, void*, grass::Backend** out) {
        *out = c->host.create<B>();
        return GRASS_SUCCESS;
    };
    ASSERT_EQ(grass::create_context("test", GRASS_HEADER_VERSION, &d, factory, nullptr, ctx), GRASS_SUCCESS);
}
