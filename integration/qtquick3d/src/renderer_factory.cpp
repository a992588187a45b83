// The renderer for the window's graphics API.
#include "field_renderer.hpp"
#include "field_renderer_gl.hpp"
#include "field_renderer_vk.hpp"

#include <QQuickWindow>
#include <QSGRendererInterface>

namespace grass_qt {

FieldRenderer* FieldRenderer::create(QQuickWindow* window, std::shared_ptr<RendererReport> report) {
    switch (window->rendererInterface()->graphicsApi()) {
    case QSGRendererInterface::OpenGL:
        return new GlFieldRenderer(window, std::move(report));
    case QSGRendererInterface::Vulkan:
        return new VkFieldRenderer(window, std::move(report));
    default: {
        QMutexLocker lock(&report->mutex);
        report->error =
            QStringLiteral("GrassField draws with OpenGL or Vulkan; this window renders with graphics API %1")
                .arg(int(window->rendererInterface()->graphicsApi()));
        return nullptr;
    }
    }
}

} // namespace grass_qt
