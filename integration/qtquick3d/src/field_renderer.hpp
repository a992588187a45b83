// The render-thread half of a GrassField: one grass context per scene graph, with the
// field's patch, maps and field, driven by the window's frame signals. GL and Vulkan
// subclasses hand grass the graphics API's resources and record the draws.
#pragma once

#include "field_settings.hpp"

#include <grass/grass.h>

#include <QMutex>
#include <QObject>
#include <QString>
#include <QVariantMap>

#include <atomic>
#include <functional>
#include <memory>

class QQuickWindow;

namespace grass_qt {

// What the renderer reports back to its item (shared: either may outlive the other).
struct RendererReport {
    QMutex mutex;
    QString error;
    QVariantMap memory;
    int frames = 0;
    std::function<void()> notify; // called under the mutex; posts to the item's thread
};

class FieldRenderer : public QObject {
public:
    // A renderer for the window's graphics API (OpenGL or Vulkan), or nullptr (and an error
    // in the report) for another.
    static FieldRenderer* create(QQuickWindow* window, std::shared_ptr<RendererReport> report);
    ~FieldRenderer() override;

    // At sync (render thread, GUI thread blocked).
    void set_settings(const FieldSettings& settings) { pending_ = std::make_unique<FieldSettings>(settings); }
    void set_frame(const FrameInput& frame) { frame_ = frame; }

    // Its item is gone: draws no more, and destroys itself (and its context) once the
    // window's command buffers that recorded grass have been recorded again without it.
    // Any thread (the item's); the renderer acts on it in its next frame or at invalidation.
    void retire() { retired_ = true; }

    // Renderers alive in the process (tests check that rebuilds do not leak them).
    static int live_count();
    static int live_contexts();

protected:
    FieldRenderer(QQuickWindow* window, std::shared_ptr<RendererReport> report);
    // Creates context_ from the window's graphics resources (in the first frame).
    virtual bool create_context(const grass_context_desc& desc, QString* error) = 0;
    // Outside the render pass, after grass_begin_frame (Vulkan: uploads and barriers).
    virtual grass_result prepare(QString* error);
    // Inside the render pass, inside begin/endExternalCommands.
    virtual grass_result draw(QString* error) = 0;
    // Before objects the GPU may still read are destroyed (Vulkan: waits for the device).
    virtual void wait_idle() {}
    // Before grass's calls: errors Qt left pending in the API (GL: glGetError) would be
    // taken for grass's own.
    virtual void clear_host_errors() {}
    // Call from the subclass's destructor (it still has its API then).
    void destroy_context();

    QQuickWindow* window_;
    grass_context* context_ = nullptr;

private:
    void frame_start();
    void begin_external_commands();
    void scene_graph_invalidated();
    void main_pass_end();
    bool rebuild(const FieldSettings& settings);
    void destroy_objects();
    void report_error(const QString& message);
    void report_frame();

    std::shared_ptr<RendererReport> report_;
    std::unique_ptr<FieldSettings> pending_;
    FrameInput frame_;
    bool failed_ = false;
    std::atomic<bool> retired_{false};
    int frames_since_retired_ = 0;
    bool frame_begun_ = false;
    grass_patch_id patch_{};
    grass_field_id field_{};
    grass_map_id density_map_{}, color_map_{};
};

} // namespace grass_qt
