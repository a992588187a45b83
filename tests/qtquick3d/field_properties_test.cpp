// GrassField's properties as a host sets them from QML: a density map from an image source
// leaves a bare area where it is black, and a bad value is refused (errorString names the
// property and the value) with the field drawn before it still drawn.
#include "qtquick3d_fixture.hpp"

#include <QTemporaryDir>
#include <QUrl>

#include <gtest/gtest.h>

namespace {

using qt_test::kClear;
using qt_test::make_grass_window;
using qt_test::render;

// No ground: every pixel is grass or the clear colour. The camera looks down the -z axis at
// the field, world +x to the right of the image.
QString scene() {
    return qt_test::grass_scene("position: Qt.vector3d(0, 260, 160); eulerRotation.x: -60; clipNear: 5; clipFar: 5000",
                                "", "extent: Qt.size(200, 200); cellSize: 25");
}

bool is_clear(QRgb p) { return qRed(p) > 200 && qBlue(p) > 200 && qGreen(p) < 60; }

// Pixels that are not the clear colour in the left and the right half of the image.
std::pair<int, int> grass_by_half(const QImage& image) {
    int left = 0, right = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (!is_clear(image.pixel(x, y))) ++(x < image.width() / 2 ? left : right);
    return {left, right};
}

TEST(GrassFieldProperties, ADensityMapImageLeavesABareArea) {
    QTemporaryDir dir;
    QImage map(64, 64, QImage::Format_Grayscale8);
    map.fill(255);
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width() / 2; ++x) map.setPixel(x, y, qRgb(0, 0, 0)); // -x half bare
    const QString path = dir.filePath(QStringLiteral("density.png"));
    ASSERT_TRUE(map.save(path));

    auto [window, grass] = make_grass_window(scene(), 1);
    ASSERT_TRUE(grass);
    const auto [left_full, right_full] = grass_by_half(render(window.get(), grass, 3));
    // Uniform grass fills both halves alike (the guard against a vacuous comparison).
    ASSERT_GT(left_full, window->width() * window->height() / 16);
    ASSERT_GT(right_full, window->width() * window->height() / 16);

    grass->setProperty("densityMap", QUrl::fromLocalFile(path));
    const QImage mapped = render(window.get(), grass, 3);
    mapped.save(QStringLiteral("qtquick3d_density_map.png"));
    EXPECT_EQ(grass->property("errorString").toString(), QString());
    const auto [left, right] = grass_by_half(mapped);
    // The -x half is bare but for blades leaning over from the edge; the +x half keeps its grass.
    EXPECT_LT(left, left_full / 10) << "of " << left_full;
    EXPECT_GT(right, right_full * 8 / 10) << "of " << right_full;
    EXPECT_TRUE(qt_test::take_validation_messages().empty());
}

TEST(GrassFieldProperties, ABadValueIsRefusedByNameAndThePreviousFieldStaysDrawn) {
    auto [window, grass] = make_grass_window(scene(), 1);
    ASSERT_TRUE(grass);
    const QImage before = render(window.get(), grass, 3);
    ASSERT_GT(grass_by_half(before).first, window->width() * window->height() / 16);

    struct Bad {
        const char* property;
        QVariant value;
        const char* names; // what errorString must contain
    };
    const Bad bad[] = {
        {"extent", QSizeF(0, 200), "GrassField.extent: 0 x 200"},
        {"extent", QSizeF(200, -5), "GrassField.extent: 200 x -5"},
        {"cellSize", 0.0, "GrassField.cellSize: 0"},
        {"cellSize", 1e9, "GrassField.cellSize: 1000000000"},
        {"density", 1.5, "GrassField.density: 1.5"},
        {"density", -0.25, "GrassField.density: -0.25"},
        {"densityMap", QUrl::fromLocalFile(QStringLiteral("/nonexistent/density.png")),
         "GrassField.densityMap: \"file:///nonexistent/density.png\""},
    };
    for (const Bad& b : bad) {
        const QVariant kept = grass->property(b.property);
        grass->setProperty(b.property, b.value);
        const QString error = grass->property("errorString").toString();
        EXPECT_TRUE(error.contains(QString::fromUtf8(b.names))) << error.toStdString();
        EXPECT_EQ(grass->property(b.property), kept) << b.property;
        EXPECT_EQ(render(window.get(), grass, 2), before) << b.names;
    }
    EXPECT_TRUE(qt_test::take_validation_messages().empty());
}

} // namespace
