// Culled blades compacted in the GL backend (docs/responsive.md "Culled blades compacted",
// jahrmann2017 6.1-6.2): before a view's geometry draws, one dispatch of
// blade_compaction.comp per draw that runs the window variant (kFeatureBladeWindow), which
// writes the blades the view draws, in order, to the draw's items and counts them into the
// indirect arguments of each of its instances; then glMemoryBarrier(GL_COMMAND_BARRIER_BIT |
// GL_SHADER_STORAGE_BARRIER_BIT), and each such draw is one glMultiDrawElementsIndirect (a
// command per instance) of one blade's indices per item. Nothing
// here exists for a frame without the blade window.
#include "gl_backend.hpp"

#include "gl_program.hpp"

#include <algorithm>
#include <cstring>

namespace grass {

namespace {

// blade_compaction.glsl's and .comp's bindings: the patch's vertices at 3, the view's
// instances at 4, the items at 5, the indirect arguments at 6 (shader storage); the draw's
// block at uniform binding 2. The table and poses stay at 1 and 2 (bind_blade_window).
constexpr GLuint kCompactVerticesStorageBinding = 3;
constexpr GLuint kCompactInstancesStorageBinding = 4;
constexpr GLuint kCompactItemsStorageBinding = 5;
constexpr GLuint kCompactCommandsStorageBinding = 6;
constexpr GLuint kCompactDrawUniformBinding = 2;
constexpr size_t kCommandWords = 5; // DrawElementsIndirectCommand

size_t align_up(size_t value, size_t alignment) { return (value + alignment - 1) / alignment * alignment; }

} // namespace

grass_result GlBackend::blade_compaction_program(const char* function, uint32_t features, GLuint* out_program) {
    const uint32_t mask = features & (kBladeWindowPassFeatures | kFeatureBladeCulling);
    *out_program = 0;
    const grass_result result =
        compute_program(function, kBladeCompactionProgramKind, mask, &create_blade_compaction_program,
                        "grass blade compaction program", &compaction_programs_[mask]);
    if (result == GRASS_SUCCESS) *out_program = compaction_programs_[mask];
    return result;
}

bool GlBackend::compacts(const FramePlan& plan, const TierDraw& draw) const {
    return plan.compact_blade_window && draw.kind == GRASS_TIER_GEOMETRY &&
           (draw.features & kFeatureBladeWindow) != 0 && draw.instance_count > 0 && draw.vertex_count > 0 &&
           patches_[draw.patch_slot].curve_bytes > 0;
}

grass_result GlBackend::compact_blade_window(const FramePlan& plan, const char* function) {
    compact_command_.assign(plan.draws.size(), -1);
    compact_first_command_.assign(plan.draws.size(), 0);
    // The draws' items, indirect arguments and blocks: a draw of n instances of b blades
    // may draw n b blades.
    size_t items = 0;
    uint32_t commands = 0; // indirect arguments: one per instance of the compacted draws
    uint32_t draws = 0;    // compacted draws (their blocks)
    const size_t block_stride = align_up(4 * sizeof(uint32_t), static_cast<size_t>(uniform_alignment_));
    compact_staging_.clear();
    command_staging_.clear();
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& draw = plan.draws[i];
        if (!compacts(plan, draw)) continue;
        const PatchGpu& patch = patches_[draw.patch_slot];
        const uint32_t blades = static_cast<uint32_t>(patch.curve_bytes / (8 * sizeof(float)));
        const uint32_t block[4] = {draw.first_instance, static_cast<uint32_t>(items), commands, 0};
        compact_staging_.resize(size_t(draws + 1) * block_stride, 0);
        std::memcpy(compact_staging_.data() + size_t(draws) * block_stride, block, sizeof(block));
        // Per instance, one blade's indices per item: the draw's index count over the patch's
        // blades, from the first index of its tessellation level (blade 0's indices of that
        // level: the shader adds the item's blade); the shader writes the count and the first item.
        const uint32_t command[kCommandWords] = {draw.vertex_count / std::max(blades, 1u), 0, draw.first_index, 0, 0};
        for (uint32_t k = 0; k < draw.instance_count; ++k) {
            command_staging_.insert(command_staging_.end(), command, command + kCommandWords);
        }
        compact_command_[i] = static_cast<int32_t>(draws++);
        compact_first_command_[i] = commands;
        commands += draw.instance_count;
        items += size_t(draw.instance_count) * blades;
    }
    if (draws == 0) return GRASS_SUCCESS;
    const size_t item_bytes = items * 2 * sizeof(uint32_t);
    if (compact_item_capacity_ < item_bytes) {
        if (compact_items_ == 0) {
            gl_.CreateBuffers(1, &compact_items_);
            label(GL_BUFFER, compact_items_, "grass compacted blades");
        }
        gl_.NamedBufferData(compact_items_, static_cast<GLsizeiptr>(item_bytes), nullptr, GL_DYNAMIC_COPY);
        const grass_result result = check_errors(function, "making the compacted blades' buffer");
        if (result != GRASS_SUCCESS) return result;
        compact_item_capacity_ = item_bytes;
    }
    if (compact_commands_.name() == 0) {
        compact_commands_.create(gl_);
        label(GL_BUFFER, compact_commands_.name(), "grass compacted blades' indirect arguments");
        compact_blocks_.create(gl_);
        label(GL_BUFFER, compact_blocks_.name(), "grass compacted blades' draws");
    }
    compact_commands_.upload(gl_, command_staging_.data(), command_staging_.size() * sizeof(uint32_t));
    compact_blocks_.upload(gl_, compact_staging_.data(), compact_staging_.size());

    gl_.BindBufferRange(GL_UNIFORM_BUFFER, 0, uniforms_.name(), 0, sizeof(FrameUniforms));
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCompactInstancesStorageBinding, instances_.name());
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCompactItemsStorageBinding, compact_items_);
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCompactCommandsStorageBinding, compact_commands_.name());
    bind_blade_window();
    for (const GLint unit : kMapUnit) gl_.BindSampler(static_cast<GLuint>(unit), sampler_);
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        if (compact_command_[i] < 0) continue;
        const TierDraw& draw = plan.draws[i];
        const PatchGpu& patch = patches_[draw.patch_slot];
        GLuint program = 0;
        const grass_result result = blade_compaction_program(function, draw.features, &program);
        if (result != GRASS_SUCCESS) return result;
        gl_.UseProgram(program);
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kBladeCurvesStorageBinding, patch.curves);
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCompactVerticesStorageBinding, patch.vertices);
        bind_field_maps(fields_[draw.field_slot], draw.features);
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, 1, uniforms_.name(), field_uniform_offsets_[i], sizeof(FieldUniforms));
        gl_.BindBufferRange(GL_UNIFORM_BUFFER, kCompactDrawUniformBinding, compact_blocks_.name(),
                            static_cast<GLintptr>(size_t(compact_command_[i]) * block_stride), 4 * sizeof(uint32_t));
        gl_.DispatchCompute(1, draw.instance_count, 1); // a work group per instance
    }
    // The draws read the arguments (indirect) and the items (storage).
    gl_.MemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    gl_.UseProgram(0);
    return GRASS_SUCCESS;
}

void GlBackend::draw_compacted(const TierDraw& draw, size_t index) const {
    const PatchGpu& patch = patches_[draw.patch_slot];
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCompactVerticesStorageBinding, patch.vertices);
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCompactInstancesStorageBinding, instances_.name());
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, kCompactItemsStorageBinding, compact_items_);
    gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, compact_commands_.name());
    const size_t offset = size_t(compact_first_command_[index]) * kCommandWords * sizeof(uint32_t);
    gl_.MultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(offset),
                                  static_cast<GLsizei>(draw.instance_count), 0);
}

uint64_t GlBackend::blade_compaction_bytes() const {
    return compact_item_capacity_ + compact_commands_.capacity() + compact_blocks_.capacity();
}

void GlBackend::release_blade_compaction_buffers() {
    if (compact_items_ != 0) gl_.DeleteBuffers(1, &compact_items_);
    compact_items_ = 0;
    compact_item_capacity_ = 0;
    compact_commands_.destroy(gl_);
    compact_blocks_.destroy(gl_);
}

void GlBackend::release_blade_compaction() {
    release_blade_compaction_buffers();
    for (GLuint& program : compaction_programs_) {
        if (program != 0) gl_.DeleteProgram(program);
        program = 0;
    }
}

} // namespace grass
