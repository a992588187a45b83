#include "vk_gbuffer.hpp"

#include "vk_pipeline.hpp"
#include "vk_view_extras.hpp"

namespace grass::vk {

namespace {
constexpr uint32_t kOpEntryPoint = 15, kOpTypePointer = 32, kOpVariable = 59, kOpDecorate = 71;
constexpr uint32_t kDecorationLocation = 30, kStoragePrivate = 6;
constexpr uint32_t kWriteMaskAll = 0xf;

// The pipelines' names, [kind].
const char* const kNames[3] = {"the blade G-buffer pipelines", "the volume tier G-buffer pipelines",
                               "the image tier G-buffer pipelines"};
} // namespace

GBufferRoutes GBufferRoutes::of(const FramePlan& plan) {
    GBufferLayout layout;
    for (uint32_t i = 0; i < kGBufferOutputs; ++i) {
        layout.attachment[i] = plan.gbuffer_attachment[i];
        layout.mask[i] = plan.gbuffer_mask[i];
    }
    return of(layout);
}

GBufferRoutes GBufferRoutes::of(const GBufferLayout& layout) {
    GBufferRoutes r;
    for (uint32_t i = 0; i < kGBufferOutputs; ++i) {
        r.attachment[i] = layout.attachment[i];
        r.mask[i] = layout.mask[i] & kWriteMaskAll;
    }
    return r;
}

bool GBufferRoutes::operator==(const GBufferRoutes& o) const {
    for (uint32_t i = 0; i < kGBufferOutputs; ++i) {
        if (attachment[i] != o.attachment[i] || mask[i] != o.mask[i]) return false;
    }
    return true;
}

bool route_gbuffer_outputs(const uint32_t* code, size_t words, const GBufferRoutes& routes, Vector<uint32_t>* out) {
    if (words < 5 || code[0] != 0x07230203u) return false;
    // The Output variables at a G-buffer output location.
    struct Output {
        uint32_t id = 0, location = 0;
    };
    Output outputs[kGBufferOutputs];
    uint32_t output_count = 0;
    for (size_t at = 5; at < words;) {
        const uint32_t count = code[at] >> 16, op = code[at] & 0xffffu;
        if (count == 0 || at + count > words) return false;
        if (op == kOpDecorate && count >= 4 && code[at + 2] == kDecorationLocation && code[at + 3] < kGBufferOutputs &&
            is_output_variable(code, words, code[at + 1]) && output_count < kGBufferOutputs) {
            outputs[output_count++] = Output{code[at + 1], code[at + 3]};
        }
        at += count;
    }
    const auto find = [&](uint32_t id) -> const Output* {
        for (uint32_t i = 0; i < output_count; ++i) {
            if (outputs[i].id == id) return &outputs[i];
        }
        return nullptr;
    };
    const auto dropped = [&](uint32_t id) {
        const Output* o = find(id);
        return o != nullptr && routes.attachment[o->location] == kNoGBufferOutput;
    };
    // The Private pointer type each dropped variable takes: an existing one of its pointee, or
    // a new id made just before the variable.
    uint32_t bound = code[3];
    out->clear();
    out->reserve(words + 4 * kGBufferOutputs);
    out->insert(out->end(), code, code + 5);
    for (size_t at = 5; at < words;) {
        const uint32_t count = code[at] >> 16, op = code[at] & 0xffffu;
        const uint32_t* in = code + at;
        at += count;
        if (op == kOpDecorate && count >= 4 && in[2] == kDecorationLocation && find(in[1]) != nullptr) {
            const uint32_t to = routes.attachment[find(in[1])->location];
            if (to == kNoGBufferOutput) continue; // a private variable has no location
            out->insert(out->end(), in, in + count);
            out->back() = to;
            continue;
        }
        if (op == kOpEntryPoint) {
            // Operands: execution model, id, name (a nul-terminated string), then the interface.
            size_t word = 3;
            while (word < count) {
                const uint32_t w = in[word++];
                if ((w >> 24) == 0 || ((w >> 16) & 0xff) == 0 || ((w >> 8) & 0xff) == 0 || (w & 0xff) == 0) break;
            }
            const size_t start = out->size();
            out->insert(out->end(), in, in + word);
            for (; word < count; ++word) {
                if (!dropped(in[word])) out->push_back(in[word]);
            }
            (*out)[start] = static_cast<uint32_t>((out->size() - start) << 16) | kOpEntryPoint;
            continue;
        }
        if (op == kOpVariable && count >= 4 && dropped(in[2])) {
            // The pointee of its Output pointer type.
            uint32_t pointee = 0;
            for (size_t t = 5; t < words;) {
                const uint32_t c = code[t] >> 16;
                if ((code[t] & 0xffffu) == kOpTypePointer && c == 4 && code[t + 1] == in[1]) pointee = code[t + 3];
                t += c;
            }
            if (pointee == 0) return false;
            const uint32_t type = bound++;
            const uint32_t pointer[4] = {(4u << 16) | kOpTypePointer, type, kStoragePrivate, pointee};
            out->insert(out->end(), pointer, pointer + 4);
            out->insert(out->end(), in, in + count);
            (*out)[out->size() - count + 1] = type;
            (*out)[out->size() - count + 3] = kStoragePrivate;
            continue;
        }
        out->insert(out->end(), in, in + count);
    }
    (*out)[3] = bound;
    return true;
}

bool GBufferPipelines::create_variant(const PipelineTarget& target, VkPipelineLayout layout,
                                      const GBufferRoutes& routes, const ShaderVariant& variant,
                                      const PipelineShape& shape, bool depth_test, VkFailure* failure,
                                      const char** what) {
    if (pipeline(routes, variant.program, variant.features, depth_test) != VK_NULL_HANDLE) return true;
    if (variant.program >= 3 || shape.fragment_code == nullptr || target.color_count == 0) {
        *what = "a G-buffer view's pipeline (no such variant, or no grass_vk_gbuffer_target_desc)";
        return false;
    }
    Vector<uint32_t> code{StlAllocator<uint32_t>(host_)};
    if (!route_gbuffer_outputs(shape.fragment_code, shape.fragment_code_size / sizeof(uint32_t), routes, &code)) {
        *what = "a G-buffer view's fragment module (not one grass can route)";
        return false;
    }
    // Each attachment's write mask: its semantic's output's, 0 where none goes.
    PipelineTarget routed = target;
    routed.velocity_attachment = 0;
    routed.explicit_masks = true;
    for (uint32_t& m : routed.write_masks) m = 0;
    for (uint32_t o = 0; o < kGBufferOutputs; ++o) {
        if (routes.attachment[o] < target.color_count) routed.write_masks[routes.attachment[o]] = routes.mask[o];
    }
    PipelineShape named = shape;
    named.name = kNames[variant.program];
    named.fragment_code = code.data();
    named.fragment_code_size = code.size() * sizeof(uint32_t);
    named.alpha_to_coverage = false; // coverage alpha-tested, as the depth pass's
    entries_.push_back(Entry{routes, variant.program, variant.features, depth_test, VK_NULL_HANDLE});
    if (!create_pipeline(fn_, device_, routed, layout, named, variant.features, depth_test, &entries_.back().pipeline,
                         failure, what)) {
        entries_.pop_back();
        return false;
    }
    return true;
}

VkPipeline GBufferPipelines::pipeline(const GBufferRoutes& routes, uint32_t kind, uint32_t features,
                                      bool depth_test) const {
    for (const Entry& e : entries_) {
        if (e.kind == kind && e.features == features && e.depth_test == depth_test && e.routes == routes)
            return e.pipeline;
    }
    return VK_NULL_HANDLE;
}

void GBufferPipelines::destroy() {
    for (Entry& e : entries_) {
        if (e.pipeline) fn_.vkDestroyPipeline(device_, e.pipeline, fn_.callbacks());
    }
    entries_.clear();
}

} // namespace grass::vk
