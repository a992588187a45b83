// Shared depth and a clean state: OSG's models and grass hide each other through OSG's
// depth buffer, and OSG's own image outside the grass is the same with grass on and off.
// Each check has a control that makes it fail: grass drawn without its depth test.
#include "osg_scene.hpp"

namespace grass_osg_test {
namespace {

struct Variant {
    uint32_t samples;
    bool ground; // an OSG ground under the grass
};

void PrintTo(const Variant& v, std::ostream* out) {
    *out << v.samples << " sample(s)" << (v.ground ? ", an OSG ground" : "");
}

class SharedDepthTest : public ::testing::TestWithParam<Variant> {
protected:
    void SetUp() override {
        TargetFormat format;
        format.samples = GetParam().samples;
        std::string error;
        host.reset(new OsgHost(format, &error));
        if (!host->ok()) GTEST_SKIP() << "no GL 4.5 compatibility context: " << error;
    }
    std::string name(const std::string& what) const {
        return what + "_" + std::to_string(GetParam().samples) + (GetParam().ground ? "x_ground" : "x");
    }
    // The field, and OSG's ground when the variant has one.
    osg::ref_ptr<osg::Group> scene(grass_osg::FieldDrawable* grass) {
        osg::ref_ptr<osg::Group> root = new osg::Group;
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(grass);
        root->addChild(geode.get());
        const float soil[3] = {0.045f, 0.036f, 0.018f};
        if (GetParam().ground) root->addChild(ground(6.0f, host->colour(soil)).get());
        return root;
    }
    std::unique_ptr<OsgHost> host;
};

const float kRed[3] = {0.8f, 0.1f, 0.1f};

TEST_P(SharedDepthTest, AnOsgBoxInFrontOfTheGrassHidesIt) {
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(field_desc(16)); // 4 m x 4 m
    const osg::Vec3d eye(2.0, 0.9, -0.5), target(2.0, 0.0, 2.0);
    host->look(eye, target, 45.0);
    osg::Vec3d ahead = target - eye;
    ahead.normalize();
    osg::ref_ptr<osg::Group> root = scene(grass.get());
    // 0.4 m ahead: nearer than any blade (the field starts 0.5 m ahead and below). OSG draws
    // it in its opaque bin, before grass.
    root->addChild(box(eye + ahead * 0.4, osg::Vec3(0.1f, 0.1f, 0.1f), host->colour(kRed)).get());
    const auto image = host->frame(root.get());
    save(image, name("box_in_front"));
    uint8_t red[3], sky[3];
    expected_bytes(kRed, red);
    expected_bytes(kSky, sky);
    EXPECT_TRUE(near_colour(image.pixel(64, 64), red, 3)) << "the box hides the grass behind it";
    EXPECT_TRUE(is_grass(image.pixel(64, 118))) << "below the box: grass";
    EXPECT_TRUE(near_colour(image.pixel(2, 2), sky, 2)) << "the top corner shows OSG's clear colour";
    EXPECT_EQ(grass->lastError(), "");

    // The control: without grass's depth test the same check fails.
    grass->setViewFlags(GRASS_VIEW_FLAG_NO_DEPTH_TEST);
    const auto no_depth = host->frame(root.get());
    save(no_depth, name("box_in_front_no_depth_test"));
    EXPECT_FALSE(near_colour(no_depth.pixel(64, 64), red, 3)) << "grass drawn over the box";
}

// A low box standing in the grass, drawn by OSG after grass (bin 20): the blades in front of
// it hide most of it, through the depth grass wrote.
TEST_P(SharedDepthTest, GrassHidesAnOsgBoxStandingInIt) {
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(field_desc(16));
    host->look(osg::Vec3d(2.0, 0.3, -0.5), osg::Vec3d(2.0, 0.1, 2.0), 45.0);
    osg::ref_ptr<osg::Group> root = scene(grass.get());
    const osg::Vec3 centre(2.0f, 0.07f, 1.5f), size(1.0f, 0.14f, 0.1f); // lower than most blades
    root->addChild(box(centre, size, host->colour(kRed), 20).get());
    uint8_t red[3];
    expected_bytes(kRed, red);
    // The box's rectangle on screen (OSG's window coordinates: y up), a pixel inside its edges.
    const osg::Camera& camera = *host->viewer().getCamera();
    const osg::Matrixd to_window =
        camera.getViewMatrix() * camera.getProjectionMatrix() * camera.getViewport()->computeWindowMatrix();
    osg::BoundingBox rect;
    for (int corner = 0; corner < 8; ++corner) {
        const osg::Vec3 p(centre.x() + size.x() * ((corner & 1) ? 0.5f : -0.5f),
                          centre.y() + size.y() * ((corner & 2) ? 0.5f : -0.5f),
                          centre.z() + size.z() * ((corner & 4) ? 0.5f : -0.5f));
        rect.expandBy(osg::Vec3d(p) * to_window);
    }
    const auto red_fraction = [&](const grass_host::Image& image) {
        size_t inside = 0, shown = 0;
        for (int y = int(rect.yMin()) + 1; y < int(rect.yMax()) - 1; ++y) {
            for (int x = int(rect.xMin()) + 1; x < int(rect.xMax()) - 1; ++x) {
                if (x < 0 || y < 0 || x >= int(image.width) || y >= int(image.height)) continue;
                ++inside;
                shown += near_colour(image.pixel(uint32_t(x), image.height - 1 - uint32_t(y)), red, 3);
            }
        }
        EXPECT_GT(inside, 100u) << "the box covers a patch of the image";
        return inside ? double(shown) / double(inside) : 0.0;
    };
    const auto image = host->frame(root.get());
    save(image, name("box_in_grass"));
    EXPECT_LT(red_fraction(image), 0.5) << "the blades in front hide most of the box";

    // The control: grass without its depth test writes no depth, and the box paints over it.
    grass->setViewFlags(GRASS_VIEW_FLAG_NO_DEPTH_TEST);
    const auto no_depth = host->frame(root.get());
    save(no_depth, name("box_in_grass_no_depth_test"));
    EXPECT_GT(red_fraction(no_depth), 0.95);
}

// Outside the grass's own pixels OSG's image is the same, byte for byte, with grass on and
// off; and a second frame is the same as the first (OSG's state cache stays true across
// grass's draws).
TEST_P(SharedDepthTest, OsgsImageOutsideTheGrassIsUnchanged) {
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(field_desc(16));
    host->look(osg::Vec3d(2.0, 0.9, -0.5), osg::Vec3d(2.0, 0.0, 2.0), 45.0);
    osg::ref_ptr<osg::Group> root = scene(grass.get());
    osg::ref_ptr<osg::Group> models = busy_models();
    root->addChild(models.get());

    // Where grass draws: grass alone, on a clear colour nothing else has.
    const float magenta[3] = {1.0f, 0.0f, 1.0f};
    host->clear_to(magenta);
    osg::ref_ptr<osg::Group> grass_only = scene(grass.get());
    grass_only->removeChild(1, 1); // no ground either
    const auto alone = host->frame(grass_only.get());
    host->clear_to(kSky);

    const auto with_grass = host->frame(root.get());
    const auto again = host->frame(root.get());
    root->getChild(0)->setNodeMask(0);
    const auto without = host->frame(root.get());
    save(alone, name("grass_alone"));
    save(with_grass, name("models_with_grass"));
    save(without, name("models_without_grass"));

    uint8_t mark[3];
    expected_bytes(magenta, mark);
    size_t grass_pixels = 0, outside = 0, outside_changed = 0, inside_changed = 0, frames_differ = 0;
    for (uint32_t y = 0; y < alone.height; ++y) {
        for (uint32_t x = 0; x < alone.width; ++x) {
            const bool grass_here = !near_colour(alone.pixel(x, y), mark, 0);
            const bool changed = !near_colour(with_grass.pixel(x, y), without.pixel(x, y), 0);
            grass_pixels += grass_here;
            outside += !grass_here;
            outside_changed += !grass_here && changed;
            inside_changed += grass_here && changed;
            frames_differ += !near_colour(with_grass.pixel(x, y), again.pixel(x, y), 0);
        }
    }
    const size_t all = size_t(alone.width) * alone.height;
    ASSERT_GT(grass_pixels, all / 5) << "the field covers a good part of the image";
    ASSERT_GT(outside, all / 5) << "and leaves a good part to OSG";
    EXPECT_GT(inside_changed, grass_pixels / 2) << "grass shows where it draws";
    EXPECT_EQ(outside_changed, 0u) << "OSG's pixels outside the grass changed";
    EXPECT_EQ(frames_differ, 0u) << "the second frame differs from the first";
    EXPECT_EQ(grass->lastError(), "");
}

INSTANTIATE_TEST_SUITE_P(Targets, SharedDepthTest, ::testing::Values(Variant{1, false}, Variant{4, true}),
                         [](const auto& p) {
                             return std::to_string(p.param.samples) + (p.param.ground ? "xGround" : "x");
                         });

} // namespace
} // namespace grass_osg_test
