// The tests' GL device: an EGL surfaceless context with the compatibility profile that
// Debian's OSG needs (GL 4.5), and a test-owned framebuffer OSG draws into through
// GraphicsContext::setDefaultFboId. No OSG here: this file talks GL and EGL only.
#pragma once

#include <headless_host.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace grass_osg_test {

struct TargetFormat {
    uint32_t width = 128, height = 128;
    uint32_t samples = 1; // 1 or 4
    bool srgb = false;    // GL_SRGB8_ALPHA8 instead of GL_RGBA8
};

class GlTarget {
public:
    // Makes the context current and its framebuffer complete; nullptr and *error if not.
    static std::unique_ptr<GlTarget> create(const TargetFormat& format, std::string* error);
    ~GlTarget();

    void make_current();
    const TargetFormat& format() const { return format_; }
    // The framebuffer OSG draws into (multisampled when samples > 1).
    unsigned framebuffer() const { return draw_fbo_; }
    // The colour as stored (resolved when multisampled), top row first. Leaves
    // GL_FRAMEBUFFER_SRGB and the framebuffer bindings as it found them.
    grass_host::Image read();

    struct Impl;

private:
    GlTarget() = default;
    TargetFormat format_;
    unsigned draw_fbo_ = 0, resolve_fbo_ = 0, renderbuffers_[3] = {0, 0, 0};
    std::unique_ptr<Impl> impl_;
};

// Writes `image` to GRASS_OSG_TEST_OUT/<name>.png for a human to look at (failures ignored).
void save(const grass_host::Image& image, const std::string& name);

} // namespace grass_osg_test
