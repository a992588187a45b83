#include "qtquick3d_fixture.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QGuiApplication>
#include <QMutex>
#include <QQuickItem>
#include <QTemporaryDir>
#include <QVulkanInstance>

#include <gtest/gtest.h>

#include <dlfcn.h>

namespace qt_test {

namespace {

QMutex g_messages_mutex;
std::vector<std::string> g_messages;
QVulkanInstance* g_instance = nullptr;
QTemporaryDir* g_dir = nullptr;

bool collect(VkDebugReportFlagsEXT flags, VkDebugReportObjectTypeEXT, uint64_t, size_t, int32_t, const char* prefix,
             const char* message) {
    if (flags & (VK_DEBUG_REPORT_ERROR_BIT_EXT | VK_DEBUG_REPORT_WARNING_BIT_EXT |
                 VK_DEBUG_REPORT_PERFORMANCE_WARNING_BIT_EXT)) {
        QMutexLocker lock(&g_messages_mutex);
        g_messages.push_back(std::string(prefix) + ": " + message);
    }
    return false; // Qt prints it too
}

// The bytes the window stores, alpha ignored. grass writes coverage into alpha and
// grabWindow() declares the image premultiplied: a conversion to an opaque format would
// un-premultiply (divide by that alpha) on the way, so the alpha is dropped by reinterpreting.
QImage stored_rgb(QImage image) {
    if (image.format() == QImage::Format_ARGB32_Premultiplied || image.format() == QImage::Format_ARGB32)
        image.reinterpretAsFormat(QImage::Format_RGB32);
    else if (image.format() == QImage::Format_RGBA8888_Premultiplied || image.format() == QImage::Format_RGBA8888)
        image.reinterpretAsFormat(QImage::Format_RGBX8888);
    return image.convertToFormat(QImage::Format_RGBX8888);
}

} // namespace

grass_qt::GraphicsApi backend() {
    return qgetenv("GRASS_QT_BACKEND") == "opengl" ? grass_qt::GraphicsApi::opengl : grass_qt::GraphicsApi::vulkan;
}

std::vector<std::string> take_validation_messages() {
    QMutexLocker lock(&g_messages_mutex);
    std::vector<std::string> m;
    m.swap(g_messages);
    return m;
}

std::unique_ptr<QQuickView> make_window(const QString& qml, int samples, QColor clear, int width, int height) {
    static int counter = 0;
    const QString path = g_dir->filePath(QStringLiteral("scene%1.qml").arg(++counter));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return nullptr;
    f.write(qml.toUtf8());
    f.close();
    auto window = std::make_unique<QQuickView>();
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setSamples(samples > 1 ? samples : 0);
    window->setFormat(format);
    if (g_instance) window->setVulkanInstance(g_instance);
    window->setColor(clear);
    window->setResizeMode(QQuickView::SizeRootObjectToView);
    window->resize(width, height);
    window->setSource(QUrl::fromLocalFile(path));
    if (window->status() != QQuickView::Ready) {
        for (const QQmlError& e : window->errors()) ADD_FAILURE() << e.toString().toStdString();
        return nullptr;
    }
    window->show();
    // Rendered only once exposed: grabWindow() on a window not yet exposed renders it
    // through a separate offscreen path, and Quick 3D then crashes at the real expose.
    QElapsedTimer timer;
    timer.start();
    while (!window->isExposed() && timer.elapsed() < 10000) QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    if (!window->isExposed()) {
        ADD_FAILURE() << "the window was not exposed within 10 s";
        return nullptr;
    }
    return window;
}

QObject* child(QQuickView* window, const char* name) {
    return window->rootObject()->findChild<QObject*>(QString::fromLatin1(name));
}

QString grass_scene(const QString& camera, const QString& models, const QString& field) {
    return QStringLiteral(R"(
import QtQuick
import QtQuick3D
import Grass 1.0
Item {
    View3D {
        id: view
        anchors.fill: parent
        renderMode: View3D.Inline
        environment: SceneEnvironment { backgroundMode: SceneEnvironment.Transparent }
        camera: cam
        PerspectiveCamera { id: cam; %1 }
%2
    }
    GrassField { objectName: "grass"; view: view; %3 }
}
)")
        .arg(camera, models, field); // in one pass: a % in an argument stays as it is
}

GrassWindow make_grass_window(const QString& qml, int samples, QColor clear) {
    GrassWindow w;
    w.window = make_window(qml, samples, clear);
    if (!w.window) return w; // make_window said why
    w.grass = child(w.window.get(), "grass");
    if (!w.grass) ADD_FAILURE() << "the scene has no GrassField \"grass\"";
    return w;
}

QImage render(QQuickView* window, QObject* grass, int frames) {
    const int target = grass->property("framesDrawn").toInt() + frames;
    QImage image;
    for (int k = 0; k < 40 && grass->property("framesDrawn").toInt() < target; ++k) {
        image = window->grabWindow();
        QCoreApplication::processEvents(); // the frame reports arrive queued
    }
    EXPECT_GE(grass->property("framesDrawn").toInt(), target)
        << "GrassField drew no frames: " << grass->property("errorString").toString().toStdString();
    return stored_rgb(image);
}

QImage render_frames(QQuickView* window, int frames) {
    QImage image;
    for (int k = 0; k < frames; ++k) {
        image = window->grabWindow();
        QCoreApplication::processEvents();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete); // no exec() loop here
    }
    return stored_rgb(image);
}

} // namespace qt_test

// gtest's main with a QGuiApplication, the backend chosen before any window, and the Vulkan
// validation layer enabled (its messages collected for the tests to check).
int main(int argc, char** argv) {
    qputenv("QSG_RENDER_LOOP", "basic"); // grabWindow renders on this thread
    // The Vulkan loader unloads lavapipe when the instance goes, EGL/GLX unload Mesa's GL driver
    // with the last context; what they keep until exit then has no module name (or another
    // module's) in LeakSanitizer's stacks and escapes its suppression by library
    // (tests/sanitizer/lsan.supp). Kept loaded, they are named (no effect elsewhere).
    dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);
    dlopen("/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so", RTLD_NOW | RTLD_NODELETE);
    ::testing::InitGoogleTest(&argc, argv);
    grass_qt::setUpGraphics(qt_test::backend(), 1);
    QGuiApplication app(argc, argv);
    grass_qt::registerQmlTypes();
    QTemporaryDir dir;
    qt_test::g_dir = &dir;
    QVulkanInstance instance;
    if (qt_test::backend() == grass_qt::GraphicsApi::vulkan) {
        if (qgetenv("GRASS_QT_VALIDATION") != "0") instance.setLayers({"VK_LAYER_KHRONOS_validation"});
        instance.setApiVersion(QVersionNumber(1, 1)); // grass's SPIR-V is for Vulkan 1.1
        instance.installDebugOutputFilter(qt_test::collect);
        if (!instance.create()) {
            fprintf(stderr, "no Vulkan instance (error %d)\n", instance.errorCode());
            return 1;
        }
        if (qgetenv("GRASS_QT_VALIDATION") != "0" && !instance.layers().contains("VK_LAYER_KHRONOS_validation")) {
            fprintf(stderr, "the Vulkan validation layer is not available\n");
            return 1;
        }
        qt_test::g_instance = &instance;
    }
    const int result = RUN_ALL_TESTS();
    qt_test::g_instance = nullptr;
    return result;
}
