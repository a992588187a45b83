#include "vdsm_link.hpp"

#include <osgUtil/CullVisitor>

#include <string>

namespace grass_osg {

bool VdsmLink::cull(osg::NodeVisitor* visitor, osg::Drawable*, osg::RenderInfo*) const {
    osgUtil::CullVisitor* cv = visitor ? visitor->asCullVisitor() : nullptr;
    osg::ref_ptr<osgShadow::ShadowedScene> scene;
    if (!cv || !scene_.lock(scene)) return false;
    osg::Camera* camera = cv->getCurrentCamera();
    auto* vdsm = dynamic_cast<osgShadow::ViewDependentShadowMap*>(scene->getShadowTechnique());
    std::lock_guard<std::mutex> lock(mutex_);
    if (!vdsm) {
        const osgShadow::ShadowTechnique* technique = scene->getShadowTechnique();
        error_ = std::string("grass_osg: the FieldDrawable's ShadowedScene has the shadow technique ") +
                 (technique ? technique->className() : "none") +
                 ", not osgShadow::ViewDependentShadowMap: grass neither casts nor receives shadows";
        culled_.clear();
        return false;
    }
    error_.clear();
    Culled& c = culled_[camera];
    c.camera = camera;
    c.data = vdsm->getViewDependentData(cv);
    c.viewpoint = osg::Vec3d(cv->getViewPointLocal());
    return false; // never culls the drawable
}

DrawShadows VdsmLink::forDraw(osg::RenderInfo& renderInfo) const {
    DrawShadows out;
    const osg::Camera* camera = renderInfo.getCurrentCamera();
    osg::ref_ptr<osgShadow::ShadowedScene> scene;
    if (!camera || !scene_.lock(scene)) return out;
    std::lock_guard<std::mutex> lock(mutex_);
    out.error = error_;
    const auto it = culled_.find(camera);
    if (it == culled_.end() || !it->second.data || it->second.camera.get() != camera) return out;
    osgShadow::ViewDependentShadowMap::ShadowDataList& maps = it->second.data->getShadowDataList();
    for (const auto& map : maps) {
        if (map->_camera.get() == camera) { // one of VDSM's shadow cameras
            out.kind = DrawShadows::Kind::Cast;
            out.lod_origin = it->second.viewpoint;
            return out;
        }
    }
    if (maps.empty()) return out; // no light casts this frame
    if (maps.size() > 1) {
        out.error = "grass_osg: grass receives one shadow map, and the ViewDependentShadowMap draws " +
                    std::to_string(maps.size()) +
                    " (a map per light and ShadowSettings::setNumShadowMapsPerLight): grass is drawn unshadowed";
        return out;
    }
    const osgShadow::ViewDependentShadowMap::ShadowData& map = *maps.front();
    // The map's camera is absolute: its view takes the ShadowedScene's local coordinates.
    // The drawable's local coordinates reach them through its model-view, the main camera's
    // view and the ShadowedScene's place in the world.
    const osg::Matrixd& model_view = renderInfo.getState()->getModelViewMatrix();
    const osg::MatrixList scene_to_world = scene->getWorldMatrices();
    const osg::Matrixd scene_model_view =
        (scene_to_world.empty() ? osg::Matrixd::identity() : scene_to_world.front()) * camera->getViewMatrix();
    const osg::Matrixd bias = osg::Matrixd::translate(1.0, 1.0, 1.0) * osg::Matrixd::scale(0.5, 0.5, 0.5);
    double left, right, bottom, top, z_near, z_far;
    if (map._camera->getProjectionMatrix().getOrtho(left, right, bottom, top, z_near, z_far)) {
        out.depth_range = z_far - z_near;
    }
    out.kind = DrawShadows::Kind::Receive;
    out.map = map._texture;
    out.world_to_shadow = model_view * osg::Matrixd::inverse(scene_model_view) * map._camera->getViewMatrix() *
                          map._camera->getProjectionMatrix() * bias;
    return out;
}

} // namespace grass_osg
