// One grass context per OSG graphics context, shared by the cameras on it; created at the
// first draw and destroyed through OSG's deletion queue when a scene-graph rebuild drops
// the drawable or the context closes (the ASan build checks that nothing leaks).
#include "osg_scene.hpp"

#include <osgViewer/CompositeViewer>

namespace grass_osg_test {
namespace {

size_t count_grass(const grass_host::Image& image, uint32_t x0, uint32_t x1) {
    size_t n = 0;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = x0; x < x1; ++x) n += is_grass(image.pixel(x, y));
    }
    return n;
}

osg::ref_ptr<osg::Geode> holding(grass_osg::FieldDrawable* grass) {
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(grass);
    return geode;
}

TEST(LifetimeTest, SceneGraphRebuildsDestroyTheGrassContextsTheyDrop) {
    const int before = grass_osg::FieldDrawable::liveGrassContexts();
    {
        std::string error;
        OsgHost host(TargetFormat{}, &error);
        if (!host.ok()) GTEST_SKIP() << "no GL 4.5 compatibility context: " << error;
        host.look(osg::Vec3d(2.0, 0.9, -0.5), osg::Vec3d(2.0, 0.0, 2.0), 45.0);
        grass_memory_stats first{};
        for (int rebuild = 0; rebuild < 4; ++rebuild) {
            osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(field_desc(16));
            const auto image = host.frame(holding(grass.get()).get()); // the old graph is dropped here
            EXPECT_GT(count_grass(image, 0, image.width), image.width * image.height / 5u);
            grass_context* context = grass->grassContext(host.context_id());
            ASSERT_NE(context, nullptr);
            grass_memory_stats stats{};
            ASSERT_EQ(grass_get_memory_stats(context, &stats), GRASS_SUCCESS);
            if (rebuild == 0) first = stats;
            EXPECT_EQ(stats.host_bytes, first.host_bytes) << "rebuild " << rebuild;
            EXPECT_EQ(stats.gpu_bytes, first.gpu_bytes) << "rebuild " << rebuild;
            // The dropped drawable's grass context waits in OSG's deletion queue until the
            // frame's flush: at most the new one and the dropped one are alive.
            EXPECT_LE(grass_osg::FieldDrawable::liveGrassContexts() - before, 2) << "rebuild " << rebuild;
        }
        host.frame(nullptr);
        host.frame(nullptr);
        EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 0) << "the flush destroyed the last one";

        // releaseGLObjects with the state of one context.
        osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(field_desc(16));
        host.frame(holding(grass.get()).get());
        EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 1);
        grass->releaseGLObjects(host.viewer().getCamera()->getGraphicsContext()->getState());
        EXPECT_EQ(grass->grassContext(host.context_id()), nullptr);
        host.frame(holding(grass.get()).get()); // queued one flushed, a new one made
        EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 1);
    }
    EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 0) << "the context's close destroyed it";
}

TEST(LifetimeTest, EachGlContextHasItsOwnGrassContext) {
    const int before = grass_osg::FieldDrawable::liveGrassContexts();
    std::string error;
    auto a = std::make_unique<OsgHost>(TargetFormat{}, &error);
    if (!a->ok()) GTEST_SKIP() << "no GL 4.5 compatibility context: " << error;
    auto b = std::make_unique<OsgHost>(TargetFormat{}, &error);
    ASSERT_TRUE(b->ok()) << error;
    ASSERT_NE(a->context_id(), b->context_id());
    // One drawable in both scene graphs.
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(field_desc(16));
    osg::ref_ptr<osg::Geode> geode = holding(grass.get());
    for (OsgHost* host : {a.get(), b.get()}) host->look(osg::Vec3d(2.0, 0.9, -0.5), osg::Vec3d(2.0, 0.0, 2.0), 45.0);
    const auto image_a = a->frame(geode.get());
    const auto image_b = b->frame(geode.get());
    EXPECT_GT(count_grass(image_a, 0, 128), 128u * 128u / 5);
    EXPECT_GT(count_grass(image_b, 0, 128), 128u * 128u / 5);
    grass_context* ca = grass->grassContext(a->context_id());
    grass_context* cb = grass->grassContext(b->context_id());
    EXPECT_NE(ca, nullptr);
    EXPECT_NE(cb, nullptr);
    EXPECT_NE(ca, cb);
    EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 2);
    b.reset(); // closes b's GL context: its grass context goes with it, a's stays
    EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 1);
    EXPECT_EQ(count_grass(a->frame(geode.get()), 0, 128), count_grass(image_a, 0, 128));
    a.reset();
    EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 0);
}

// Two views on one GL context (a split screen through osgViewer::CompositeViewer): each
// draws grass with its own camera, and they share one grass context.
TEST(LifetimeTest, CamerasOnOneGlContextShareOneGrassContext) {
    const int before = grass_osg::FieldDrawable::liveGrassContexts();
    std::string error;
    std::unique_ptr<GlTarget> target = GlTarget::create(TargetFormat{}, &error);
    if (!target) GTEST_SKIP() << "no GL 4.5 compatibility context: " << error;
    osg::ref_ptr<grass_osg::FieldDrawable> grass = field_drawable(field_desc(16));
    osg::ref_ptr<osg::Geode> geode = holding(grass.get());
    {
        osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> window = new osgViewer::GraphicsWindowEmbedded(0, 0, 128, 128);
        window->setDefaultFboId(target->framebuffer());
        osgViewer::CompositeViewer viewer;
        viewer.setThreadingModel(osgViewer::CompositeViewer::SingleThreaded);
        const double eyes_x[2] = {1.0, 3.0};
        for (int i = 0; i < 2; ++i) {
            osg::ref_ptr<osgViewer::View> view = new osgViewer::View;
            osg::Camera* camera = view->getCamera();
            camera->setGraphicsContext(window.get());
            camera->setViewport(64 * i, 0, 64, 128);
            camera->setDrawBuffer(GL_COLOR_ATTACHMENT0);
            camera->setReadBuffer(GL_COLOR_ATTACHMENT0);
            camera->setClearColor(osg::Vec4(0.5f, 0.5f, 0.9f, 1));
            camera->setViewMatrixAsLookAt(osg::Vec3d(eyes_x[i], 0.9, -0.5), osg::Vec3d(eyes_x[i], 0.0, 2.0),
                                          osg::Vec3d(0, 1, 0));
            camera->setProjectionMatrixAsPerspective(45.0, 0.5, 0.05, 500.0);
            camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
            view->setSceneData(geode.get());
            viewer.addView(view.get());
        }
        viewer.realize();
        viewer.frame();
        const auto image = target->read();
        save(image, "two_views_one_context");
        EXPECT_GT(count_grass(image, 0, 64), 64u * 128u / 5) << "the left view";
        EXPECT_GT(count_grass(image, 64, 128), 64u * 128u / 5) << "the right view";
        EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 1);
        grass_frame_stats stats{};
        ASSERT_EQ(grass_get_frame_stats(grass->grassContext(window->getState()->getContextID()), &stats),
                  GRASS_SUCCESS);
        EXPECT_GT(stats.cells_drawn, 0u) << "the last view's frame";
        target->make_current();
    }
    EXPECT_EQ(grass_osg::FieldDrawable::liveGrassContexts() - before, 0);
}

} // namespace
} // namespace grass_osg_test
