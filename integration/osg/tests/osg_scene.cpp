#include "osg_scene.hpp"

#include <osg/Material>
#include <osg/Program>
#include <osg/ShapeDrawable>
#include <osg/Texture2D>
#include <osgViewer/GraphicsWindow>

#include <sys/stat.h>

#include <cmath>
#include <cstdlib>

namespace grass_osg_test {

OsgHost::OsgHost(const TargetFormat& format, std::string* error) {
    target_ = GlTarget::create(format, error);
    if (!target_) return;
    viewer_ = new osgViewer::Viewer;
    viewer_->setThreadingModel(osgViewer::Viewer::SingleThreaded);
    osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> window =
        new osgViewer::GraphicsWindowEmbedded(0, 0, int(format.width), int(format.height));
    window->setDefaultFboId(target_->framebuffer());
    osg::Camera* camera = viewer_->getCamera();
    camera->setGraphicsContext(window.get());
    camera->setViewport(0, 0, int(format.width), int(format.height));
    camera->setDrawBuffer(GL_COLOR_ATTACHMENT0);
    camera->setReadBuffer(GL_COLOR_ATTACHMENT0);
    clear_to(kSky);
    look(osg::Vec3d(0, 1, -1), osg::Vec3d(0, 0, 0), 45.0);
    viewer_->realize();
}

OsgHost::~OsgHost() {
    if (!target_) return;
    target_->make_current();
    viewer_ = nullptr; // closes the window: OSG deletes its GL objects (and grass's) with the context current
}

void OsgHost::look(const osg::Vec3d& eye, const osg::Vec3d& target, double fovy_degrees, bool compute_near_far) {
    osg::Camera* camera = viewer_->getCamera();
    camera->setViewMatrixAsLookAt(eye, target, osg::Vec3d(0, 1, 0));
    const TargetFormat& f = target_->format();
    camera->setProjectionMatrixAsPerspective(fovy_degrees, double(f.width) / f.height, 0.05, 500.0);
    camera->setComputeNearFarMode(compute_near_far ? osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES
                                                   : osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
}

osg::Vec4 OsgHost::colour(const float linear[3]) const {
    if (target_->format().srgb) return osg::Vec4(linear[0], linear[1], linear[2], 1.0f);
    return osg::Vec4(grass_host::linear_to_srgb(linear[0]), grass_host::linear_to_srgb(linear[1]),
                     grass_host::linear_to_srgb(linear[2]), 1.0f);
}

void OsgHost::clear_to(const float linear[3]) { viewer_->getCamera()->setClearColor(colour(linear)); }

grass_host::Image OsgHost::frame(osg::Node* scene) {
    target_->make_current();
    if (viewer_->getSceneData() != scene) viewer_->setSceneData(scene);
    viewer_->frame();
    return target_->read();
}

unsigned int OsgHost::context_id() const {
    return viewer_->getCamera()->getGraphicsContext()->getState()->getContextID();
}

grass_osg::FieldDesc field_desc(uint32_t cells) {
    grass_osg::FieldDesc d;
    d.patch.blade_count = 512;
    d.field.cells_x = cells;
    d.field.cells_z = cells;
    d.field.cell_size = 0.25;
    // The volume and image tiers' slices are baked once and read back by the other tests.
    const std::string cache = std::string(GRASS_OSG_TEST_OUT) + "/slice-cache";
    mkdir(GRASS_OSG_TEST_OUT, 0755);
    mkdir(cache.c_str(), 0755);
    d.cache_directory = cache;
    return d;
}

osg::ref_ptr<grass_osg::FieldDrawable> field_drawable(const grass_osg::FieldDesc& desc) {
    return new grass_osg::FieldDrawable(desc);
}

namespace {

osg::ref_ptr<osg::Geode> unlit(osg::Drawable* drawable, int bin) {
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(drawable);
    osg::StateSet* ss = geode->getOrCreateStateSet();
    ss->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    if (bin != 0) ss->setRenderBinDetails(bin, "RenderBin");
    return geode;
}

} // namespace

osg::ref_ptr<osg::Geode> box(const osg::Vec3& centre, const osg::Vec3& size, const osg::Vec4& colour, int bin) {
    osg::ref_ptr<osg::ShapeDrawable> shape = new osg::ShapeDrawable(new osg::Box(centre, size.x(), size.y(), size.z()));
    shape->setColor(colour);
    return unlit(shape.get(), bin);
}

osg::ref_ptr<osg::Geode> ground(float size, const osg::Vec4& colour) {
    osg::ref_ptr<osg::Geometry> quad =
        osg::createTexturedQuadGeometry(osg::Vec3(-1, 0, -1), osg::Vec3(0, 0, size), osg::Vec3(size, 0, 0));
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array(1, &colour);
    quad->setColorArray(colours.get(), osg::Array::BIND_OVERALL);
    return unlit(quad.get(), 0);
}

osg::ref_ptr<osg::Group> busy_models() {
    osg::ref_ptr<osg::Group> group = new osg::Group;
    // A lit sphere with a material, before grass.
    osg::ref_ptr<osg::Geode> sphere = new osg::Geode;
    sphere->addDrawable(new osg::ShapeDrawable(new osg::Sphere(osg::Vec3(1.0f, 0.3f, 1.5f), 0.25f)));
    osg::ref_ptr<osg::Material> material = new osg::Material;
    material->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(0.9f, 0.6f, 0.2f, 1.0f));
    sphere->getOrCreateStateSet()->setAttributeAndModes(material.get());
    group->addChild(sphere.get());
    // A textured quad (a checker), after grass.
    osg::ref_ptr<osg::Image> checker = new osg::Image;
    checker->allocateImage(8, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            unsigned char* p = checker->data(x, y);
            const unsigned char v = ((x + y) & 1) ? 250 : 40;
            p[0] = v;
            p[1] = 40;
            p[2] = 250 - v + 40;
            p[3] = 255;
        }
    }
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(checker.get());
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    osg::ref_ptr<osg::Geode> quad = unlit(
        osg::createTexturedQuadGeometry(osg::Vec3(2.6f, 0.0f, 1.2f), osg::Vec3(0.6f, 0, 0), osg::Vec3(0, 0.6f, 0)), 20);
    quad->getOrCreateStateSet()->setTextureAttributeAndModes(0, texture.get());
    group->addChild(quad.get());
    // A box drawn by a GLSL program, after grass.
    const float blue[3] = {0.1f, 0.2f, 0.8f};
    osg::ref_ptr<osg::Geode> shaded =
        box(osg::Vec3(1.9f, 0.45f, 2.6f), osg::Vec3(0.3f, 0.3f, 0.3f), osg::Vec4(blue[0], blue[1], blue[2], 1), 20);
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->addShader(new osg::Shader(osg::Shader::VERTEX, "#version 120\n"
                                                            "void main() { gl_Position = ftransform(); }\n"));
    program->addShader(new osg::Shader(osg::Shader::FRAGMENT, "#version 120\n"
                                                              "void main() { gl_FragColor = vec4(0.3, 0.5, "
                                                              "0.95, 1.0); }\n"));
    shaded->getOrCreateStateSet()->setAttributeAndModes(program.get());
    group->addChild(shaded.get());
    return group;
}

void expected_bytes(const float linear[3], uint8_t out[3]) {
    for (int c = 0; c < 3; ++c) out[c] = uint8_t(std::lround(grass_host::linear_to_srgb(linear[c]) * 255.0f));
}

bool near_colour(const uint8_t* pixel, const uint8_t expected[3], int tolerance) {
    for (int c = 0; c < 3; ++c) {
        if (std::abs(int(pixel[c]) - int(expected[c])) > tolerance) return false;
    }
    return true;
}

bool is_grass(const uint8_t* p) { return p[1] > p[0] + 8 && p[1] > p[2] + 8; }

} // namespace grass_osg_test
