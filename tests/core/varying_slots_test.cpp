// The blade tier's varyings fill as few slots as GL's linker would pack them into.
// lavapipe (Mesa's Vulkan on llvmpipe; seen in 22.3) neither packs varyings nor drops those
// the fragment shader does not read: every output slot of every vertex is copied, set up per
// triangle and interpolated. With eight outputs in eight slots the Vulkan blade tier cost
// 1.3 times GL's CPU time per cell (docs/records/tier-cost.md); packed four to a slot, as
// GL's linker packs them, the two are level. The test reads the SPIR-V the Vulkan backend
// embeds (vk_spirv.hpp) and counts the vertex shader's located outputs in every variant.
#include "vk_spirv.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>

namespace {

constexpr uint32_t kOpTypeVector = 23, kOpTypeArray = 28, kOpTypeMatrix = 24, kOpTypeStruct = 30;
constexpr uint32_t kOpTypePointer = 32, kOpVariable = 59, kOpDecorate = 71;
constexpr uint32_t kDecorationLocation = 30, kStorageOutput = 3;

// The located outputs of a SPIR-V module: one slot each (vectors and scalars of 32 bits; an
// array, matrix or struct, which could take more, is an error).
struct Outputs {
    int slots = 0;
    std::string error;
};

Outputs located_outputs(const uint32_t* words, uint32_t bytes) {
    Outputs out;
    const uint32_t count = bytes / 4;
    if (count < 5 || words[0] != 0x07230203u) {
        out.error = "not a SPIR-V module";
        return out;
    }
    std::set<uint32_t> located;
    std::map<uint32_t, uint32_t> pointee; // pointer type -> pointed-to type
    std::map<uint32_t, uint32_t> opcode_of_type;
    std::map<uint32_t, uint32_t> output_vars; // variable -> pointer type
    for (uint32_t i = 5; i < count;) {
        const uint32_t n = words[i] >> 16, op = words[i] & 0xffffu;
        if (n == 0 || i + n > count) {
            out.error = "malformed instruction at word " + std::to_string(i);
            return out;
        }
        const uint32_t* w = words + i;
        if (op == kOpDecorate && n >= 3 && w[2] == kDecorationLocation) located.insert(w[1]);
        if ((op == kOpTypeVector || op == kOpTypeArray || op == kOpTypeMatrix || op == kOpTypeStruct) && n >= 2) {
            opcode_of_type[w[1]] = op;
        }
        if (op == kOpTypePointer && n >= 4) pointee[w[1]] = w[3];
        if (op == kOpVariable && n >= 4 && w[3] == kStorageOutput) output_vars[w[2]] = w[1];
        i += n;
    }
    for (const auto& [var, pointer] : output_vars) {
        if (located.count(var) == 0) continue; // built-ins (gl_PerVertex)
        const auto type = opcode_of_type.find(pointee[pointer]);
        if (type != opcode_of_type.end() && type->second != kOpTypeVector) {
            out.error = "output %" + std::to_string(var) + " is an array, matrix or struct: count its slots";
            return out;
        }
        ++out.slots;
    }
    return out;
}

TEST(VaryingSlotsTest, BladeVertexShaderWritesFourSlots) {
    // Position and density, normal and opacity, albedo and the threshold's code, the shape and
    // the light: 14 values, four slots (blade.vert).
    for (const bool multiview : {false, true}) {
        for (const bool responsive : {false, true}) {
            for (const bool indexed_blocks : {false, true}) {
                const grass::vk::Spirv code =
                    grass::vk::spirv(grass::vk::Shader::blade_vert, {responsive, indexed_blocks, multiview});
                const Outputs out = located_outputs(code.code, code.size);
                ASSERT_EQ(out.error, "");
                EXPECT_EQ(out.slots, 4) << "blade.vert (responsive " << responsive << ", indexed blocks "
                                        << indexed_blocks << ", multiview " << multiview
                                        << "): pack its varyings four to a slot";
            }
        }
    }
}

// The multiview variant (stereo, GRASS_MULTIVIEW) is what a stereo context's pipelines run,
// and only theirs: its vertex shaders declare the MultiView capability (gl_ViewIndex picks
// the eye; a fragment shader declares it only where it reads the eye), and none of the mono
// modules does (a mono context runs exactly the shaders of before).
TEST(VaryingSlotsTest, OnlyTheMultiviewModulesDeclareMultiView) {
    constexpr uint32_t kOpCapability = 17, kCapabilityMultiView = 4439;
    const auto declares_multiview = [&](const grass::vk::Spirv& code) {
        const uint32_t count = code.size / 4;
        for (uint32_t at = 5; at < count;) {
            const uint32_t words = code.code[at] >> 16, op = code.code[at] & 0xffffu;
            if (words == 0) return false;
            if (op == kOpCapability && words >= 2 && code.code[at + 1] == kCapabilityMultiView) return true;
            at += words;
        }
        return false;
    };
    for (int shader = 0; shader <= static_cast<int>(grass::vk::Shader::debug_frag); ++shader) {
        for (const bool multiview : {false, true}) {
            for (const bool responsive : {false, true}) {
                for (const bool indexed_blocks : {false, true}) {
                    const grass::vk::Spirv code = grass::vk::spirv(static_cast<grass::vk::Shader>(shader),
                                                                   {responsive, indexed_blocks, multiview});
                    const bool vertex = shader % 2 == 0; // Shader: each vertex shader, then its fragment shader
                    if (!multiview || vertex) {
                        EXPECT_EQ(declares_multiview(code), multiview)
                            << "shader " << shader << " (responsive " << responsive << ", indexed blocks "
                            << indexed_blocks << ", multiview " << multiview << ")";
                    }
                }
            }
        }
    }
}

TEST(VaryingSlotsTest, RejectsWhatIsNotSpirv) {
    const uint32_t words[6] = {0x12345678u, 0, 0, 0, 0, 0};
    EXPECT_EQ(located_outputs(words, sizeof(words)).error, "not a SPIR-V module");
}

} // namespace
