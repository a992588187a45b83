// GrassField: a grass field inside a Qt Quick 3D scene, as a QML type.
//
//   import Grass 1.0
//   View3D { id: view; renderMode: View3D.Inline; camera: cam; ... }
//   GrassField { view: view; extent: Qt.size(1200, 1200); cellSize: 25 }
//
// It draws into the window's main render pass after Qt has recorded it (View3D.Inline shares
// that pass and its depth buffer with Quick 3D's models), with the View3D's camera.
// Lengths are in the scene's units (Quick 3D's convention is centimetres: a #Cube is 100
// units): grass is scale-free, its tiers and blades scale with cellSize.
// docs/integration-qtquick3d.md describes the hooks, conventions and limits.
#pragma once

#include <QImage>
#include <QPointer>
#include <QQuickItem>
#include <QSizeF>
#include <QUrl>
#include <QVariantMap>
#include <QVector3D>

#include <memory>

namespace grass_qt {

class FieldRenderer;
struct RendererReport;

class GrassField : public QQuickItem {
    Q_OBJECT
    // The View3D whose camera and viewport grass draws with (renderMode: View3D.Inline).
    Q_PROPERTY(QQuickItem* view READ view WRITE setView NOTIFY viewChanged)
    // The field's centre on the ground plane (y is its height), scene units.
    Q_PROPERTY(QVector3D position READ position WRITE setPosition NOTIFY positionChanged)
    // Width along x and depth along z, scene units, each > 0; rounded to whole cells.
    Q_PROPERTY(QSizeF extent READ extent WRITE setExtent NOTIFY extentChanged)
    // Edge of one cell (one patch of blades), scene units, 1e-4 .. 1e4.
    Q_PROPERTY(double cellSize READ cellSize WRITE setCellSize NOTIFY cellSizeChanged)
    // Uniform density 0..1 (multiplies the density map).
    Q_PROPERTY(double density READ density WRITE setDensity NOTIFY densityChanged)
    // grass_quality_level: 0 reference, 1 high, 2 default, 3 low, 4 fastest.
    Q_PROPERTY(int quality READ quality WRITE setQuality NOTIFY qualityChanged)
    // Design maps from image sources (file:, qrc:, or a plain path): grey density, RGBA colour
    // (sRGB rgb, alpha = weight). The image's top row lies along the field's -z edge. Empty: none.
    Q_PROPERTY(QUrl densityMap READ densityMap WRITE setDensityMap NOTIFY densityMapChanged)
    Q_PROPERTY(QUrl colorMap READ colorMap WRITE setColorMap NOTIFY colorMapChanged)
    // Debugging: false draws grass without its depth test (over the scene's models).
    Q_PROPERTY(bool depthTest READ depthTest WRITE setDepthTest NOTIFY depthTestChanged)
    // The last refusal (a bad property value, an unreadable map, an error from grass), or "".
    Q_PROPERTY(QString errorString READ errorString NOTIFY errorStringChanged)
    // Frames drawn with grass since the item was made (tests wait on it).
    Q_PROPERTY(int framesDrawn READ framesDrawn NOTIFY framesDrawnChanged)

public:
    explicit GrassField(QQuickItem* parent = nullptr);
    ~GrassField() override;

    QQuickItem* view() const { return view_; }
    void setView(QQuickItem* view);
    QVector3D position() const { return position_; }
    void setPosition(const QVector3D& position);
    QSizeF extent() const { return extent_; }
    void setExtent(const QSizeF& extent);
    double cellSize() const { return cell_size_; }
    void setCellSize(double cell_size);
    double density() const { return density_; }
    void setDensity(double density);
    int quality() const { return quality_; }
    void setQuality(int quality);
    QUrl densityMap() const { return density_map_; }
    void setDensityMap(const QUrl& url);
    QUrl colorMap() const { return color_map_; }
    void setColorMap(const QUrl& url);
    bool depthTest() const { return depth_test_; }
    void setDepthTest(bool on);
    QString errorString() const;
    int framesDrawn() const;

    // The grass context's memory (grass_memory_stats) after the last frame drawn:
    // {hostBytes, hostAllocations, gpuBytes, live}; live is false when no context exists.
    Q_INVOKABLE QVariantMap memoryStats() const;

signals:
    void viewChanged();
    void positionChanged();
    void extentChanged();
    void cellSizeChanged();
    void densityChanged();
    void qualityChanged();
    void densityMapChanged();
    void colorMapChanged();
    void depthTestChanged();
    void errorStringChanged();
    void framesDrawnChanged();

protected:
    void itemChange(ItemChange change, const ItemChangeData& data) override;
    void releaseResources() override;

private slots:
    void sync();
    void invalidateSceneGraph();
    void reportFrame();

private:
    void refuse(const QString& message);
    void attachWindow(QQuickWindow* window);
    // Sets a setting to `value` where it differs: the renderer gets the settings at the next
    // sync (the window asked to update), QML hears `notify`.
    template <typename T>
    void store(T& setting, const T& value, void (GrassField::*notify)());
    bool loadMap(const QUrl& url, bool single_channel, const char* property, QImage* out);
    void dropRenderer();

    QPointer<QQuickItem> view_;
    QVector3D position_;
    QSizeF extent_{400.0, 400.0};
    double cell_size_ = 25.0;
    double density_ = 1.0;
    int quality_ = 2;
    QUrl density_map_, color_map_;
    QImage density_image_, color_image_;
    bool depth_test_ = true;
    bool settings_dirty_ = true;        // handed to the renderer at the next sync
    FieldRenderer* renderer_ = nullptr; // lives and dies on the render thread
    QQuickWindow* window_ = nullptr;    // the window attached to, as windowChanged said
    std::shared_ptr<RendererReport> report_;
    QString last_error_;
};

// The graphics API Qt Quick renders with (a QRhi backend grass draws with).
enum class GraphicsApi { opengl, vulkan };

// Call before the first window is created: selects the API (QQuickWindow::setGraphicsApi)
// and the default surface format's sample count (1 = no MSAA); on OpenGL it also requests
// the 4.5 core context grass needs (Qt's default format asks for no version). The host still owns
// the QVulkanInstance (QQuickWindow::setVulkanInstance) if it wants one of its own.
void setUpGraphics(GraphicsApi api, int samples);

// Registers GrassField as "Grass" 1.0 for QML. Call once before loading QML that uses it.
void registerQmlTypes();

// Render-thread halves of GrassFields alive in the process (tests check rebuilds free them).
int liveRenderers();
// grass contexts those renderers hold (one per GrassField whose scene graph has drawn).
int liveContexts();

} // namespace grass_qt
