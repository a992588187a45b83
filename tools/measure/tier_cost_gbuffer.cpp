// grass-measure tier-cost --gbuffer: the plain table's rows drawn as a colour view and as a
// G-buffer view (GRASS_PASS_GBUFFER) of the same camera, into the host's framebuffer with two
// RGBA8 renderbuffers added as draw buffers 1 and 2: albedo to the host's colour (draw buffer
// 0), the normal and the material to 1 and 2. Vulkan: the host's pass with two more RGBA8
// attachments (tier_cost.cpp, TargetDesc::vk_gbuffer_formats), the same layout.
#include "tier_cost.hpp"

#include "cli.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <GL/glcorearb.h>

#include <cstdio>
#include <cstring>
#include <vector>

namespace grass_measure {
namespace tier_cost {

int run_gbuffer(Rig& rig, const std::vector<Setup>& rows) {
    const Options& o = rig.options();
    grass_context* ctx = rig.ctx();
    const bool gl = o.backend == GRASS_BACKEND_GL;
    rig.frame_times(1); // the GL host binds its framebuffer and leaves it bound
    grass_host::Host& host = rig.host();
    const uint32_t formats[2] = {GL_RGBA8, GL_RGBA8};
    GLuint targets[2] = {};
    if (gl && !add_colour_targets(host, o.width, o.height, formats, 2, targets)) {
        std::fprintf(stderr, "grass-tier-cost --gbuffer: the host left no framebuffer bound\n");
        return 1;
    }

    grass_view_gbuffer_desc layout = grass_default_view_gbuffer_desc();
    layout.attachment_count = 3;
    layout.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
    layout.attachments[1].semantic = GRASS_GBUFFER_NORMAL;
    layout.attachments[2].semantic = GRASS_GBUFFER_MATERIAL;
    layout.attachments[2].write_mask = 0x7;
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    pass.next = &layout;
    std::printf("grass-tier-cost --gbuffer: %s (%s), %ux%u, 1024 cells of 0.25 m, frame with no grass %.2f ms (CPU "
                "%.2f ms)\n\n",
                grass_sample::backend_name(o.backend), host.device_name().c_str(), o.width, o.height, rig.empty_ms(),
                rig.empty_cpu_ms());
    std::printf("| tier | colour per basic cell (us) | G-buffer | CPU: colour (us) | CPU: G-buffer / colour |\n"
                "|---|---|---|---|---|\n");
    for (const Setup& s : rows) {
        if (!o.tier.empty() && std::strncmp(s.name, o.tier.c_str(), o.tier.size()) != 0) continue;
        const TierField tf(s, rig.patch());
        grass_field_id field{};
        grass_sample::check(grass_create_field(ctx, &tf.desc, &field), "grass_create_field", ctx);
        double us[2], cpu_us[2];
        rig.per_cell_variants(
            2, [&](int variant) { rig.set_pass(variant == 1 ? &pass : nullptr); }, us, cpu_us);
        rig.set_pass(nullptr);
        std::printf("| %s | %.2f | %.2f | %.2f | %.2f |\n", s.name, us[0], us[1], cpu_us[0], cpu_us[1] / cpu_us[0]);
        grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
    }
    if (gl) delete_colour_targets(host, 2, targets);
    return rig.finish();
}

} // namespace tier_cost
} // namespace grass_measure
