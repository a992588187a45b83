#include "osg_view.hpp"

#include <osg/GLExtensions>
#include <osg/Viewport>

#include <cmath>
#include <cstring>
#include <sstream>

namespace grass_osg {

bool view_from_state(const osg::State& state, grass_view_desc* view, std::string* error) {
    const osg::Matrixd& mv = state.getModelViewMatrix();
    // OSG's matrices are row-vector (v' = v M), so their memory order is the column-major
    // order of the column-vector matrix grass takes.
    for (int c = 0; c < 3; ++c) {
        const double length = osg::Vec3d(mv(c, 0), mv(c, 1), mv(c, 2)).length();
        if (!(std::fabs(length - 1.0) < 1e-4)) {
            std::ostringstream s;
            s << "grass_osg: the model-view matrix of the FieldDrawable is not rigid (local axis " << c
              << " has length " << length << " in eye space): grass needs a transform without scale or shear";
            *error = s.str();
            return false;
        }
    }
    const osg::Vec3d eye = osg::Matrixd::inverse(mv).getTrans();
    for (int c = 0; c < 3; ++c) view->camera_position[c] = eye[c];
    for (int k = 0; k < 16; ++k) view->view[k] = static_cast<float>(mv.ptr()[k]);
    view->view[12] = view->view[13] = view->view[14] = 0.0f; // the translation is camera_position's
    const osg::Matrixd& p = state.getProjectionMatrix();
    for (int k = 0; k < 16; ++k) view->projection[k] = static_cast<float>(p.ptr()[k]);
    const osg::Viewport* vp = state.getCurrentViewport();
    if (!vp) {
        *error = "grass_osg: OSG has applied no viewport for the FieldDrawable's camera";
        return false;
    }
    view->viewport[0] = static_cast<int32_t>(std::lround(vp->x()));
    view->viewport[1] = static_cast<int32_t>(std::lround(vp->y()));
    view->viewport[2] = static_cast<int32_t>(std::lround(vp->width()));
    view->viewport[3] = static_cast<int32_t>(std::lround(vp->height()));
    if (const osg::FrameStamp* stamp = state.getFrameStamp()) view->time = stamp->getSimulationTime();
    return true;
}

namespace {

// The few GL names this file reads (OSG's GL header may or may not define them).
constexpr unsigned kFramebufferSrgb = 0x8DB9, kDrawFramebufferBinding = 0x8CA6, kDrawBuffer0 = 0x8825,
                   kColorEncoding = 0x8210, kSrgb = 0x8C40, kFront = 0x0404, kBack = 0x0405, kFrontLeft = 0x0400,
                   kBackLeft = 0x0402, kFrontAndBack = 0x0408;
using IsEnabledFn = unsigned char (*)(unsigned);
using GetIntegervFn = void (*)(unsigned, int*);
using GetNamedFramebufferAttachmentParameterivFn = void (*)(unsigned, unsigned, unsigned, int*);

template <typename Fn>
Fn load(const char* name) {
    void* address = osg::getGLExtensionFuncPtr(name);
    Fn fn = nullptr;
    std::memcpy(&fn, &address, sizeof(fn));
    return fn;
}

} // namespace

bool target_encodes_srgb() {
    static const auto is_enabled = load<IsEnabledFn>("glIsEnabled");
    static const auto get_integerv = load<GetIntegervFn>("glGetIntegerv");
    static const auto get_attachment =
        load<GetNamedFramebufferAttachmentParameterivFn>("glGetNamedFramebufferAttachmentParameteriv");
    if (!is_enabled || !get_integerv || !get_attachment || !is_enabled(kFramebufferSrgb)) return false;
    int framebuffer = 0, buffer = 0, encoding = 0;
    get_integerv(kDrawFramebufferBinding, &framebuffer);
    get_integerv(kDrawBuffer0, &buffer);
    if (buffer == 0) return false; // GL_NONE: nothing is written
    if (framebuffer == 0) {        // the window's buffers are named by side
        if (buffer == int(kBack)) buffer = int(kBackLeft);
        if (buffer == int(kFront) || buffer == int(kFrontAndBack)) buffer = int(kFrontLeft);
    }
    get_attachment(static_cast<unsigned>(framebuffer), static_cast<unsigned>(buffer), kColorEncoding, &encoding);
    return encoding == int(kSrgb);
}

} // namespace grass_osg
