// Rendering tests run in both backends through the headless hosts. Each test gets a fresh
// host, a context and the default patch; Vulkan tests fail if the validation layers said
// anything. Images of failing tests go to GRASS_TEST_IMAGE_DIR for a look.
#pragma once

#include <grass/grass.h>
#include <grass/grass_gl.h>
#include <grass/grass_vk.h>

#include "headless_host.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace grass_test {

std::string backend_name(grass_backend b);
// The backends this build has hosts for.
std::vector<grass_backend> enabled_backends();

class RenderTest : public ::testing::TestWithParam<grass_backend> {
protected:
    void SetUp() override;
    void TearDown() override;

    // Makes the host, the context and the default patch (call again to change the target), on
    // `backend` (GRASS_BACKEND_NONE: the test's parameter).
    void start(const grass_host::TargetDesc& target, grass_backend backend = GRASS_BACKEND_NONE);
    grass_field_id make_field(grass_field_desc d);
    // A square field of the default patch drawn by one geometry tier (blades) out to 60 m:
    // the tests of the blade tier's behaviour. Tests of the other tiers set their own.
    grass_field_desc field_desc(uint32_t cells) const;
    // A square field drawn by one tier alone at every distance, in macro-cells of up to
    // `max_macro_cells` (volume and image tiers).
    grass_field_desc solo_tier_field(uint32_t cells, grass_tier_kind kind, uint32_t slices, uint32_t max_macro_cells);
    // A square field of three tiers by distance from the lod origin: geometry 0-3 m (fading
    // out over its last metre), a volume of 2 slices 2-7 m (fading in over 1 m, out over
    // 1.5 m), the horizontal slice from 5.5 m (fading in over 1.5 m).
    grass_field_desc three_tier_field(uint32_t cells);
    grass_view_desc view(const double eye[3], const double target[3], float fovy_degrees = 50.0f) const;
    grass_host::Image render(const grass_view_desc& v, const grass_host::Occluder* occluder = nullptr);
    void save(const grass_host::Image& image, const std::string& tag) const;

    // Sub-pixel camera motion (FarFromOriginTest, ExtremesTest): a field of cells x cells of
    // the blade tier (8 x 8: 2 m x 2 m) with its corner at (ox, 0, oz), seen from `height` m
    // above its centre looking straight down (50 degree fov); the camera moves `step_m` along
    // +x, `steps` times. The field is destroyed afterwards.
    struct CameraSteps {
        std::vector<grass_host::Image> frames;       // steps + 1
        std::vector<double> shift;                   // grass centroid (px) minus the first frame's
        double slope = 0.0;                          // px per step, least-squares through zero (< 0: the
                                                     // grass moves left as the camera moves right)
        double px_per_step = 0.0;                    // |slope|
        double expected_lo = 0.0, expected_hi = 0.0; // px per step for the ground .. the tallest blades
    };
    CameraSteps step_camera(double ox, double oz, int steps, double step_m, double height = 3.0, uint32_t cells = 8);

    std::unique_ptr<grass_host::Host> host;
    grass_context* ctx = nullptr;
    const void* context_next = nullptr; // chained to the context desc by start() (a debug labels desc)
    grass_patch_id patch{};
    std::string log;
    grass_tier_desc blade_tier{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test blade_band{};
    grass_tier_desc solo_tier{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test solo_tests[2] = {};
    grass_tier_desc three_tiers[3] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 2}, {GRASS_TIER_IMAGE, 0}};
    grass_lod_test three_tier_bands[3] = {};
};

// A 128 x 128 target with 4 samples, cleared to black or to white and nothing else: the
// grass rendered over both separates its coverage from its colour (TierLightingTest).
grass_host::TargetDesc black_or_white_target(bool white);
// The clear colour as the hosts write it (linear -> sRGB 8-bit).
void expected_sky(const grass_host::TargetDesc& t, uint8_t out[3]);
// A pixel differs from the sky by more than `tolerance` levels in some channel.
bool is_grass(const uint8_t* pixel, const uint8_t sky[3], int tolerance = 6);
// A square field of `cells` x `cells` cells of `patch`, drawn by one geometry tier (blades)
// out to 60 m.
grass_result create_blade_field(grass_context* ctx, grass_patch_id patch, uint32_t cells, grass_field_id* out);
// Called before each frame of render_default_scene: may set the wind, colliders and so on,
// and change the view (its time).
using SceneFrame = std::function<void(grass_context* ctx, int frame, grass_view_desc* view)>;
// `frames` frames (the last one returned) of the default patch on a square field of
// `cells` cells, rendered by a fresh host of `backend`, from `eye` towards `look` (50
// degree fov). Fails the calling test on any error or validation message; empty image then.
// `field_setup`, when given, is called once with the field after it is made (a wind map).
using FieldSetup = std::function<void(grass_context* ctx, grass_field_id field)>;
grass_host::Image render_default_scene(grass_backend backend, const grass_host::TargetDesc& target, uint32_t cells,
                                       const double eye[3], const double look[3], int frames = 1,
                                       const SceneFrame& before_frame = nullptr,
                                       const FieldSetup& field_setup = nullptr);
// Centre of the grass along x, weighted by how far each pixel is from the sky colour, in pixels.
double grass_centroid_x(const grass_host::Image& image, const uint8_t sky[3]);
// Mean absolute difference of the RGB channels, in 8-bit levels.
double mean_difference(const grass_host::Image& a, const grass_host::Image& b);
// Share of pixels whose largest RGB channel difference is over `levels` (1 when the sizes
// differ): with mean_difference, BackendAgreement's single-sampled measure (0.05 levels, 0.05%
// of pixels over 32).
double share_apart(const grass_host::Image& a, const grass_host::Image& b, int levels);
// Where a world point appears in an image of `width` x `height` rendered through
// view(eye, target, fovy_degrees) (grass_host::make_view's camera): pixel coordinates, x to
// the right and y down from the top-left corner (a pixel's centre at +0.5). False when the
// point is behind the camera.
// The camera basis of grass_host::make_view: forward f, right r = f x up, up u = r x f (unit).
void look_at_basis(const double eye[3], const double target[3], double f[3], double r[3], double u[3]);
bool project_point(const double eye[3], const double target[3], float fovy_degrees, uint32_t width, uint32_t height,
                   const double point[3], double* out_x, double* out_y);
// A patch like the football field's turf (dense, short and thin blades: the slices are nearly
// opaque, so no clear colour shows), with 1200 blades a cell so that the blades everywhere
// render in seconds (MoireTest, TierBoundaryTest). Failures go to `log`'s test expectations.
grass_patch_id create_turf_patch(grass_context* ctx, uint64_t seed, std::string* log);
// Share of pixels in [x0, x1) x [y0, y1) that are grass.
double grass_share(const grass_host::Image& image, const uint8_t sky[3], uint32_t x0, uint32_t y0, uint32_t x1,
                   uint32_t y1);
// The share of `image` (rendered into `target`) that is grass, which must be at least
// `min_share`: comparisons of two images prove nothing when both are all sky.
double expect_grass(const grass_host::Image& image, const grass_host::TargetDesc& target, double min_share,
                    const char* what);

} // namespace grass_test
