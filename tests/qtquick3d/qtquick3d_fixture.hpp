// Windows with a Quick 3D scene and a GrassField, on the backend the test runs with
// (GRASS_QT_BACKEND=vulkan|opengl, under xvfb-run), read back with grabWindow().
#pragma once

#include <grass_qtquick3d/grass_field.hpp>

#include <QColor>
#include <QImage>
#include <QQuickView>
#include <QString>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace qt_test {

// The colour the tests clear the window to: magenta, which neither grass nor their models draw.
inline const QColor kClear(255, 0, 255);

// The backend of this run; the Vulkan instance has the validation layer.
grass_qt::GraphicsApi backend();
// Messages the Vulkan validation layer reported since the last call (empty on GL).
std::vector<std::string> take_validation_messages();

// A window of `width` x `height` with `samples` samples showing the QML item `qml` (which
// may use QtQuick, QtQuick3D and Grass), cleared to `clear`.
std::unique_ptr<QQuickView> make_window(const QString& qml, int samples, QColor clear, int width = 320,
                                        int height = 240);
// The item with objectName `name` (e.g. the GrassField "grass").
QObject* child(QQuickView* window, const char* name);

// The QML of a scene with grass: an inline View3D with a transparent background (the window's
// colour shows through) seen by the PerspectiveCamera with the properties `camera`, holding the
// QML items `models`, and the GrassField "grass" with the properties `field` drawing into it.
QString grass_scene(const QString& camera, const QString& models, const QString& field);
// A window of make_window's and its GrassField "grass"; `grass` is null (a failure added)
// where either is missing.
struct GrassWindow {
    std::unique_ptr<QQuickView> window;
    QObject* grass = nullptr;
};
GrassWindow make_grass_window(const QString& qml, int samples, QColor clear = kClear);
// Renders until the GrassField has drawn `frames` more frames (at most 40 tries), then grabs.
QImage render(QQuickView* window, QObject* grass, int frames = 2);
// Renders a few frames and grabs (for scenes without grass or with grass hidden).
QImage render_frames(QQuickView* window, int frames = 3);

} // namespace qt_test
