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
// Renders until the GrassField has drawn `frames` more frames (at most 40 tries), then grabs.
QImage render(QQuickView* window, QObject* grass, int frames = 2);
// Renders a few frames and grabs (for scenes without grass or with grass hidden).
QImage render_frames(QQuickView* window, int frames = 3);

} // namespace qt_test
