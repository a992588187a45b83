// The tests' OSG host: an osgViewer::Viewer on an osgViewer::GraphicsWindowEmbedded around
// the test's EGL context, drawing into its framebuffer (setDefaultFboId), and the OSG
// models the tests stand in the grass.
#pragma once

#include "osg_headless.hpp"

#include <grass_osg/field_drawable.hpp>

#include <gtest/gtest.h>
#include <osg/Geode>
#include <osgViewer/Viewer>

namespace grass_osg_test {

// A linear sky, as the headless host clears to.
constexpr float kSky[3] = {0.55f, 0.70f, 0.90f};

class OsgHost {
public:
    // GTEST_SKIPs the calling test when the device cannot be had.
    explicit OsgHost(const TargetFormat& format, std::string* error);
    ~OsgHost();
    bool ok() const { return target_ != nullptr; }

    // A fixed perspective camera (no near/far computation) looking from eye at target,
    // y up, or OSG's default near/far computation from the bounds when compute_near_far.
    void look(const osg::Vec3d& eye, const osg::Vec3d& target, double fovy_degrees, bool compute_near_far = false);
    // Clears to `linear` (encoded to sRGB for the target: the camera's clear colour is sRGB
    // bytes on a UNORM target, linear with GL_FRAMEBUFFER_SRGB on an sRGB one).
    void clear_to(const float linear[3]);
    // One viewer.frame() with `scene`, read back.
    grass_host::Image frame(osg::Node* scene);
    osgViewer::Viewer& viewer() { return *viewer_; }
    unsigned int context_id() const;
    GlTarget& target() { return *target_; }
    // What OSG must output for a pixel to store `linear`'s sRGB bytes on this target: the
    // encoded colour on a UNORM target, the linear one on an sRGB target (which the test
    // host keeps GL_FRAMEBUFFER_SRGB on for, unknown to OSG).
    osg::Vec4 colour(const float linear[3]) const;

private:
    std::unique_ptr<GlTarget> target_;
    osg::ref_ptr<osgViewer::Viewer> viewer_;
};

// The test field: `cells` x `cells` cells of 0.25 m from the origin, y up.
grass_osg::FieldDesc field_desc(uint32_t cells);
osg::ref_ptr<grass_osg::FieldDrawable> field_drawable(const grass_osg::FieldDesc& desc);

// An unlit box of one colour (OsgHost::colour) in OSG render bin `bin` (0: opaque, before
// grass; 20: after grass).
osg::ref_ptr<osg::Geode> box(const osg::Vec3& centre, const osg::Vec3& size, const osg::Vec4& colour, int bin = 0);
// A ground quad at y = 0 from (-1, -1) to (size - 1, size - 1) in x and z, unlit.
osg::ref_ptr<osg::Geode> ground(float size, const osg::Vec4& colour);
// Models that use more of OSG's state than a colour: a lit sphere (material, light), a
// textured quad and a box drawn by a GLSL program; the last two after grass (bin 20).
osg::ref_ptr<osg::Group> busy_models();

// Linear colour to the bytes an 8-bit sRGB or sRGB-encoded UNORM target stores.
void expected_bytes(const float linear[3], uint8_t out[3]);
bool near_colour(const uint8_t* pixel, const uint8_t expected[3], int tolerance);
// Green dominates, and it is neither the sky nor the soil: a grass pixel.
bool is_grass(const uint8_t* pixel);

} // namespace grass_osg_test
