// The QML camera of a View3D as a grass view: view rotation, camera position (double),
// projection in the clip conventions of the window's graphics API, and the viewport.
#pragma once

#include <grass/grass.h>

#include <QQuaternion>
#include <QRectF>
#include <QString>
#include <QVector3D>

class QObject;

namespace grass_qt {

// A PerspectiveCamera's state, read through its QML properties (no private Qt headers).
struct CameraState {
    QVector3D scene_position;
    QQuaternion scene_rotation;
    float field_of_view = 60.0f; // degrees
    bool horizontal_fov = false; // fieldOfViewOrientation == PerspectiveCamera.Horizontal
    float clip_near = 10.0f, clip_far = 10000.0f;
};

// Reads scenePosition, sceneRotation, fieldOfView, fieldOfViewOrientation, clipNear and
// clipFar. False and *error when the object is not a perspective camera.
bool read_camera(const QObject* camera, CameraState* out, QString* error);

enum class ClipConvention {
    gl,     // clip z -1..1, y up, viewport origin lower-left
    vulkan, // clip z 0..1, y down (QRhi::clipSpaceCorrMatrix()), viewport origin upper-left
};

// `viewport_px` is the View3D's rectangle in device pixels from the window's top-left
// corner, `window_height_px` the window's height in device pixels.
grass_view_desc make_view(const CameraState& camera, const QRectF& viewport_px, int window_height_px,
                          ClipConvention convention);

} // namespace grass_qt
