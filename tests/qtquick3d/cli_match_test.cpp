// The adapter's image of a fixed field and camera matches grass-render's headless image of
// the same field and camera (same backend, one sample, no ground, the CLI's sky as the
// window's colour). The scene is in the CLI's metres: grass has no absolute scale, so the
// GrassField's scene units follow. The field is small enough (every cell within 5 cells of
// the camera) for the geometry tier alone, in both: the CLI's demo tiers and the default
// quality preset agree there. Measured: see kMeanTolerance.
#include "qtquick3d_fixture.hpp"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

namespace {

// grass-render's clear colour, linear (0.55, 0.70, 0.90), as its sRGB target stores it.
QColor cli_sky() {
    auto encode = [](double v) {
        v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
        return int(std::lround(v * 255.0));
    };
    return QColor(encode(0.55), encode(0.70), encode(0.90));
}

QString scene() {
    return qt_test::grass_scene("position: Qt.vector3d(0, 1.2, 2.2); eulerRotation.x: -35; fieldOfView: 60; "
                                "clipNear: 0.05; clipFar: 50",
                                "", "extent: Qt.size(3, 3); cellSize: 1");
}

// The same field and camera for grass-render (its target: the camera pitched 35 degrees down).
const char* kCliScene = R"({
  "field": { "cells": [3, 3], "cell_size": 1.0, "origin": [-1.5, 0, -1.5], "density_map": null },
  "camera": { "position": [0, 1.2, 2.2], "target": [0, 0, 0.486222], "fov": 60, "far": 50 },
  "image": { "width": 320, "height": 240, "samples": 1 }
})";

QImage cli_image(const QTemporaryDir& dir, const QStringList& extra) {
    const QString scene = dir.filePath("scene.json"), out = dir.filePath("cli.png");
    QFile f(scene);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(kCliScene);
    f.close();
    QProcess p;
    const QString backend = qt_test::backend() == grass_qt::GraphicsApi::vulkan ? "vk" : "gl";
    p.start(QStringLiteral(GRASS_RENDER_PATH),
            QStringList{"--scene", scene, "--backend", backend, "--no-ground", "--output", out} + extra);
    EXPECT_TRUE(p.waitForFinished(120000));
    EXPECT_EQ(p.exitCode(), 0) << p.readAllStandardError().toStdString();
    return QImage(out).convertToFormat(QImage::Format_RGBX8888);
}

// Measured (llvmpipe and lavapipe): mean 0.065 levels and no pixel off by more than 32 on
// both backends; another tiling scores 35.6 levels and 42% of pixels. The tolerance sits
// well above the first and far below the second.
constexpr double kMeanTolerance = 1.0;
constexpr double kFarShareTolerance = 0.005;

struct Difference {
    double mean = 0.0;    // mean absolute difference per channel, 0..255
    double far_share = 0; // share of pixels whose largest channel difference exceeds 32
};

Difference compare(const QImage& a, const QImage& b) {
    Difference d;
    double sum = 0.0;
    int far = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int dr = std::abs(qRed(p) - qRed(q)), dg = std::abs(qGreen(p) - qGreen(q)),
                      db = std::abs(qBlue(p) - qBlue(q));
            sum += dr + dg + db;
            far += std::max({dr, dg, db}) > 32 ? 1 : 0;
        }
    const double n = double(a.width()) * a.height();
    d.mean = sum / (3.0 * n);
    d.far_share = far / n;
    return d;
}

TEST(CliMatch, TheAdaptersImageMatchesTheHeadlessCli) {
    QTemporaryDir dir;
    const QImage cli = cli_image(dir, {});
    ASSERT_EQ(cli.size(), QSize(320, 240));
    const QColor sky = cli_sky();
    auto [window, grass] = qt_test::make_grass_window(scene(), 1, sky);
    ASSERT_TRUE(grass);
    const QImage qt = qt_test::render(window.get(), grass);
    qt.save("qtquick3d_cli_match_adapter.png");
    cli.save("qtquick3d_cli_match_cli.png");

    // Not vacuous: grass covers a good part of both images.
    int grass_pixels = 0;
    for (int y = 0; y < qt.height(); ++y)
        for (int x = 0; x < qt.width(); ++x) grass_pixels += qt.pixel(x, y) != sky.rgba() ? 1 : 0;
    EXPECT_GT(grass_pixels, qt.width() * qt.height() / 4);

    const Difference same = compare(qt, cli);
    std::printf("adapter vs CLI: mean %.3f levels, %.4f of pixels off by more than 32\n", same.mean, same.far_share);
    EXPECT_LT(same.mean, kMeanTolerance);
    EXPECT_LT(same.far_share, kFarShareTolerance);

    // The measure tells fields apart: the CLI's other tiling (no mirroring) is far off.
    const Difference other = compare(qt, cli_image(dir, {"--no-mirror"}));
    std::printf("adapter vs CLI without mirroring: mean %.3f, %.4f far\n", other.mean, other.far_share);
    EXPECT_GT(other.mean, 2.0 * kMeanTolerance);
    EXPECT_TRUE(qt_test::take_validation_messages().empty());
}

} // namespace
