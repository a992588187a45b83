// Grass in OSG's shadows: under osgShadow::ViewDependentShadowMap a box's shadow darkens the
// grass (grass receives VDSM's map), and the grass's shadow darkens OSG's ground beside the
// field (grass casts into it). Each check compares the same pixels in a control frame
// without the caster, and checks that those pixels show what they should (grass, ground).
#include "osg_scene.hpp"

#include <osg/LightSource>
#include <osgShadow/ShadowMap>
#include <osgShadow/ShadowedScene>
#include <osgShadow/ViewDependentShadowMap>

#include <cmath>
#include <cstdio>

namespace grass_osg_test {
namespace {

constexpr unsigned kReceives = 0x1, kCasts = 0x2;

class VdsmShadowTest : public ::testing::Test {
protected:
    void SetUp() override {
        TargetFormat format;
        format.width = format.height = 256;
        std::string error;
        host.reset(new OsgHost(format, &error));
        if (!host->ok()) GTEST_SKIP() << "no GL 4.5 compatibility context: " << error;
        host->viewer().setLightingMode(osg::View::NO_LIGHT); // the scene's sun is VDSM's light
        // Across the field's edge at x = 0: OSG's ground beside it, grass beyond.
        host->look(osg::Vec3d(-1.5, 2.0, 2.0), osg::Vec3d(0.3, 0.0, 2.0), 60.0);
    }

    // A ShadowedScene with VDSM as an application sets it up: a sun (a directional light),
    // the ground, the field 4 m x 4 m from the origin, and a box above the grass.
    void build(osgShadow::ShadowTechnique* technique = new osgShadow::ViewDependentShadowMap,
               bool orthographic = true) {
        scene = new osgShadow::ShadowedScene;
        osg::ref_ptr<osgShadow::ShadowSettings> settings = new osgShadow::ShadowSettings;
        settings->setReceivesShadowTraversalMask(kReceives);
        settings->setCastsShadowTraversalMask(kCasts);
        settings->setTextureSize(osg::Vec2s(1024, 1024));
        // VDSM's default is a light-space perspective map; the tests of grass casting run with
        // both.
        if (orthographic) settings->setShadowMapProjectionHint(osgShadow::ShadowSettings::ORTHOGRAPHIC_SHADOW_MAP);
        scene->setShadowSettings(settings.get());
        scene->setShadowTechnique(technique);
        osg::ref_ptr<osg::Light> light = new osg::Light(0);
        light->setPosition(osg::Vec4(kSun.x(), kSun.y(), kSun.z(), 0.0f)); // w = 0: directional, towards the sun
        osg::ref_ptr<osg::LightSource> sun = new osg::LightSource;
        sun->setLight(light.get());
        scene->addChild(sun.get());
        const float soil[3] = {0.30f, 0.22f, 0.12f};
        ground_ = ground(6.0f, host->colour(soil));
        ground_->setNodeMask(kReceives | kCasts);
        scene->addChild(ground_.get());
        grass_osg::FieldDesc desc = field_desc(8);
        desc.field.cell_size = 0.5; // blades 0.2 to 0.4 m long
        grass = field_drawable(desc);
        grass_osg::Lights lights;
        const osg::Vec3 to_sun = kSun / kSun.length();
        for (int c = 0; c < 3; ++c) lights.sun_direction[c] = to_sun[c];
        grass->setLights(lights);
        grass->setShadowedScene(scene.get());
        grass_geode = new osg::Geode;
        grass_geode->addDrawable(grass.get());
        grass_geode->setNodeMask(kReceives | kCasts);
        scene->addChild(grass_geode.get());
        const float grey[3] = {0.5f, 0.5f, 0.5f};
        box_ = box(kBoxCentre, osg::Vec3(0.5f, 0.5f, 0.5f), host->colour(grey));
        box_->setNodeMask(kReceives | kCasts);
        scene->addChild(box_.get());
    }

    // Two frames (VDSM sets up its data at the first), read back.
    grass_host::Image frames() {
        host->frame(scene.get());
        return host->frame(scene.get());
    }

    // The pixel a world point falls on, top row first.
    void project(const osg::Vec3d& p, int* x, int* y) {
        const osg::Camera* camera = host->viewer().getCamera();
        const osg::Vec3d w =
            p * camera->getViewMatrix() * camera->getProjectionMatrix() * camera->getViewport()->computeWindowMatrix();
        *x = int(std::lround(w.x()));
        *y = int(host->target().format().height) - 1 - int(std::lround(w.y()));
    }

    struct Patch {
        double brightness = 0; // mean of R + G + B, 0..765
        int grass = 0, pixels = 0;
    };
    // The pixels within `radius` of where p falls.
    Patch patch(const grass_host::Image& image, const osg::Vec3d& p, int radius) {
        int cx = 0, cy = 0;
        project(p, &cx, &cy);
        Patch out;
        for (int y = cy - radius; y <= cy + radius; ++y) {
            for (int x = cx - radius; x <= cx + radius; ++x) {
                if (x < 0 || y < 0 || x >= int(image.width) || y >= int(image.height)) continue;
                const uint8_t* px = image.pixel(uint32_t(x), uint32_t(y));
                out.brightness += px[0] + px[1] + px[2];
                out.grass += is_grass(px) ? 1 : 0;
                ++out.pixels;
            }
        }
        if (out.pixels) out.brightness /= out.pixels;
        return out;
    }

    // The patch around p in a frame in which `caster` no longer casts (written to `name`).
    Patch without_casting(osg::Node* caster, const osg::Vec3d& p, int radius, const std::string& name) {
        caster->setNodeMask(kReceives);
        const grass_host::Image without = frames();
        save(without, name);
        return patch(without, p, radius);
    }
    static void expect_darker(const Patch& shaded, const Patch& control, double ratio, const char* what) {
        EXPECT_LT(shaded.brightness, ratio * control.brightness)
            << what << ": " << shaded.brightness << " against " << control.brightness;
        std::printf("%s: %.1f against %.1f\n", what, shaded.brightness, control.brightness);
    }

    // OSG's ground 0.15 m outside the field's edge: the blades at the edge, 0.2 m to 0.4 m
    // long and leaning, shade it. The control: the grass does not cast.
    void check_grass_shadows_the_ground(const char* what) {
        const grass_host::Image casting = frames();
        save(casting, "vdsm_grass_casting");
        ASSERT_EQ(grass->lastError(), "");
        const osg::Vec3d beside(-0.15, 0.0, 2.0);
        const Patch shaded = patch(casting, beside, 3);
        const Patch control = without_casting(grass_geode.get(), beside, 3, "vdsm_shadows_grass_not_casting");
        ASSERT_GT(control.pixels, 40);
        EXPECT_LT(control.grass, control.pixels / 4) << "the pixels show the ground";
        expect_darker(shaded, control, 0.85, what);
        // Deep in the field's own shade the grass still shows: the depth pass wrote no colour.
        const Patch field = patch(casting, osg::Vec3d(1.0, 0.1, 2.0), 5);
        EXPECT_GT(field.grass, field.pixels * 9 / 10);
        EXPECT_EQ(grass->lastError(), "");
    }

    // Towards the sun, 45 degrees up from +x: shadows fall towards -x, as long as their
    // casters are high.
    const osg::Vec3 kSun{1.0f, 1.0f, 0.0f};
    const osg::Vec3 kBoxCentre{1.6f, 1.0f, 2.8f};

    std::unique_ptr<OsgHost> host;
    osg::ref_ptr<osgShadow::ShadowedScene> scene;
    osg::ref_ptr<grass_osg::FieldDrawable> grass;
    osg::ref_ptr<osg::Geode> grass_geode, ground_, box_;
};

TEST_F(VdsmShadowTest, ABoxShadowsTheGrass) {
    build();
    // From the sun's side (blades seen from behind show little of the sun), past the box.
    host->look(osg::Vec3d(5.5, 2.0, 2.0), osg::Vec3d(1.5, 0.0, 2.4), 60.0);
    const grass_host::Image lit_and_shadowed = frames();
    save(lit_and_shadowed, "vdsm_shadows");
    ASSERT_EQ(grass->lastError(), "");
    // The box's shadow on the blades' upper half (0.2 m up), and the control: the box casts
    // nothing (it no longer has the casts mask), the same pixels.
    const osg::Vec3d shadow = osg::Vec3d(kBoxCentre) - osg::Vec3d(1, 1, 0) * (kBoxCentre.y() - 0.2);
    const Patch shadowed = patch(lit_and_shadowed, shadow, 5);
    const Patch control = without_casting(box_.get(), shadow, 5, "vdsm_shadows_box_not_casting");
    ASSERT_GT(control.pixels, 100);
    EXPECT_GT(control.grass, control.pixels * 9 / 10) << "the pixels show grass";
    expect_darker(shadowed, control, 0.75, "the box's shadow darkens the grass");
    EXPECT_EQ(grass->lastError(), "");
    // docs/images/integration/osg-vdsm-shadows.png: both shadows, seen from the side.
    box_->setNodeMask(kReceives | kCasts);
    host->look(osg::Vec3d(4.2, 2.6, -0.8), osg::Vec3d(1.0, 0.0, 2.4), 60.0);
    save(frames(), "vdsm_shadows_side");
}

TEST_F(VdsmShadowTest, GrassShadowsOsgsGroundBesideTheField) {
    build();
    check_grass_shadows_the_ground("the grass's shadow darkens the ground");
}

// VDSM's default, a light-space perspective map (a warped projection whose rays stay parallel
// to the sun): grass casts into it as well.
TEST_F(VdsmShadowTest, GrassShadowsOsgsGroundInVdsmsDefaultPerspectiveMap) {
    build(new osgShadow::ViewDependentShadowMap, false);
    check_grass_shadows_the_ground("the grass's shadow in a perspective map darkens the ground");
}

// Another technique: grass draws unshadowed and says why, naming the technique.
TEST_F(VdsmShadowTest, AnotherTechniqueIsNamedInTheError) {
    build(new osgShadow::ShadowMap);
    const grass_host::Image image = frames();
    EXPECT_NE(grass->lastError().find("ShadowMap, not osgShadow::ViewDependentShadowMap"), std::string::npos)
        << grass->lastError();
    const Patch field = patch(image, osg::Vec3d(1.0, 0.1, 2.0), 5);
    EXPECT_GT(field.grass, field.pixels * 9 / 10) << "grass is drawn";
}

// VDSM's default, a light-space perspective map: grass receives it as well.
TEST_F(VdsmShadowTest, APerspectiveShadowMapIsReceived) {
    build(new osgShadow::ViewDependentShadowMap, false);
    host->look(osg::Vec3d(5.5, 2.0, 2.0), osg::Vec3d(1.5, 0.0, 2.4), 60.0);
    const grass_host::Image image = frames();
    EXPECT_EQ(grass->lastError(), "");
    const osg::Vec3d shadow = osg::Vec3d(kBoxCentre) - osg::Vec3d(1, 1, 0) * (kBoxCentre.y() - 0.2);
    const Patch shadowed = patch(image, shadow, 5);
    const Patch lit = without_casting(box_.get(), shadow, 5, "vdsm_perspective_box_not_casting");
    EXPECT_GT(lit.grass, lit.pixels * 9 / 10) << "the pixels show grass";
    expect_darker(shadowed, lit, 0.75, "a perspective map's box shadow darkens the grass");
}

} // namespace
} // namespace grass_osg_test
