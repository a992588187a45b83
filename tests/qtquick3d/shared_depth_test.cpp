// The Qt Quick 3D adapter shares the window's depth buffer with Quick 3D's models: a model in
// front of the grass hides it, grass in front of a model hides the model; with grass's depth
// test off the first check fails (the negative control). With and without a ground under the
// grass, 1 and 4 samples, on the backend of the run.
#include "qtquick3d_fixture.hpp"

#include <QQmlProperty>

#include <gtest/gtest.h>

namespace {

using qt_test::kClear;
using qt_test::make_grass_window;
using qt_test::render;
using qt_test::render_frames;

// The camera 150 units up, pitched 30 degrees down; a red cube floats between it and the
// grass (nothing of the grass can reach in front of it); a flat blue slab lies in the grass.
QString scene(bool ground) {
    const QString models = QStringLiteral(R"(
        Model {
            source: "#Cube"; position: Qt.vector3d(0, 100, 213.4); scale: Qt.vector3d(0.3, 0.3, 0.3)
            materials: PrincipledMaterial { baseColor: "#ff0000"; lighting: PrincipledMaterial.NoLighting }
        }
        Model {
            source: "#Cube"; position: Qt.vector3d(60, 3, -20); scale: Qt.vector3d(1.0, 0.06, 0.8)
            materials: PrincipledMaterial { baseColor: "#0000ff"; lighting: PrincipledMaterial.NoLighting }
        }
        Model {
            visible: %1
            source: "#Rectangle"; scale: Qt.vector3d(6, 6, 1); eulerRotation.x: -90
            materials: PrincipledMaterial { baseColor: "#808080"; lighting: PrincipledMaterial.NoLighting }
        })")
                               .arg(ground ? "true" : "false");
    return qt_test::grass_scene("position: Qt.vector3d(0, 150, 300); eulerRotation.x: -30; clipNear: 5; clipFar: 5000",
                                models, "extent: Qt.size(400, 400); cellSize: 25");
}

bool is_red(QRgb p) { return qRed(p) > 200 && qGreen(p) < 40 && qBlue(p) < 40; }
bool is_blue(QRgb p) { return qBlue(p) > 200 && qRed(p) < 40 && qGreen(p) < 40; }

struct Mask {
    std::vector<QPoint> points;
};

Mask mask_of(const QImage& image, bool (*test)(QRgb)) {
    Mask m;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (test(image.pixel(x, y))) m.points.push_back({x, y});
    return m;
}

double fraction(const QImage& image, const Mask& mask, bool (*test)(QRgb)) {
    int n = 0;
    for (const QPoint& p : mask.points) n += test(image.pixel(p)) ? 1 : 0;
    return mask.points.empty() ? 0.0 : double(n) / double(mask.points.size());
}

struct Params {
    bool ground;
    int samples;
};

class SharedDepthTest : public ::testing::TestWithParam<Params> {};

TEST_P(SharedDepthTest, ModelsAndGrassHideEachOther) {
    auto [window, grass] = make_grass_window(scene(GetParam().ground), GetParam().samples);
    ASSERT_TRUE(grass);

    // The models alone: where the cube and the slab are.
    grass->setProperty("visible", false);
    const QImage models = render_frames(window.get());
    const Mask cube = mask_of(models, is_red), slab = mask_of(models, is_blue);
    ASSERT_GT(cube.points.size(), 400u);
    ASSERT_GT(slab.points.size(), 400u);

    grass->setProperty("visible", true);
    const QImage both = render(window.get(), grass);
    both.save(QStringLiteral("qtquick3d_shared_depth_%1_%2.png").arg(GetParam().ground).arg(GetParam().samples));
    // The cube in front hides the grass behind it: every one of its pixels stays red (at 4
    // samples its edge pixels may take some grass behind them: 99%).
    EXPECT_GE(fraction(both, cube, is_red), GetParam().samples > 1 ? 0.99 : 1.0);
    // The grass in front of the slab hides most of it (without grass it is all blue).
    EXPECT_LT(fraction(both, slab, is_blue), 0.5);
    // An off-centre pixel shows grass, the top corner the clear colour.
    const QRgb below = both.pixel(both.width() / 2, both.height() * 7 / 8);
    EXPECT_TRUE(qGreen(below) > qRed(below) && qGreen(below) > qBlue(below)) << std::hex << below;
    EXPECT_EQ(both.pixel(0, 0), kClear.rgba());

    // The negative control: without grass's depth test the grass behind the cube covers it.
    grass->setProperty("depthTest", false);
    const QImage no_depth = render(window.get(), grass);
    EXPECT_LT(fraction(no_depth, cube, is_red), 0.9);
    EXPECT_TRUE(qt_test::take_validation_messages().empty());
}

INSTANTIATE_TEST_SUITE_P(Hosts, SharedDepthTest,
                         ::testing::Values(Params{false, 1}, Params{true, 1}, Params{false, 4}, Params{true, 4}),
                         [](const ::testing::TestParamInfo<Params>& p) {
                             return std::string(p.param.ground ? "Ground" : "NoGround") + "_" +
                                    std::to_string(p.param.samples) + "Samples";
                         });

} // namespace
