// grass-deferred's velocity frame, the same in both halves (velocity.hpp): the previous camera,
// the gust, the ground's matrices, the checks of the read-back attachment and its picture.
#include "velocity.hpp"

#include "image_io.hpp"
#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace deferred {

namespace {

// Column-major 4 x 4 matrix times (x, y, z, 1).
void transform(const float m[16], const double p[3], double out[4]) {
    for (int r = 0; r < 4; ++r) out[r] = m[12 + r] + m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2];
}

// World -> clip of a camera at `eye` with rotation `view` and `projection`: the camera-relative
// view-projection (scene.hpp) after the translation by -eye.
void world_to_clip_of(const double eye[3], const float view[16], const float projection[16], float out[16]) {
    grass_view_desc v{};
    std::memcpy(v.view, view, sizeof(v.view));
    std::memcpy(v.projection, projection, sizeof(v.projection));
    view_projection(v, out);
    for (int r = 0; r < 4; ++r) out[12 + r] -= float(out[r] * eye[0] + out[4 + r] * eye[1] + out[8 + r] * eye[2]);
}

struct Chained { // the head every grass extension struct starts with
    grass_struct_type type;
    const void* next;
};

// The pixels of one frame, top row first.
const float* texel(const VelocityImage& image, uint32_t x, uint32_t y) {
    return &image.rgba[(size_t(y) * kWidth + x) * 4];
}
bool is_ground(const float* t) { return t[2] > 0.5f && t[3] > 0.5f; } // the ground writes b = a = 1
bool is_grass(const float* t) { return t[2] < 0.5f && t[3] > 0.5f; }  // grass writes rgb over the ground's

// The velocity (`now` and `before` from ground_matrices) of the ground seen through the centre
// of pixel (x, row) (top row first) of `view`, were nothing in front of it; false above the
// horizon. Its ray: (ndc x / P00, ndc y / P11, -1) in view space, rotated to the world.
bool ground_velocity_at(const grass_view_desc& view, const float now[16], const float before[16], uint32_t x,
                        uint32_t row, bool y_down, double out[2]) {
    const double nx = 2.0 * (x + 0.5) / kWidth - 1.0, ny_down = 2.0 * (row + 0.5) / kHeight - 1.0;
    const double ray_view[3] = {nx / view.projection[0], (y_down ? ny_down : -ny_down) / view.projection[5], -1.0};
    double ray[3];
    for (int k = 0; k < 3; ++k)
        ray[k] =
            view.view[4 * k] * ray_view[0] + view.view[4 * k + 1] * ray_view[1] + view.view[4 * k + 2] * ray_view[2];
    if (ray[1] >= 0.0) return false;
    const double t = -view.camera_position[1] / ray[1];
    const double p[3] = {view.camera_position[0] + t * ray[0], 0.0, view.camera_position[2] + t * ray[2]};
    double c[4], b[4];
    transform(now, p, c);
    transform(before, p, b);
    out[0] = (c[0] / c[3] - b[0] / b[3]) * 0.5;
    out[1] = (c[1] / c[3] - b[1] / b[3]) * 0.5;
    return true;
}

} // namespace

grass_wind_desc gust_wind() {
    grass_wind_desc wind = grass_default_wind_desc(); // along (1, 0, 0.3)
    wind.speed = 20.0f;
    wind.gust_strength = 4.0f;
    wind.turbulence = 1.0f;
    return wind;
}

grass_view_motion_desc pan_motion(const grass_host::Host& host, bool wind_moves) {
    const double eye[3] = {kEye[0] - kPan, kEye[1], kEye[2]}, at[3] = {kAt[0] - kPan, kAt[1], kAt[2]};
    const grass_view_desc previous = grass_host::make_view(host, eye, at, kFovy, kNear, kFar);
    grass_view_motion_desc motion = grass_default_view_motion_desc();
    std::memcpy(motion.previous_camera_position, previous.camera_position, sizeof(motion.previous_camera_position));
    std::memcpy(motion.previous_view, previous.view, sizeof(motion.previous_view));
    std::memcpy(motion.previous_projection, previous.projection, sizeof(motion.previous_projection));
    motion.previous_time = wind_moves ? kPreviousTime : kTime;
    motion.velocity_attachment = 3;
    return motion;
}

void ground_matrices(const grass_view_desc& view, float world_to_clip[16], float world_to_previous_clip[16]) {
    world_to_clip_of(view.camera_position, view.view, view.projection, world_to_clip);
    std::memcpy(world_to_previous_clip, world_to_clip, 16 * sizeof(float));
    for (const void* p = view.next; p; p = static_cast<const Chained*>(p)->next) {
        if (static_cast<const Chained*>(p)->type != GRASS_STRUCT_TYPE_VIEW_MOTION_DESC) continue;
        const auto* motion = static_cast<const grass_view_motion_desc*>(p);
        world_to_clip_of(motion->previous_camera_position, motion->previous_view, motion->previous_projection,
                         world_to_previous_clip);
    }
}

int check_and_write_velocity(const grass_view_desc& view, const VelocityImage& still, const VelocityImage& gust,
                             const std::string& out_path) {
    const size_t texels = size_t(kWidth) * kHeight * 4;
    if (still.rgba.size() != texels || gust.rgba.size() != texels) {
        std::fprintf(stderr, "the velocity read-back holds %zu and %zu floats, not %zu\n", still.rgba.size(),
                     gust.rgba.size(), texels);
        return 1;
    }
    // 1. The ground at points of y = 0 every half metre: its velocity where it is seen.
    float now[16], before[16];
    ground_matrices(view, now, before);
    long ground_points = 0, ground_wrong = 0;
    double worst = 0.0;
    for (double x = -40.0; x <= 56.0; x += 0.5) {
        for (double z = -40.0; z <= 56.0; z += 0.5) {
            const double p[3] = {x, 0.0, z};
            double c[4], b[4];
            transform(now, p, c);
            transform(before, p, b);
            if (c[3] < kNear || b[3] < kNear) continue;
            const double nx = c[0] / c[3], ny = c[1] / c[3];
            const double px = (nx * 0.5 + 0.5) * kWidth, py = (ny * 0.5 + 0.5) * kHeight;
            if (px < 0.0 || py < 0.0 || px >= kWidth || py >= kHeight) continue;
            const uint32_t row = gust.y_down ? uint32_t(py) : kHeight - 1 - uint32_t(py);
            const float* t = texel(still, uint32_t(px), row);
            if (!is_ground(t)) continue;
            const double expected[2] = {(nx - b[0] / b[3]) * 0.5, (ny - b[1] / b[3]) * 0.5};
            ground_points += 1;
            for (int k = 0; k < 2; ++k) {
                const double error = std::fabs(t[k] - expected[k]);
                worst = std::max(worst, error);
                if (error > 0.02 * std::fabs(expected[k]) + 1e-4) ground_wrong += 1;
            }
        }
    }
    // 2. Grass without the wind's motion (the pan alone), 3. what the gust adds.
    // 2. also, grass lies between the camera and the ground behind it: with the pan alone, its
    // vx over that ground's vx (the same sideways pan: 1 / depth) is at least 1, and at most 1.5
    // (blades under 0.47 m for the camera's 1.4 m; seen 0.991 to 1.139).
    long grass = 0, ground = 0, grass_at_depth = 0;
    double lowest_ratio = 1e9, highest_ratio = 0.0;
    double sum_vx = 0.0, sum_abs_vx = 0.0, sum_abs_vy = 0.0, gust_added = 0.0, ground_changed = 0.0, ground_vx = 0.0;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const float *s = texel(still, x, y), *g = texel(gust, x, y);
            const double change = std::hypot((g[0] - s[0]) * kWidth, (g[1] - s[1]) * kHeight); // pixels
            if (is_grass(s)) {
                grass += 1;
                sum_vx += s[0];
                sum_abs_vx += std::fabs(s[0]);
                sum_abs_vy += std::fabs(s[1]);
                gust_added += change;
                double expected[2];
                if (ground_velocity_at(view, now, before, x, y, still.y_down, expected)) {
                    const double ratio = s[0] / expected[0];
                    lowest_ratio = std::min(lowest_ratio, ratio);
                    highest_ratio = std::max(highest_ratio, ratio);
                    grass_at_depth += ratio > 0.98 && ratio < 1.5 ? 1 : 0;
                }
            } else if (is_ground(s)) {
                ground += 1;
                ground_vx += s[0];
                ground_changed = std::max(ground_changed, change);
            }
        }
    }
    const double pixels = double(kWidth) * kHeight;
    std::printf("ground: %ld points checked, %ld components off (worst %.2e viewport units); %ld ground and %ld "
                "grass pixels; without the wind's motion grass moves %.3f px in x, mean |vx| %.3f px, mean |vy| "
                "%.4f px, %.2f%% of its pixels between the ground's and 1.5 times it (ratios %.3f to %.3f); the gust "
                "adds a mean %.3f px on grass, at most %.2e px on the ground\n",
                ground_points, ground_wrong, worst, ground, grass, grass ? sum_vx / grass * kWidth : 0.0,
                grass ? sum_abs_vx / grass * kWidth : 0.0, grass ? sum_abs_vy / grass * kHeight : 0.0,
                grass ? 100.0 * grass_at_depth / grass : 0.0, lowest_ratio, highest_ratio,
                grass ? gust_added / grass : 0.0, ground_changed);
    bool ok = true;
    const auto fail = [&ok](const char* what) {
        std::fprintf(stderr, "velocity: %s\n", what);
        ok = false;
    };
    if (ground_points < 200 || ground_wrong != 0) fail("the ground's velocity is not its camera motion");
    if (grass * 10 < long(pixels) || ground * 20 < long(pixels)) fail("too few grass or ground pixels");
    if (grass && (sum_abs_vy * kHeight > 0.02 * sum_abs_vx * kWidth || sum_vx * ground_vx <= 0.0))
        fail("the pan alone does not move grass sideways with the ground");
    if (grass_at_depth < grass * 99 / 100) fail("the pan alone does not move grass as its depth does");
    if (grass && (gust_added / grass < 0.1 || ground_changed > 1e-6)) fail("the gust does not move grass alone");

    // The picture of the gust frame (velocity.hpp's colours).
    grass_host::Image picture;
    picture.width = kWidth;
    picture.height = kHeight;
    picture.rgba.resize(size_t(kWidth) * kHeight * 4);
    const auto level = [](double v) { return uint8_t(std::clamp(128.0 + v * kLevelsPerPixel, 0.0, 255.0) + 0.5); };
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const float* t = texel(gust, x, y);
            uint8_t* c = &picture.rgba[(size_t(y) * kWidth + x) * 4];
            const bool covered = t[3] > 0.5f;
            c[0] = covered ? level(t[0] * kWidth) : 0;
            c[1] = covered ? level((gust.y_down ? -t[1] : t[1]) * kHeight) : 0;
            c[2] = is_ground(t) ? 192 : covered ? 128 : 0;
            c[3] = 255;
        }
    }
    std::string error;
    if (!grass_host::write_png(out_path, picture, &error)) fail(("cannot write the picture: " + error).c_str());
    std::printf("wrote %s\n", out_path.c_str());
    return ok ? 0 : 1;
}

} // namespace deferred
