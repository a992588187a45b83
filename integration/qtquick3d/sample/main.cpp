// grass-qtquick3d: a Qt Quick 3D scene with a grass field, a model and a camera you move
// (W A S D, R F, drag with the mouse). Options:
//   --backend vulkan|opengl   the QRhi backend (default vulkan)
//   --samples N               MSAA samples of the window (default 4)
//   --validate                Vulkan: with the Khronos validation layer
//   --screenshot FILE.png     render a few frames, save the window, quit
#include <grass_qtquick3d/grass_field.hpp>

#include <QCommandLineParser>
#include <QGuiApplication>
#include <QQmlApplicationEngine>
#include <QQuickWindow>
#include <QTimer>
#include <QVulkanInstance>

int main(int argc, char** argv) {
    QGuiApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription("grass in a Qt Quick 3D scene");
    parser.addHelpOption();
    const QCommandLineOption backend("backend", "vulkan or opengl", "API", "vulkan");
    const QCommandLineOption samples("samples", "MSAA samples", "N", "4");
    const QCommandLineOption validate("validate", "Vulkan validation layer");
    const QCommandLineOption screenshot("screenshot", "save the window to FILE and quit", "FILE");
    parser.addOptions({backend, samples, validate, screenshot});
    parser.process(app);
    const bool vulkan = parser.value(backend) == "vulkan";
    if (!vulkan && parser.value(backend) != "opengl") {
        qCritical("--backend is \"%s\"; it must be vulkan or opengl", qPrintable(parser.value(backend)));
        return 2;
    }
    grass_qt::setUpGraphics(vulkan ? grass_qt::GraphicsApi::vulkan : grass_qt::GraphicsApi::opengl,
                            parser.value(samples).toInt());
    grass_qt::registerQmlTypes();

    QVulkanInstance instance;
    if (vulkan) {
        if (parser.isSet(validate)) instance.setLayers({"VK_LAYER_KHRONOS_validation"});
        instance.setApiVersion(QVersionNumber(1, 1)); // grass's SPIR-V is for Vulkan 1.1 (Qt asks for 1.0)
        if (!instance.create()) {
            qCritical("no Vulkan instance (error %d)", instance.errorCode());
            return 1;
        }
    }
    QQmlApplicationEngine engine;
    QObject::connect(&engine, &QQmlApplicationEngine::objectCreated, &app, [&](QObject* object, const QUrl&) {
        auto* window = qobject_cast<QQuickWindow*>(object);
        if (!window) QCoreApplication::exit(1);
        if (vulkan) window->setVulkanInstance(&instance);
    });
    engine.load(QUrl("qrc:/main.qml"));
    if (engine.rootObjects().isEmpty()) return 1;
    auto* window = qobject_cast<QQuickWindow*>(engine.rootObjects().first());
    if (parser.isSet(screenshot)) {
        const QString path = parser.value(screenshot);
        QTimer::singleShot(1500, &app, [window, path]() {
            // The window's stored colour: grass keeps coverage in alpha and the window is opaque;
            // the grab is declared premultiplied, so alpha is dropped without un-premultiplying.
            QImage image = window->grabWindow();
            if (image.format() == QImage::Format_ARGB32_Premultiplied) image.reinterpretAsFormat(QImage::Format_RGB32);
            if (image.format() == QImage::Format_RGBA8888_Premultiplied)
                image.reinterpretAsFormat(QImage::Format_RGBX8888);
            const bool saved = image.save(path);
            QCoreApplication::exit(saved ? 0 : 1);
        });
    }
    return app.exec();
}
