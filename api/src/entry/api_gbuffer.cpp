// G-buffer views (GRASS_PASS_GBUFFER, grass_view_gbuffer_desc, grass.h; docs/engine-frames.md
// "Deferred renderers"): the struct's validation and defaults.
#include "entry/api_gbuffer.hpp"

#include "foundation/raw_enum.hpp"

#include <cstring>

namespace grass {
namespace {

const char* const kSemanticNames[5] = {"GRASS_GBUFFER_NONE", "GRASS_GBUFFER_ALBEDO", "GRASS_GBUFFER_NORMAL",
                                       "GRASS_GBUFFER_MATERIAL", "GRASS_GBUFFER_VELOCITY"};

} // namespace

grass_result check_view_gbuffer(grass_context* ctx, const char* fn, const grass_view_gbuffer_desc& d) {
    if (d.attachment_count < 1 || d.attachment_count > GRASS_MAX_GBUFFER_ATTACHMENTS) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_view_gbuffer_desc->attachment_count is %u; expected 1 to %d", fn,
                         d.attachment_count, GRASS_MAX_GBUFFER_ATTACHMENTS);
    }
    uint32_t first_of[5] = {0, 0, 0, 0, 0}; // 1 + the attachment of each semantic
    for (uint32_t i = 0; i < d.attachment_count; ++i) {
        const grass_gbuffer_attachment& a = d.attachments[i];
        const int64_t semantic = raw_enum(a.semantic);
        if (semantic < GRASS_GBUFFER_NONE || semantic > GRASS_GBUFFER_VELOCITY) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: grass_view_gbuffer_desc->attachments[%u].semantic is %lld; expected "
                             "GRASS_GBUFFER_NONE (0) to GRASS_GBUFFER_VELOCITY (4)",
                             fn, i, static_cast<long long>(semantic));
        }
        const int64_t format = raw_enum(a.format);
        if (format < GRASS_GBUFFER_FORMAT_UNORM || format > GRASS_GBUFFER_FORMAT_FLOAT) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: grass_view_gbuffer_desc->attachments[%u].format is %lld; expected "
                             "GRASS_GBUFFER_FORMAT_UNORM (0), GRASS_GBUFFER_FORMAT_SNORM (1) or "
                             "GRASS_GBUFFER_FORMAT_FLOAT (2)",
                             fn, i, static_cast<long long>(format));
        }
        if (a.write_mask > 15u) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: grass_view_gbuffer_desc->attachments[%u].write_mask is 0x%x; expected 0 to 15 (bit 1 "
                             "r, 2 g, 4 b, 8 a; 0: the semantic's own)",
                             fn, i, a.write_mask);
        }
        if (semantic == GRASS_GBUFFER_NONE) continue;
        if (first_of[semantic] != 0) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: grass_view_gbuffer_desc->attachments[%u].semantic is %s, as attachments[%u]'s is; "
                             "each semantic but GRASS_GBUFFER_NONE goes to one attachment",
                             fn, i, kSemanticNames[semantic], first_of[semantic] - 1);
        }
        first_of[semantic] = i + 1;
    }
    return GRASS_SUCCESS;
}

grass_result check_gbuffer_chain(grass_context* ctx, const char* fn, const ViewExtensions& ext) {
    if (!ext.pass || ext.pass->pass != GRASS_PASS_GBUFFER) return GRASS_SUCCESS;
    if (!ext.gbuffer) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                         "%s: grass_view_pass_desc->pass is GRASS_PASS_GBUFFER, but view->next chains no "
                         "grass_view_gbuffer_desc (the host's attachments)",
                         fn);
    }
    for (uint32_t i = 0; i < ext.gbuffer->attachment_count; ++i) {
        if (ext.gbuffer->attachments[i].semantic == GRASS_GBUFFER_VELOCITY && !ext.motion) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                             "%s: grass_view_gbuffer_desc->attachments[%u].semantic is GRASS_GBUFFER_VELOCITY, but "
                             "view->next chains no grass_view_motion_desc (the previous camera and time the "
                             "velocity is measured from)",
                             fn, i);
        }
    }
    return GRASS_SUCCESS;
}

} // namespace grass

GRASS_API grass_view_gbuffer_desc grass_default_view_gbuffer_desc(void) {
    grass_view_gbuffer_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC;
    d.attachment_count = 1;
    return d;
}
