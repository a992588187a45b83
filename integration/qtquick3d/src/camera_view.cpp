#include "camera_view.hpp"

#include <QMatrix4x4>
#include <QObject>
#include <QVariant>

#include <cmath>

namespace grass_qt {

bool read_camera(const QObject* camera, CameraState* out, QString* error) {
    if (!camera) {
        *error = QStringLiteral("the View3D has no camera");
        return false;
    }
    const QVariant fov = camera->property("fieldOfView");
    if (!fov.isValid()) {
        *error = QStringLiteral("the View3D's camera is a %1, not a PerspectiveCamera")
                     .arg(QString::fromLatin1(camera->metaObject()->className()));
        return false;
    }
    out->scene_position = camera->property("scenePosition").value<QVector3D>();
    out->scene_rotation = camera->property("sceneRotation").value<QQuaternion>();
    out->field_of_view = fov.toFloat();
    // PerspectiveCamera.Vertical is 0, .Horizontal 1.
    out->horizontal_fov = camera->property("fieldOfViewOrientation").toInt() == 1;
    out->clip_near = camera->property("clipNear").toFloat();
    out->clip_far = camera->property("clipFar").toFloat();
    return true;
}

grass_view_desc make_view(const CameraState& camera, const QRectF& viewport_px, int window_height_px,
                          ClipConvention convention) {
    grass_view_desc v = grass_default_view_desc();
    for (int c = 0; c < 3; ++c) v.camera_position[c] = static_cast<double>(camera.scene_position[c]);
    // World to eye: the inverse of the camera's rotation (its translation travels in
    // camera_position). Quick 3D is right-handed, y up, and a camera looks down its -z.
    const QMatrix3x3 r = camera.scene_rotation.normalized().toRotationMatrix();
    for (int k = 0; k < 16; ++k) v.view[k] = 0.0f;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) v.view[4 * col + row] = r(col, row); // transposed
    v.view[15] = 1.0f;

    // Quick 3D's perspective projection (GL conventions), then QRhi's clip-space correction.
    const double aspect = viewport_px.width() / viewport_px.height();
    double fovy = camera.field_of_view * M_PI / 180.0;
    if (camera.horizontal_fov) fovy = 2.0 * std::atan(std::tan(fovy * 0.5) / aspect);
    QMatrix4x4 projection;
    projection.perspective(static_cast<float>(fovy * 180.0 / M_PI), static_cast<float>(aspect), camera.clip_near,
                           camera.clip_far);
    if (convention == ClipConvention::vulkan) {
        const QMatrix4x4 clip_space_corr(1.0f, 0.0f, 0.0f, 0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.5f, 0.0f,
                                         0.0f, 0.0f, 1.0f);
        projection = clip_space_corr * projection;
    }
    const float* p = projection.constData(); // column-major
    for (int k = 0; k < 16; ++k) v.projection[k] = p[k];

    const QRect px = viewport_px.toRect();
    v.viewport[0] = px.x();
    v.viewport[1] = convention == ClipConvention::gl ? window_height_px - px.y() - px.height() : px.y();
    v.viewport[2] = px.width();
    v.viewport[3] = px.height();
    // Qt's window targets are UNORM and store what the shaders write.
    v.flags = GRASS_VIEW_FLAG_ENCODE_SRGB;
    return v;
}

} // namespace grass_qt
