#include <grass_qtquick3d/grass_field.hpp>

#include "camera_view.hpp"
#include "field_renderer.hpp"

#include <QQmlFile>
#include <QQuickWindow>
#include <QSGRendererInterface>
#include <QSurfaceFormat>
#include <QtQml/qqml.h>

#include <cmath>

namespace grass_qt {

namespace {

QString number(double v) { return QString::number(v, 'g', 10); }

// The refusal of `value` for GrassField.`property`, a number that must lie within `range` (in
// words), `kept` being the value it keeps.
QString range_refusal(const char* property, double value, const char* range, double kept) {
    return QStringLiteral("GrassField.%1: %2; it must be within %3; kept %4")
        .arg(QString::fromLatin1(property), number(value), QString::fromLatin1(range), number(kept));
}

} // namespace

GrassField::GrassField(QQuickItem* parent) : QQuickItem(parent), report_(std::make_shared<RendererReport>()) {
    // Called by the renderer under the report's mutex, on the render thread; the destructor
    // clears it under that mutex, so `this` is alive whenever it runs.
    report_->notify = [this]() { QMetaObject::invokeMethod(this, "reportFrame", Qt::QueuedConnection); };
    connect(this, &QQuickItem::windowChanged, this, &GrassField::attachWindow);
}

GrassField::~GrassField() {
    // ~QQuickItem emits windowChanged(nullptr) when it leaves its parent, after this part of
    // the object is gone: the slot would run on a destroyed GrassField.
    disconnect(this, &QQuickItem::windowChanged, this, &GrassField::attachWindow);
    if (window_) disconnect(window_, nullptr, this, nullptr);
    {
        QMutexLocker lock(&report_->mutex);
        report_->notify = nullptr;
    }
    dropRenderer();
}

void GrassField::dropRenderer() {
    if (renderer_) {
        // It destroys itself on the render thread: after the frames in flight, or when the
        // scene graph is invalidated, whichever comes first.
        renderer_->retire();
        if (window_) window_->update();
    }
    renderer_ = nullptr;
    settings_dirty_ = true;
}

void GrassField::releaseResources() { dropRenderer(); }

template <typename T>
void GrassField::store(T& setting, const T& value, void (GrassField::*notify)()) {
    if (setting == value) return;
    setting = value;
    settings_dirty_ = true;
    if (window_) window_->update();
    emit(this->*notify)();
}

void GrassField::itemChange(ItemChange change, const ItemChangeData& data) {
    QQuickItem::itemChange(change, data);
    if (change == ItemVisibleHasChanged && window_) window_->update();
}

void GrassField::attachWindow(QQuickWindow* window) {
    if (window_) disconnect(window_, nullptr, this, nullptr);
    window_ = window;
    if (!window) return;
    connect(window, &QQuickWindow::beforeSynchronizing, this, &GrassField::sync, Qt::DirectConnection);
    connect(window, &QQuickWindow::sceneGraphInvalidated, this, &GrassField::invalidateSceneGraph,
            Qt::DirectConnection);
}

// Render thread, GUI thread blocked: the item's state is read here and nowhere else.
void GrassField::sync() {
    if (!window_) return;
    if (!renderer_) {
        renderer_ = FieldRenderer::create(window_, report_);
        if (!renderer_) return;
    }
    if (settings_dirty_) {
        FieldSettings s;
        s.position = position_;
        s.extent = extent_;
        s.cell_size = cell_size_;
        s.density = density_;
        s.quality = quality_;
        s.density_map = density_image_;
        s.color_map = color_image_;
        renderer_->set_settings(s);
        settings_dirty_ = false;
    }
    FrameInput frame;
    CameraState camera;
    QString error;
    if (isVisible() && view_ && view_->width() > 0 && view_->height() > 0 &&
        read_camera(view_->property("camera").value<QObject*>(), &camera, &error)) {
        const qreal dpr = window_->effectiveDevicePixelRatio();
        const QRectF r = view_->mapRectToScene(QRectF(0, 0, view_->width(), view_->height()));
        const QRectF px(r.x() * dpr, r.y() * dpr, r.width() * dpr, r.height() * dpr);
        const bool vulkan = window_->rendererInterface()->graphicsApi() == QSGRendererInterface::Vulkan;
        frame.view = make_view(camera, px, qRound(window_->height() * dpr),
                               vulkan ? ClipConvention::vulkan : ClipConvention::gl);
        if (!depth_test_) frame.view.flags |= GRASS_VIEW_FLAG_NO_DEPTH_TEST;
        frame.valid = true;
    } else if (!error.isEmpty()) {
        QMutexLocker lock(&report_->mutex);
        report_->error = error;
    }
    renderer_->set_frame(frame);
}

// Render thread: the window's graphics resources go, and the grass context with them.
void GrassField::invalidateSceneGraph() {
    delete renderer_;
    renderer_ = nullptr;
    settings_dirty_ = true;
}

void GrassField::reportFrame() {
    emit framesDrawnChanged();
    const QString e = errorString();
    if (e != last_error_) {
        last_error_ = e;
        emit errorStringChanged();
    }
}

QString GrassField::errorString() const {
    QMutexLocker lock(&report_->mutex);
    return report_->error;
}

int GrassField::framesDrawn() const {
    QMutexLocker lock(&report_->mutex);
    return report_->frames;
}

QVariantMap GrassField::memoryStats() const {
    QMutexLocker lock(&report_->mutex);
    QVariantMap m = report_->memory;
    if (m.isEmpty()) m.insert(QStringLiteral("live"), false);
    return m;
}

void GrassField::refuse(const QString& message) {
    qmlWarning(this) << message;
    {
        QMutexLocker lock(&report_->mutex);
        report_->error = message;
    }
    last_error_ = message;
    emit errorStringChanged();
}

void GrassField::setView(QQuickItem* view) {
    if (view_ == view) return;
    view_ = view;
    emit viewChanged();
    update();
}

void GrassField::setPosition(const QVector3D& p) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        return refuse(QStringLiteral("GrassField.position: (%1, %2, %3) is not finite; kept (%4, %5, %6)")
                          .arg(number(p.x()), number(p.y()), number(p.z()), number(position_.x()),
                               number(position_.y()), number(position_.z())));
    store(position_, p, &GrassField::positionChanged);
}

void GrassField::setExtent(const QSizeF& e) {
    if (!(e.width() > 0.0 && e.height() > 0.0 && std::isfinite(e.width()) && std::isfinite(e.height())))
        return refuse(
            QStringLiteral("GrassField.extent: %1 x %2; both must be finite and > 0; kept %3 x %4")
                .arg(number(e.width()), number(e.height()), number(extent_.width()), number(extent_.height())));
    store(extent_, e, &GrassField::extentChanged);
}

void GrassField::setCellSize(double c) {
    if (!(c >= 1e-4 && c <= 1e4)) return refuse(range_refusal("cellSize", c, "1e-4 .. 1e4", cell_size_));
    store(cell_size_, c, &GrassField::cellSizeChanged);
}

void GrassField::setDensity(double density) {
    if (!(density >= 0.0 && density <= 1.0)) return refuse(range_refusal("density", density, "0 .. 1", density_));
    store(density_, density, &GrassField::densityChanged);
}

void GrassField::setQuality(int q) {
    if (q < 0 || q >= GRASS_QUALITY_LEVEL_COUNT)
        return refuse(QStringLiteral("GrassField.quality: %1; it must be 0 (reference) .. 4 (fastest); kept %2")
                          .arg(q)
                          .arg(quality_));
    store(quality_, q, &GrassField::qualityChanged);
}

void GrassField::setDepthTest(bool on) {
    if (on == depth_test_) return;
    depth_test_ = on;
    emit depthTestChanged();
    if (window_) window_->update();
}

bool GrassField::loadMap(const QUrl& url, bool single_channel, const char* property, QImage* out) {
    if (url.isEmpty()) {
        *out = QImage();
        return true;
    }
    const QString path = QQmlFile::urlToLocalFileOrQrc(url);
    QImage image(path);
    if (image.isNull()) {
        refuse(QStringLiteral("GrassField.%1: \"%2\" is not an image Qt can read; kept the previous map")
                   .arg(QString::fromLatin1(property), url.toString()));
        return false;
    }
    *out = image.convertToFormat(single_channel ? QImage::Format_Grayscale8 : QImage::Format_RGBA8888);
    return true;
}

void GrassField::setDensityMap(const QUrl& url) {
    // Loaded only when it differs: store() compares again, to no effect.
    if (url != density_map_ && loadMap(url, true, "densityMap", &density_image_))
        store(density_map_, url, &GrassField::densityMapChanged);
}

void GrassField::setColorMap(const QUrl& url) {
    if (url != color_map_ && loadMap(url, false, "colorMap", &color_image_))
        store(color_map_, url, &GrassField::colorMapChanged);
}

void setUpGraphics(GraphicsApi api, int samples) {
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setSamples(samples > 1 ? samples : 0);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    if (api == GraphicsApi::opengl) {
        format.setVersion(4, 5);
        format.setProfile(QSurfaceFormat::CoreProfile);
    }
    QSurfaceFormat::setDefaultFormat(format);
    QQuickWindow::setGraphicsApi(api == GraphicsApi::vulkan ? QSGRendererInterface::Vulkan
                                                            : QSGRendererInterface::OpenGL);
}

void registerQmlTypes() { qmlRegisterType<GrassField>("Grass", 1, 0, "GrassField"); }

int liveRenderers() { return FieldRenderer::live_count(); }

int liveContexts() { return FieldRenderer::live_contexts(); }

} // namespace grass_qt
