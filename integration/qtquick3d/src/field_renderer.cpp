#include "field_renderer.hpp"

#include <QAtomicInt>
#include <QMetaObject>
#include <QQuickWindow>

#include <cmath>

namespace grass_qt {

namespace {

QAtomicInt g_live_renderers, g_live_contexts;

void GRASS_API_PTR log_to_report(void* user_data, grass_log_level level, grass_message_id id, const char* message) {
    if (level != GRASS_LOG_ERROR) return;
    auto* report = static_cast<RendererReport*>(user_data);
    QMutexLocker lock(&report->mutex);
    report->error = QStringLiteral("grass (message %1): %2").arg(int(id)).arg(QString::fromUtf8(message));
}

grass_map_desc map_desc(const QImage& image, grass_map_format format) {
    grass_map_desc d = grass_default_map_desc();
    d.pixels = image.constBits();
    d.width = static_cast<uint32_t>(image.width());
    d.height = static_cast<uint32_t>(image.height());
    d.row_pitch = static_cast<uint32_t>(image.bytesPerLine());
    d.format = format;
    return d;
}

} // namespace

FieldRenderer::FieldRenderer(QQuickWindow* window, std::shared_ptr<RendererReport> report)
    : window_(window), report_(std::move(report)) {
    g_live_renderers.ref();
    // Both on the render thread: before the main pass (plan, uploads) and at its end (draws).
    connect(window, &QQuickWindow::beforeRendering, this, &FieldRenderer::frame_start, Qt::DirectConnection);
    connect(window, &QQuickWindow::afterRenderPassRecording, this, &FieldRenderer::main_pass_end, Qt::DirectConnection);
    // The window's device or GL context goes: grass's objects on it go first.
    connect(window, &QQuickWindow::sceneGraphInvalidated, this, &FieldRenderer::scene_graph_invalidated,
            Qt::DirectConnection);
}

FieldRenderer::~FieldRenderer() { g_live_renderers.deref(); }

int FieldRenderer::live_count() { return g_live_renderers.loadRelaxed(); }

int FieldRenderer::live_contexts() { return g_live_contexts.loadRelaxed(); }

grass_result FieldRenderer::prepare(QString*) { return GRASS_SUCCESS; }

void FieldRenderer::scene_graph_invalidated() {
    destroy_context();
    if (retired_) deleteLater(); // its item is gone: nothing else will delete it
}

void FieldRenderer::begin_external_commands() {
    window_->beginExternalCommands();
    clear_host_errors();
}

void FieldRenderer::destroy_context() {
    if (!context_) return;
    wait_idle();
    grass_destroy_context(context_); // destroys the field, maps and patch with it
    context_ = nullptr;
    g_live_contexts.deref();
    field_ = {};
    color_map_ = density_map_ = {};
    patch_ = {};
    pending_.reset();
}

void FieldRenderer::report_error(const QString& message) {
    {
        QMutexLocker lock(&report_->mutex);
        report_->error = message;
        if (report_->notify) report_->notify();
    }
    qWarning("GrassField: %s", qPrintable(message));
}

void FieldRenderer::frame_start() {
    frame_begun_ = false;
    if (retired_) {
        // Qt records frame slot after frame slot; frames in flight + 1 frames from now none
        // of its command buffers refers to grass's objects any more.
        if (context_ && ++frames_since_retired_ > window_->graphicsStateInfo().framesInFlight) {
            destroy_context();
            deleteLater(); // the QObject, on the render thread's event loop
        }
        return;
    }
    if (failed_) return;
    if (!context_) {
        grass_context_desc desc = grass_default_context_desc();
        desc.log_fn = log_to_report;
        desc.log_user_data = report_.get();
        QString error;
        begin_external_commands();
        const bool ok = create_context(desc, &error);
        window_->endExternalCommands();
        if (!ok) {
            failed_ = true; // not retried every frame: the window's resources will not change
            QString logged;
            {
                QMutexLocker lock(&report_->mutex);
                logged = report_->error; // what grass logged, if it got that far
            }
            report_error(
                QStringLiteral("no grass context: %1%2").arg(error, logged.isEmpty() ? QString() : ": " + logged));
            return;
        }
        g_live_contexts.ref();
    }
    if (pending_) {
        const std::unique_ptr<FieldSettings> settings = std::move(pending_);
        begin_external_commands();
        rebuild(*settings);
        window_->endExternalCommands();
    }
    if (grass_field_id_is_null(field_) || !frame_.valid) return;
    if (grass_begin_frame(context_, &frame_.view) != GRASS_SUCCESS) {
        report_error(QString::fromUtf8(grass_get_last_error(context_)));
        return;
    }
    QString error;
    begin_external_commands();
    const grass_result r = prepare(&error);
    window_->endExternalCommands();
    if (r != GRASS_SUCCESS) {
        report_error(error);
        grass_end_frame(context_);
        return;
    }
    frame_begun_ = true;
}

void FieldRenderer::main_pass_end() {
    if (!frame_begun_) return;
    frame_begun_ = false;
    QString error;
    begin_external_commands();
    const grass_result r = draw(&error);
    window_->endExternalCommands();
    grass_end_frame(context_);
    if (r != GRASS_SUCCESS) {
        report_error(error);
        return;
    }
    report_frame();
}

void FieldRenderer::report_frame() {
    grass_memory_stats stats{};
    grass_get_memory_stats(context_, &stats);
    {
        QMutexLocker lock(&report_->mutex);
        report_->memory = QVariantMap{{QStringLiteral("hostBytes"), qulonglong(stats.host_bytes)},
                                      {QStringLiteral("hostAllocations"), qulonglong(stats.host_allocations)},
                                      {QStringLiteral("gpuBytes"), qulonglong(stats.gpu_bytes)},
                                      {QStringLiteral("live"), true}};
        ++report_->frames;
        if (report_->notify) report_->notify();
    }
}

bool FieldRenderer::rebuild(const FieldSettings& s) {
    // Everything new is made first: on a refusal it is destroyed and the field drawn so far stays.
    grass_patch_desc patch_desc = grass_default_patch_desc();
    grass_tier_desc tiers[GRASS_MAX_TIERS];
    grass_lod_test tests[GRASS_MAX_LOD_TESTS];
    uint32_t tier_count = 0, test_count = 0;
    const grass_quality_desc quality = grass_quality_preset(static_cast<grass_quality_level>(s.quality));
    grass_patch_id patch{};
    grass_map_id density_map{}, color_map{};
    grass_field_id field{};
    auto fail = [&]() {
        report_error(QString::fromUtf8(grass_get_last_error(context_)));
        if (!grass_field_id_is_null(field)) grass_destroy_field(context_, field);
        if (!grass_map_id_is_null(color_map)) grass_destroy_map(context_, color_map);
        if (!grass_map_id_is_null(density_map)) grass_destroy_map(context_, density_map);
        if (!grass_patch_id_is_null(patch)) grass_destroy_patch(context_, patch);
        return false;
    };
    if (grass_apply_quality(context_, &quality, s.cell_size, &patch_desc, tiers, &tier_count, tests, &test_count) !=
            GRASS_SUCCESS ||
        grass_create_patch(context_, &patch_desc, &patch) != GRASS_SUCCESS)
        return fail();
    grass_field_desc field_desc = grass_default_field_desc();
    if (!s.density_map.isNull()) {
        const grass_map_desc d = map_desc(s.density_map, GRASS_MAP_FORMAT_R8_UNORM);
        if (grass_create_map(context_, &d, &density_map) != GRASS_SUCCESS) return fail();
        field_desc.maps.density = density_map;
    }
    if (!s.color_map.isNull()) {
        const grass_map_desc d = map_desc(s.color_map, GRASS_MAP_FORMAT_RGBA8_UNORM);
        if (grass_create_map(context_, &d, &color_map) != GRASS_SUCCESS) return fail();
        field_desc.maps.color = color_map;
    }
    field_desc.patch = patch;
    field_desc.cell_size = s.cell_size;
    // At least one cell each way; the extent is rounded to whole cells around the centre.
    field_desc.cells_x = static_cast<uint32_t>(std::max(1.0, std::round(s.extent.width() / s.cell_size)));
    field_desc.cells_z = static_cast<uint32_t>(std::max(1.0, std::round(s.extent.height() / s.cell_size)));
    field_desc.base_transform[12] = s.position.x() - 0.5 * field_desc.cells_x * s.cell_size;
    field_desc.base_transform[13] = s.position.y();
    field_desc.base_transform[14] = s.position.z() - 0.5 * field_desc.cells_z * s.cell_size;
    field_desc.density = static_cast<float>(s.density);
    field_desc.tiers = tiers;
    field_desc.tier_count = tier_count;
    field_desc.lod_tests = tests;
    field_desc.lod_test_count = test_count;
    if (grass_create_field(context_, &field_desc, &field) != GRASS_SUCCESS) return fail();

    wait_idle(); // the old field's buffers may still be read by frames in flight
    destroy_objects();
    patch_ = patch;
    density_map_ = density_map;
    color_map_ = color_map;
    field_ = field;
    return true;
}

void FieldRenderer::destroy_objects() {
    if (!grass_field_id_is_null(field_)) grass_destroy_field(context_, field_);
    if (!grass_map_id_is_null(color_map_)) grass_destroy_map(context_, color_map_);
    if (!grass_map_id_is_null(density_map_)) grass_destroy_map(context_, density_map_);
    if (!grass_patch_id_is_null(patch_)) grass_destroy_patch(context_, patch_);
    field_ = {};
    color_map_ = density_map_ = {};
    patch_ = {};
}

} // namespace grass_qt
