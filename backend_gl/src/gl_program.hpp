// The backend's programs, compiled by the driver from the embedded shader sources. Each
// program comes in variants, one per design-map feature mask (GRASS_FEATURES in
// blade_interface.glsl: bit = 1 << MapRole), so that a field samples only its own maps.
#pragma once

#include "gl_functions.hpp"

#include "context/context.hpp"
#include "foundation/shader_interface.hpp"
#include "foundation/shader_variants.hpp"

namespace grass {

// Texture units of the programs' samplers. Unit 0 holds the density map (the shaders'
// binding 2 is the Vulkan descriptor binding; unit 0 is the one grass_gl.h documents);
// units 3-5 the baked slices and 6-9 the colour, ambient, diffuse and height maps, as bound
// in blade_interface.glsl. All of them are saved and restored around drawing.
constexpr GLint kDensityMapUnit = 0;
constexpr GLint kSliceColorUnit = 3;
constexpr GLint kSliceNormalUnit = 4;
constexpr GLint kSliceThresholdUnit = 5;
constexpr GLint kMapUnit[kMapRoleCount] = {
    kDensityMapUnit, static_cast<GLint>(kMapBinding[kMapColor]), static_cast<GLint>(kMapBinding[kMapAmbient]),
    static_cast<GLint>(kMapBinding[kMapDiffuse]), static_cast<GLint>(kMapBinding[kMapHeight])};
static_assert(kMapUnit[kMapColor] == 6 && kMapUnit[kMapHeight] == 9, "design map units 6-9");

// The programs of the backend.
enum GlProgramKind : uint32_t {
    kProgramBlades = 0,     // blade.vert + blade.frag
    kProgramVolume = 1,     // volume.vert + volume.frag
    kProgramImage = 2,      // image.vert + image.frag
    kProgramDebugTiers = 3, // debug_tiers.vert + debug_tiers.frag (GRASS_VIEW_FLAG_DEBUG_CELLS)
    kProgramKindCount = 4
};
static_assert(kProgramBlades == static_cast<uint32_t>(kShaderBlades) &&
                  kProgramVolume == static_cast<uint32_t>(kShaderVolume) &&
                  kProgramImage == static_cast<uint32_t>(kShaderImage) &&
                  kProgramDebugTiers == static_cast<uint32_t>(kShaderDebugBoxes),
              "the programs of foundation/shader_variants.hpp");
// Every feature mask: the design maps' bits, then kFeatureWind, kFeatureInteraction,
// kFeatureWindMap, kFeatureBladeCulling and kFeatureDebugView (backend.hpp).
constexpr uint32_t kFeatureVariants = kFeatureMaskCount;
// The masks without kFeatureDepthPass, kFeatureShadowReceive, kFeatureMotion,
// kFeatureHostLights, kFeatureGBuffer and kFeatureBladeWindow (a depth pass's, a receiving
// view's, a motion view's, a lit view's, a G-buffer view's and the blade window's
// programs are kept apart, made on the first such view:
// GlBackend::program_slot), and the masks with either.
constexpr uint32_t kColourVariants = kFeatureDepthPass;
constexpr uint32_t kPassVariants = kFeatureVariants - kColourVariants;
static_assert(kFeatureShadowReceive == kFeatureDepthPass << 1 && kFeatureMotion == kFeatureShadowReceive << 1 &&
                  kFeatureHostLights == kFeatureMotion << 1 && kFeatureGBuffer == kFeatureHostLights << 1 &&
                  kFeatureBladeWindow == kFeatureGBuffer << 1 && kFeatureVariants == kFeatureBladeWindow << 1,
              "the pass bits and the blade window's are the last six");
// A view lit by the host's lights: its GrassLights block at uniform binding 4 (host_lights.glsl).
constexpr GLuint kLightsUniformBinding = 4;
// A G-buffer view: its GrassGBuffer block at uniform binding 5 (gbuffer.glsl); output
// locations as kGBufferOutput (gl_gbuffer.cpp routes them).
constexpr GLuint kGBufferUniformBinding = 5;
// A view with motion vectors: its GrassMotion block at uniform binding 3 (motion.glsl); the
// fragment shaders write the velocity to output location 1 (gl_motion.cpp routes it).
constexpr GLuint kMotionUniformBinding = 3;
constexpr GLuint kVelocityOutput = 1;
// A receiving view's shadow map (host_shadows.glsl: a GL_TEXTURE_2D_ARRAY with a depth-compare
// sampler) at texture unit 14, its GrassShadow block at uniform binding 2.
constexpr GLint kShadowMapUnit = 14;
constexpr GLuint kShadowUniformBinding = 2;
static_assert(kFeatureWind == 1u << kMapRoleCount && kFeatureInteraction == kFeatureWind << 1 &&
                  kFeatureWindMap == kFeatureInteraction << 1 && kFeatureBladeCulling == kFeatureWindMap << 1 &&
                  kFeatureDebugView == kFeatureBladeCulling << 1,
              "feature bits follow the design maps' bits");

// Responsive grass (api/shaders/interaction.glsl, blade_dynamics.glsl, interaction.comp):
// the interaction map's levels are sampled from texture units 10 and 11; a geometry draw
// reads its patch's blade curves from shader storage binding 0; the interaction pass binds
// its level's uniform block at uniform binding 0, colliders and tile lists at shader
// storage bindings 1-3 and the level's texture at image unit 0.
constexpr GLint kInteractionMapUnit[2] = {static_cast<GLint>(kInteractionMapBinding[0]),
                                          static_cast<GLint>(kInteractionMapBinding[1])};
// A field's wind map (kFeatureWindMap) is fetched from texture unit 13.
constexpr GLint kWindMapUnit = static_cast<GLint>(kWindMapBinding);
constexpr GLuint kBladeCurvesStorageBinding = 0;
constexpr GLuint kInteractionUniformBinding = 0;
constexpr GLuint kCollidersStorageBinding = 1;
constexpr GLuint kTileOffsetsStorageBinding = 2;
constexpr GLuint kTileCollidersStorageBinding = 3;
constexpr GLuint kInteractionImageUnit = 0;

// Compiles and links the program of `kind` for the feature mask `features` (<
// kFeatureVariants): the shaders get `#define GRASS_FEATURES <features>u` after their
// #version line (and `#define GRASS_RESPONSIVE 1` when the mask has one of
// kBladeCurveFeatures, with `#define GRASS_BLADE_WINDOW 1` when it also has
// kFeatureBladeWindow, and `#define GRASS_BLADE_COMPACT 1` with it where `compact`: the
// compacted window variant), `#define GRASS_HOST_SHADOWS 1` when it has kFeatureShadowReceive,
// `#define GRASS_VELOCITY 1` when it has kFeatureMotion, `#define GRASS_HOST_LIGHTS 1` when
// it has kFeatureHostLights). On failure the driver's log is in the context's error message
// (named after `function`) and nothing is left behind.
grass_result create_program(grass_context* ctx, const GlFunctions& gl, const char* function, GlProgramKind kind,
                            uint32_t features, bool compact, GLuint* out_program);

// Points the sampler uniforms of `program` at their texture units (after linking, and after
// glProgramBinary, which resets every uniform).
void set_sampler_units(const GlFunctions& gl, GLuint program);

// FNV-1a 64 over every embedded shader source: a program binary saved with other sources is
// not loaded (gl_program_cache.hpp).
uint64_t shader_sources_hash();

// Compiles and links the blade window pass for the feature mask `features` (within
// kBladeWindowPassFeatures; it has kFeatureWind or kFeatureInteraction), likewise.
grass_result create_blade_window_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                         uint32_t features, GLuint* out_program);
// The compaction pass of blade_compaction.comp for `features` (kBladeWindowPassFeatures and
// kFeatureBladeCulling of the draw it compacts).
grass_result create_blade_compaction_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                             uint32_t features, GLuint* out_program);

// Compiles and links the interaction pass (interaction.comp), likewise.
grass_result create_interaction_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                        GLuint* out_program);

} // namespace grass
