// grass-osg-viewer: a grass field in an OpenSceneGraph scene. An osgViewer window with OSG's
// manipulators (1 trackball, 2 terrain, 3 first person; the mouse as OSG's manipulators
// take it), OSG models standing in the grass, and grass drawn by grass_osg::FieldDrawable.
//
//   grass-osg-viewer [--model FILE] [--frames N --screenshot FILE.png] [--size W H] [--tiers]
//
// --model loads a model any OSG plugin reads (osgconv's formats; z up, metres) and stands it
// in the middle of the field instead of the built-in cottage. --frames N draws N frames and
// quits (exit status 1 when the built-in scene's last frame is under a quarter grass); with
// --screenshot the last one is written to a PNG.
#include <grass_osg/field_drawable.hpp>

#include <osg/Geode>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osg/ShapeDrawable>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgGA/FirstPersonManipulator>
#include <osgGA/KeySwitchMatrixManipulator>
#include <osgGA/StateSetManipulator>
#include <osgGA/TerrainManipulator>
#include <osgGA/TrackballManipulator>
#include <osgViewer/Viewer>
#include <osgViewer/ViewerEventHandlers>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>

namespace {

constexpr double kFieldSize = 40.0; // metres a side

osg::ref_ptr<osg::Geode> shape(osg::Shape* s, const osg::Vec4& colour) {
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::ShapeDrawable> drawable = new osg::ShapeDrawable(s);
    drawable->setColor(colour);
    geode->addDrawable(drawable.get());
    return geode;
}

// A cottage of OSG shapes (z up): walls, a roof, a chimney; and a tree beside it.
osg::ref_ptr<osg::Node> cottage() {
    osg::ref_ptr<osg::Group> g = new osg::Group;
    g->addChild(shape(new osg::Box(osg::Vec3(0, 0, 1.5f), 6, 4, 3), osg::Vec4(0.85f, 0.8f, 0.7f, 1)).get());
    osg::ref_ptr<osg::Cone> roof = new osg::Cone(osg::Vec3(0, 0, 3.2f), 4.2f, 2.6f);
    g->addChild(shape(roof.get(), osg::Vec4(0.55f, 0.2f, 0.15f, 1)).get());
    g->addChild(
        shape(new osg::Box(osg::Vec3(1.5f, 1.0f, 5.0f), 0.5f, 0.5f, 1.6f), osg::Vec4(0.4f, 0.4f, 0.4f, 1)).get());
    g->addChild(shape(new osg::Cylinder(osg::Vec3(7, 3, 1.5f), 0.3f, 3), osg::Vec4(0.35f, 0.25f, 0.15f, 1)).get());
    g->addChild(shape(new osg::Sphere(osg::Vec3(7, 3, 4), 1.8f), osg::Vec4(0.2f, 0.45f, 0.15f, 1)).get());
    return g;
}

// Reads the last frame's colour buffer: counts its grass pixels (green above red and blue)
// and writes it to a PNG when asked (osgDB's png plugin).
struct LastFrame : osg::Camera::DrawCallback {
    std::string path;
    mutable bool armed = false;
    mutable double grass_fraction = 0.0;
    void operator()(osg::RenderInfo& info) const override {
        if (!armed) return;
        armed = false;
        const osg::Viewport* vp = info.getState()->getCurrentViewport();
        osg::ref_ptr<osg::Image> image = new osg::Image;
        image->readPixels(int(vp->x()), int(vp->y()), int(vp->width()), int(vp->height()), GL_RGB, GL_UNSIGNED_BYTE);
        size_t grass = 0;
        const size_t pixels = size_t(image->s()) * size_t(image->t());
        for (size_t i = 0; i < pixels; ++i) {
            const unsigned char* p = image->data() + 3 * i;
            grass += p[1] > p[0] + 8 && p[1] > p[2] + 8;
        }
        grass_fraction = pixels ? double(grass) / double(pixels) : 0.0;
        if (!path.empty() && !osgDB::writeImageFile(*image, path)) std::cerr << "could not write " << path << "\n";
    }
};

} // namespace

int main(int argc, char** argv) {
    osg::ArgumentParser args(&argc, argv);
    std::string model_path, screenshot_path;
    int frames = 0, width = 1280, height = 720;
    args.read("--model", model_path);
    args.read("--screenshot", screenshot_path);
    args.read("--frames", frames);
    args.read("--size", width, height);
    const bool tiers = args.read("--tiers");
    if (args.read("--help") || args.read("-h")) {
        std::cout << "usage: grass-osg-viewer [--model FILE] [--frames N [--screenshot FILE.png]] [--size W H] "
                     "[--tiers]\n";
        return 0;
    }
    if (frames < 0 || width <= 0 || height <= 0) {
        std::cerr << "grass-osg-viewer: --frames must be >= 0 and --size positive (got " << frames << ", " << width
                  << " x " << height << ")\n";
        return 2;
    }

    // The field: 40 m x 40 m of 0.25 m cells centred on the origin, lying in OSG's z-up world.
    grass_osg::FieldDesc desc;
    desc.field.cell_size = 0.25;
    desc.field.cells_x = desc.field.cells_z = uint32_t(kFieldSize / desc.field.cell_size);
    const double origin[3] = {-kFieldSize / 2, kFieldSize / 2, 0.0};
    grass_osg::z_up_base_transform(origin, desc.field.base_transform);
    osg::ref_ptr<grass_osg::FieldDrawable> grass;
    try {
        grass = new grass_osg::FieldDrawable(desc);
    } catch (const std::invalid_argument& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    grass_osg::Lights lights;
    const float sun[3] = {0.35f, -0.25f, 0.8f}; // z up
    std::copy(sun, sun + 3, lights.sun_direction);
    grass->setLights(lights);
    if (tiers) grass->setViewFlags(GRASS_VIEW_FLAG_DEBUG_TIERS);

    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Geode> field = new osg::Geode;
    field->addDrawable(grass.get());
    root->addChild(field.get());
    osg::ref_ptr<osg::Node> model = model_path.empty() ? cottage() : osgDB::readRefNodeFile(model_path);
    if (!model) {
        std::cerr << "grass-osg-viewer: --model " << model_path << ": no OSG plugin could read it\n";
        return 1;
    }
    root->addChild(model.get());
    // The soil under the grass: an OSG quad, a little larger than the field.
    osg::ref_ptr<osg::Geode> soil = shape(new osg::Box(osg::Vec3(0, 0, -0.05f), kFieldSize + 2, kFieldSize + 2, 0.1f),
                                          osg::Vec4(0.24f, 0.2f, 0.13f, 1));
    root->addChild(soil.get());

    // Debian's OSG draws with the legacy pipeline: a compatibility context, GL 4.5 for grass
    // (set before the window is made).
    osg::DisplaySettings::instance()->setGLContextVersion("4.5");
    osg::DisplaySettings::instance()->setGLContextProfileMask(0x2); // GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB
    osgViewer::Viewer viewer(args);
    viewer.setSceneData(root.get());
    viewer.setUpViewInWindow(40, 40, width, height);
    viewer.getCamera()->setClearColor(osg::Vec4(0.76f, 0.85f, 0.95f, 1)); // sRGB bytes: the window is RGBA8
    osg::ref_ptr<osgGA::KeySwitchMatrixManipulator> manipulators = new osgGA::KeySwitchMatrixManipulator;
    manipulators->addMatrixManipulator('1', "Trackball", new osgGA::TrackballManipulator);
    manipulators->addMatrixManipulator('2', "Terrain", new osgGA::TerrainManipulator);
    manipulators->addMatrixManipulator('3', "FirstPerson", new osgGA::FirstPersonManipulator);
    // Home: standing in the grass at the field's corner, looking at the cottage.
    manipulators->setHomePosition(osg::Vec3d(-11, -17, 2.2), osg::Vec3d(2, 2, 1.6), osg::Vec3d(0, 0, 1));
    manipulators->setAutoComputeHomePosition(false);
    viewer.setCameraManipulator(manipulators.get());
    viewer.addEventHandler(new osgGA::StateSetManipulator(viewer.getCamera()->getOrCreateStateSet()));
    viewer.addEventHandler(new osgViewer::StatsHandler);
    osg::ref_ptr<LastFrame> last_frame = new LastFrame;
    last_frame->path = screenshot_path;
    viewer.getCamera()->setFinalDrawCallback(last_frame.get());
    viewer.realize();
    if (!viewer.isRealized()) {
        std::cerr << "grass-osg-viewer: no window (a display is needed; try xvfb-run -a)\n";
        return 1;
    }
    if (frames == 0) return viewer.run();
    // Counted frames: the last frame's draw must have finished when frame() returns.
    viewer.setThreadingModel(osgViewer::Viewer::SingleThreaded);
    for (int i = 0; i < frames && !viewer.done(); ++i) {
        last_frame->armed = i == frames - 1;
        viewer.frame();
    }
    if (!grass->lastError().empty()) {
        std::cerr << "grass-osg-viewer: " << grass->lastError() << "\n";
        return 1;
    }
    // The sample's own check (ctest osg_viewer_shows_grass): grass fills a good part of the
    // home view, around the cottage.
    std::cout << "grass-osg-viewer: " << frames << " frames, grass in " << 100.0 * last_frame->grass_fraction
              << "% of the last one\n";
    return model_path.empty() && last_frame->grass_fraction < 0.25 ? 1 : 0;
}
