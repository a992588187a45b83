// A minimal headless host: what an engine does around grass, without a window. It owns
// the device (EGL/OSMesa GL 4.5 context or a lavapipe Vulkan device with the validation
// layers on), an offscreen colour + depth target, and the frame. Used by grass-render and
// by the rendering tests. It talks to grass only through the public C headers.
#pragma once

#include <grass/grass.h>
#include <grass/grass_vk.h>

#include "host_mesh.hpp"
#include "mesh_draw.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace grass_host {

// The host's own cascaded sun shadows (light_cascades.hpp): each frame the host fits
// `cascades` orthographic views of the sun around slices of the main camera's frustum, draws
// its meshes' depth and grass's depth views (GRASS_PASS_DEPTH, their lod origin the main
// camera) into a 2D-array depth map, then draws the main view with its ground and meshes
// sampling the map and grass receiving it (grass_shadow_receive_desc). One grass frame:
// grass_begin_frame(main view), grass_plan_view of each cascade. Standard depth only (not
// with reversed_z or gl_clip_zero_to_one); single-sampled or multisampled targets alike.
struct HostShadows {
    uint32_t cascades = 0;                          // 0: off; 1 to GRASS_MAX_SHADOW_CASCADES
    uint32_t map_size = 512;                        // texels a side of each cascade's layer
    float splits[4] = {6.0f, 15.0f, 40.0f, 100.0f}; // where cascade i ends, metres along the view axis
    float caster_reach = 30.0f;                     // metres the light's near plane lies beyond a slice (tall casters)
    // Grass's depth views: glPolygonOffset / vkCmdSetDepthBias (grass_view_pass_desc).
    float grass_bias_constant = 2.0f;
    float grass_bias_slope = 1.5f;
    // The host's meshes cast with this offset (constant, slope) too.
    float mesh_bias_constant = 2.0f;
    float mesh_bias_slope = 1.5f;
    float grass_receive_bias = 0.008f; // grass_shadow_receive_desc.depth_bias (depth units)
    float host_receive_bias = 0.0005f; // the ground's and meshes' bias (depth units)
    float filter_radius = 1.0f;        // texels: grass's and the host's PCF
};

struct TargetDesc {
    uint32_t width = 256;
    uint32_t height = 256;
    uint32_t samples = 1;                               // 1 or 4 (multisampled target, resolved for read-back)
    float clear_color[4] = {0.55f, 0.70f, 0.90f, 1.0f}; // linear RGB sky
    bool vk_dynamic_rendering = false;                  // Vulkan: dynamic rendering instead of a render pass
    // A linear float colour target (GL_RGBA32F / VK_FORMAT_R32G32B32A32_SFLOAT) instead of
    // sRGB RGBA8: the shaders' output is stored unclamped, so NaN and infinity survive to the
    // read-back (Image::rgba_f32). For tests; use samples = 1 (blending is off either way).
    bool float_color = false;
    // The host's own terrain: a flat ground at world height 0 under the grass, drawn before
    // grass like an engine's scene. Off for tests that count sky pixels.
    bool ground = false;
    float ground_color[3] = {0.045f, 0.036f, 0.018f}; // linear albedo: dark soil
    // The host's depth convention. reversed_z: depth 1 is near: the projection maps the near
    // plane to 1, the host clears depth to 0 and tests GREATER (give grass GRASS_DEPTH_GREATER).
    bool reversed_z = false;
    // GL: glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) while the frame draws, and projections
    // with clip z 0..1 (Vulkan's convention; Vulkan hosts ignore this: they always have it).
    bool gl_clip_zero_to_one = false;
    // An 8-bit UNORM colour target (GL_RGBA8 / VK_FORMAT_R8G8B8A8_UNORM) instead of sRGB: it
    // stores what the shaders write. The host encodes its clear and occluder colours to sRGB
    // itself, as an engine without sRGB targets does (the ground is not encoded: leave it
    // off). Pair it with GRASS_VIEW_FLAG_ENCODE_SRGB.
    bool unorm_color = false;
    // The host's own scene: meshes drawn before grass, Lambert + ambient under the view's
    // sun, into the colour and depth grass draws over (see host_mesh.hpp).
    std::vector<HostMesh> meshes;
    // Reads the depth buffer back too (Image::depth); single-sampled targets only (Vulkan:
    // with a render pass, not dynamic rendering). For tests that measure heights.
    bool read_depth = false;
    // Vulkan: a depth-only render pass over the depth image besides (single-sampled, with
    // read_depth), given to grass as its grass_vk_depth_pass_desc; Host::depth_only draws in it.
    bool vk_depth_pass = false;
    // Vulkan: motion vectors' target (extra_targets_vk.hpp): 0 none; 1 or 2 an RGBA32F
    // velocity image at that colour attachment of the pass (2: an RGBA8 image at attachment 1
    // besides), cleared to velocity_clear and other_clear, read back into Image::velocity and
    // Image::other, given to grass as its grass_vk_velocity_target_desc. Single-sampled, with
    // a render pass; no ground nor meshes (their pipelines have one colour attachment).
    uint32_t vk_velocity_attachment = 0;
    float velocity_clear[4] = {};
    float other_clear[4] = {};
    // Vulkan: a G-buffer target (extra_targets_vk.hpp): the VkFormat values of up to 3
    // colour attachments after the host's colour (attachment 0), 0 after the last; each
    // cleared to gbuffer_clear[i], read back into Image::gbuffer[i] as stored, given to grass
    // as its grass_vk_gbuffer_target_desc. With vk_velocity_attachment besides, that
    // attachment (an RGBA32F one) is the velocity target too (Image::velocity). Any sample
    // count (multisampled: each resolved, the resolve read back), a render pass or dynamic
    // rendering; no ground nor meshes.
    uint32_t vk_gbuffer_formats[3] = {};
    float gbuffer_clear[3][4] = {};
    // The host's cascaded sun shadows (off by default).
    HostShadows host_shadows;
    // Vulkan: the vkGetInstanceProcAddr the host hands grass (grass_vk_desc's
    // get_instance_proc_addr); nullptr: the loader's own. Tests pass a wrapper that counts
    // handles or makes a call fail, for grass's dispatch table only.
    grass_vk_get_instance_proc_addr_fn vk_get_instance_proc_addr = nullptr;
    // Vulkan: grass_vk_host_objects_desc::allocation_callbacks (a const VkAllocationCallbacks*); grass only.
    const void* vk_allocation_callbacks = nullptr;
    // Vulkan: the host makes a VkPipelineCache of its own and hands it to grass
    // (grass_vk_host_objects_desc.pipeline_cache); Host::vk_pipeline_cache() names it.
    bool vk_host_pipeline_cache = false;
    // GL: given each GL entry point grass asks the host's loader for (its name and the real
    // one), returns the one grass gets; nullptr: the real ones. For fault-injection tests.
    void (*(*gl_proc_filter)(const char* name, void (*real)(void)))(void) = nullptr;
};

// A Vulkan host's perspective projection (clip y down, z 0..1, or 1..0 with `reversed_z`),
// column-major.
void vk_projection(float fovy_radians, float aspect, float near_m, float far_m, bool reversed_z, float out[16]);

// Linear to sRGB-encoded, 0..1 (clamped).
float linear_to_srgb(float linear);
// The target's clear colour as its colour image stores it (encoded where unorm_color).
void stored_clear_color(const TargetDesc& target, float out[4]);

// An opaque camera-facing rectangle the host draws into its own colour and depth before
// grass draws: a box face `distance` metres in front of the camera. Pixel rectangle with
// the origin at the top-left of the image, x1/y1 exclusive.
struct Occluder {
    int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    float distance = 1.0f;               // metres along the view axis
    float color[3] = {0.8f, 0.1f, 0.1f}; // linear RGB
};

struct Image {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba; // sRGB-encoded RGBA8, top row first
    // Float targets only (TargetDesc::float_color): the linear RGBA floats as stored, top row
    // first; `rgba` then holds them clamped to 0..1 and sRGB-encoded (NaN as 0), so the
    // 8-bit helpers and PNG output work on either target.
    std::vector<float> rgba_f32;
    // TargetDesc::read_depth: the window depth (0..1 as the host's convention stores it) of
    // each pixel, top row first; empty otherwise.
    std::vector<float> depth;
    // TargetDesc::vk_velocity_attachment: the velocity image's RGBA floats, and the other
    // colour image's RGBA8 (attachment 2 only), top row first; empty otherwise.
    std::vector<float> velocity;
    std::vector<uint8_t> other;
    // TargetDesc::vk_gbuffer_formats: each further attachment's texels as stored, top row first.
    std::vector<std::vector<uint8_t>> gbuffer;
    const uint8_t* pixel(uint32_t x, uint32_t y) const { return &rgba[(size_t(y) * width + x) * 4]; }
    const float* pixel_f32(uint32_t x, uint32_t y) const { return &rgba_f32[(size_t(y) * width + x) * 4]; }
};

class Host {
public:
    virtual ~Host() = default;

    // GRASS_BACKEND_GL (EGL surfaceless, falling back to OSMesa) or GRASS_BACKEND_VULKAN
    // (lavapipe or any Vulkan device, validation layers on when installed). nullptr and
    // *error set when the device cannot be had.
    static std::unique_ptr<Host> create(grass_backend backend, const TargetDesc& target, std::string* error);

    virtual grass_backend backend() const = 0;
    // The device's name as its driver gives it.
    virtual std::string device_name() const { return device_name_; }
    const TargetDesc& target() const { return target_; }

    // Creates a grass context on this host's device.
    virtual grass_result create_context(const grass_context_desc& desc, grass_context** out) = 0;

    // The host's projection for its clip-space convention (GL: z -1..1, y up; Vulkan:
    // z 0..1, y down), column-major. Both give the same picture.
    virtual void projection(float fovy_radians, float aspect, float near_m, float far_m, float out[16]) const = 0;

    // Renders one frame: clear, the occluder if given, grass_begin_frame(view), the
    // backend's draw, grass_end_frame, then reads the resolved colour back. Returns the
    // first failing grass_result (or GRASS_ERROR_BACKEND for a host-side failure with
    // *error set).
    virtual grass_result render(grass_context* context, const grass_view_desc& view, const Occluder* occluder,
                                Image* out, std::string* error) = 0;

    // Vulkan: messages the validation layers printed (warnings and errors) since creation.
    // GL: GL debug-output errors. 0 when silent.
    virtual uint32_t validation_messages() const { return messages_; }
    // Moves the target's mesh `index` (TargetDesc::meshes) to a new world origin from the
    // next render on: a host object that moves (a ball that rolls).
    // Hosts without meshes ignore it.
    void move_mesh(size_t index, const double origin[3]) {
        if (movable_meshes_) movable_meshes_->set_origin(index, origin);
    }
    virtual std::string validation_log() const { return log_; }
    // Vulkan hosts with TargetDesc::vk_host_pipeline_cache: the VkPipelineCache given to
    // grass (a non-dispatchable handle); 0 otherwise.
    virtual uint64_t vk_pipeline_cache() const { return 0; }

    // GL hosts: the address of a GL entry point in the host's context, which stays current
    // on the creating thread (for tests that inspect GL state). Others return nullptr.
    virtual void* gl_proc_address(const char* name) const {
        (void)name;
        return nullptr;
    }

    // Vulkan hosts: a cascaded shadow map for grass_shadow_receive_desc (shadow_map_vk.hpp): a
    // D32_SFLOAT 2D array of `layers` layers of `size` x `size` depths, depths[(layer * size
    // + row) * size + column], left in `vk_layout` (a VkImageLayout). Its VkImageView, or 0
    // with *error set; it replaces the host's previous map. GL hosts return 0.
    virtual uint64_t make_vk_shadow_map(uint32_t size, uint32_t layers, const float* depths, uint32_t vk_layout,
                                        std::string* error) {
        (void)size, (void)layers, (void)depths, (void)vk_layout, (void)error;
        return 0;
    }

    // GL hosts: called in render() right before grass_begin_frame (after the clear, the
    // ground and the occluder) and right after grass_end_frame (before the read-back), for
    // tests of the GL state grass draws under and leaves. Vulkan hosts do not call them.
    std::function<void()> before_grass;
    std::function<void()> after_grass;

    // Tests of frames and views (FrameViewsTest): when set, render() calls begin_grass_frame
    // in place of grass_begin_frame(view), and draw_grass in place of grass_gl_render /
    // grass_vk_record (Vulkan: inside the pass, with the command buffer; GL: nullptr);
    // grass_vk_prepare and grass_end_frame as usual. `view` still draws the host's ground and
    // meshes.
    std::function<grass_result(grass_context*)> begin_grass_frame;
    std::function<grass_result(grass_context*, void* command_buffer)> draw_grass;
    // Vulkan hosts with TargetDesc::vk_depth_pass: render() draws grass in the depth-only pass
    // (no colour attachment, no ground or meshes; the colour image is cleared outside it, so
    // it reads back as cleared). GL hosts ignore it: a GL depth pass draws into the colour and
    // depth framebuffer with its colour masks off.
    bool depth_only = false;
    // TargetDesc::host_shadows: what takes part, for tests that compare with a part left out.
    // grass_casts: grass's depth views are drawn into the cascades; grass_receives: the main
    // view chains grass_shadow_receive_desc; host_casts: the meshes draw into the cascades;
    // host_receives: the ground and meshes sample the map. All off: the frame of a host
    // without shadows (grass_begin_frame(view) alone).
    struct ShadowParts {
        bool grass_casts = true, grass_receives = true, host_casts = true, host_receives = true;
        bool any() const { return grass_casts || grass_receives || host_casts || host_receives; }
    } shadow_parts;

protected:
    explicit Host(const TargetDesc& target) : target_(target) {}
    // One validation message (a line, without its newline): counted and logged.
    void add_validation_message(const std::string& line) {
        messages_ += 1;
        log_ += line;
        log_ += '\n';
    }
    TargetDesc target_;
    std::string device_name_;                 // set by the host's init
    MovableMeshes* movable_meshes_ = nullptr; // the host's mesh drawer (TargetDesc::meshes), if any
    uint32_t messages_ = 0;
    std::string log_;
};

// Fills image->rgba from image->rgba_f32 (linear floats): clamped, sRGB-encoded RGB, alpha
// linear; NaN becomes 0. Used by the hosts for float targets.
void encode_float_image(Image* image);

// Builds a look-at view (rotation only is used by grass) and a default view desc with this
// host's projection for the target's aspect.
grass_view_desc make_view(const Host& host, const double eye[3], const double target[3], float fovy_degrees,
                          float near_m = 0.05f, float far_m = 500.0f);

} // namespace grass_host
