// G-buffer views (GRASS_PASS_GBUFFER): the routes of a view's outputs and its GrassGBuffer block.
#include "plan/gbuffer_plan.hpp"

#include "foundation/shader_interface.hpp"

namespace grass {

uint32_t gbuffer_write_mask(const grass_gbuffer_attachment& a) {
    if (a.write_mask != 0) return a.write_mask;
    return a.semantic == GRASS_GBUFFER_ALBEDO || a.semantic == GRASS_GBUFFER_NORMAL ? 7u : 3u;
}

GBufferLayout gbuffer_layout(const grass_view_gbuffer_desc& d) {
    GBufferLayout layout;
    for (uint32_t a = 0; a < d.attachment_count; ++a) {
        const grass_gbuffer_attachment& at = d.attachments[a];
        const uint32_t output = kGBufferOutput[at.semantic];
        if (output == kNoGBufferOutput) continue;
        layout.attachment[output] = a;
        layout.mask[output] = gbuffer_write_mask(at);
    }
    return layout;
}

void plan_gbuffer(const ViewExtensions& ext, FramePlan* plan) {
    plan->gbuffer = ext.pass && ext.pass->pass == GRASS_PASS_GBUFFER && ext.gbuffer;
    const GBufferLayout layout = plan->gbuffer ? gbuffer_layout(*ext.gbuffer) : GBufferLayout{};
    for (uint32_t i = 0; i < kGBufferOutputs; ++i) {
        plan->gbuffer_attachment[i] = layout.attachment[i];
        plan->gbuffer_mask[i] = layout.mask[i];
    }
    plan->gbuffer_uniforms = GBufferUniforms{};
    if (!plan->gbuffer) return;
    const grass_view_gbuffer_desc& d = *ext.gbuffer;
    plan->gbuffer_uniforms.normal_encode[0] = 1.0f;
    for (uint32_t a = 0; a < d.attachment_count; ++a) {
        const grass_gbuffer_attachment& at = d.attachments[a];
        if (at.semantic == GRASS_GBUFFER_NORMAL && at.format == GRASS_GBUFFER_FORMAT_UNORM) {
            plan->gbuffer_uniforms.normal_encode[0] = 0.5f;
            plan->gbuffer_uniforms.normal_encode[1] = 0.5f;
        }
    }
    for (TierDraw& draw : plan->draws) {
        draw.features |= kFeatureGBuffer;
        draw.uniforms.tiling[3] = draw.features;
    }
}

} // namespace grass
