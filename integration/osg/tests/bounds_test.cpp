// OSG's bounds of a field: they hold every blade and the terrain, so OSG's view-frustum
// culling and its near/far fitting never drop grass that is in view.
#include "osg_scene.hpp"

namespace grass_osg_test {
namespace {

class BoundsTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        host.reset(new OsgHost(TargetFormat{}, &error));
        if (!host->ok()) GTEST_SKIP() << "no GL 4.5 compatibility context: " << error;
    }
    // Grass pixels of a frame with OSG's default near/far computation from the bounds.
    size_t grass_pixels(grass_osg::FieldDrawable* grass, const osg::Vec3d& eye, const osg::Vec3d& target,
                        const std::string& name) {
        host->look(eye, target, 30.0, true);
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(grass);
        const auto image = host->frame(geode.get());
        save(image, name);
        size_t n = 0;
        for (uint32_t y = 0; y < image.height; ++y) {
            for (uint32_t x = 0; x < image.width; ++x) n += is_grass(image.pixel(x, y));
        }
        return n;
    }
    std::unique_ptr<OsgHost> host;
};

grass_osg::FieldDesc raised_field(float height) {
    grass_osg::FieldDesc d = field_desc(16);
    d.field.cell_size = 0.5; // 8 m x 8 m
    d.height_map.width = d.height_map.height = 4;
    d.height_map.values.assign(16, 1.0f);
    d.height_map.scale = height;
    return d;
}

TEST_F(BoundsTest, TheBoxHoldsTheCellsTheBladesAndTheTerrain) {
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(raised_field(3.0f));
    const osg::BoundingBox& box = grass->getBoundingBox();
    EXPECT_LE(box.xMin(), 0.0f);
    EXPECT_LE(box.zMin(), 0.0f);
    EXPECT_GE(box.xMax(), 8.0f);
    EXPECT_GE(box.zMax(), 8.0f);
    EXPECT_LE(box.yMin(), 3.0f) << "the roots stand on the raised terrain";
    // The tallest blade: 0.85 patch units of arc at most, nearly upright, on 0.5 m cells.
    EXPECT_GT(box.yMax(), 3.0f + 0.3f) << "the blades' height is in the box";
    EXPECT_LT(box.yMax(), 3.0f + 0.5f);
    EXPECT_LT(box.xMax(), 8.5f) << "a box, not the whole world";

    // A field turned into OSG's z-up world: the box turns with it.
    grass_osg::FieldDesc d = raised_field(3.0f);
    const double origin[3] = {10.0, 20.0, 30.0};
    grass_osg::z_up_base_transform(origin, d.field.base_transform);
    osg::ref_ptr<grass_osg::FieldDrawable> turned = field_drawable(d);
    const osg::BoundingBox& up = turned->getBoundingBox();
    EXPECT_NEAR(up.zMin(), 33.0f, 0.05f);
    EXPECT_GT(up.zMax(), 33.3f);
    EXPECT_NEAR(up.yMax(), 20.0f, 0.3f);
    EXPECT_NEAR(up.yMin(), 12.0f, 0.3f);
}

// The camera stands low at the field's edge and looks up, so the ground plane of the field
// is below the view: only the blades reach into it. A bound without the blades' height is
// culled by OSG's view-frustum test (and fits the far plane in front of the grass).
TEST_F(BoundsTest, BladeTipsSeenOverTheFieldsEdgeAreDrawn) {
    grass_osg::FieldDesc d = field_desc(16);
    d.field.cell_size = 0.5;
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(d);
    const size_t flat =
        grass_pixels(grass.get(), osg::Vec3d(4.0, 0.12, -1.0), osg::Vec3d(4.0, 1.3, 3.0), "bounds_flat");
    EXPECT_GT(flat, 128u * 128u / 20) << "blade tips along the lower edge of the image";
}

TEST_F(BoundsTest, GrassOnRaisedTerrainIsDrawn) {
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(raised_field(3.0f));
    const size_t raised =
        grass_pixels(grass.get(), osg::Vec3d(4.0, 3.12, -1.0), osg::Vec3d(4.0, 4.3, 3.0), "bounds_raised");
    EXPECT_GT(raised, 128u * 128u / 20) << "blade tips on the raised terrain";
    EXPECT_EQ(grass->lastError(), "");
}

TEST_F(BoundsTest, ARefusedDescThrowsGrasssMessage) {
    grass_osg::FieldDesc d = field_desc(16);
    d.field.cell_size = -1.0;
    try {
        field_drawable(d);
        FAIL() << "a negative cell size was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("cell_size"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("-1"), std::string::npos) << e.what();
    }
    d = raised_field(3.0f);
    d.height_map.values.pop_back();
    EXPECT_THROW(field_drawable(d), std::invalid_argument);
}

} // namespace
} // namespace grass_osg_test
