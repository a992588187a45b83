// The field drawable's link to an osgShadow::ViewDependentShadowMap (VDSM): which of its
// draws are VDSM's shadow cameras (grass casts: a depth pass) and which cameras receive
// VDSM's map (grass reads it). Private to the adapter.
#pragma once

#include <osg/Drawable>
#include <osg/Matrixd>
#include <osg/Texture2D>
#include <osg/observer_ptr>
#include <osgShadow/ShadowedScene>
#include <osgShadow/ViewDependentShadowMap>

#include <map>
#include <mutex>
#include <string>

namespace grass_osg {

// What one draw of the field does with VDSM's shadows.
struct DrawShadows {
    enum class Kind { None, Cast, Receive };
    Kind kind = Kind::None;
    // Cast: the main camera's eye in the drawable's local coordinates, the lod origin.
    osg::Vec3d lod_origin;
    // Receive: VDSM's map of this camera and the drawable's local coordinates to its
    // (u, v, depth) (OSG's row-vector order: p * world_to_shadow).
    osg::ref_ptr<osg::Texture2D> map;
    osg::Matrixd world_to_shadow;
    double depth_range = 0.0; // metres the map's depth spans (orthographic maps), else 0
    std::string error;        // why the draw neither casts nor receives, "" when that is not an error
};

// A cull callback on the drawable: at each cull it notes the camera, the VDSM data of the
// cull visitor (the same for the main camera and its shadow cameras) and the viewpoint.
class VdsmLink : public osg::Drawable::CullCallback {
public:
    explicit VdsmLink(osgShadow::ShadowedScene* scene) : scene_(scene) {}

    osgShadow::ShadowedScene* scene() const { return scene_.get(); }

    bool cull(osg::NodeVisitor* visitor, osg::Drawable* drawable, osg::RenderInfo* info) const override;

    // The shadows of the draw under renderInfo's current camera (VDSM has culled and
    // placed its cameras for this frame by then).
    DrawShadows forDraw(osg::RenderInfo& renderInfo) const;

private:
    struct Culled {
        osg::observer_ptr<osg::Camera> camera;
        osg::ref_ptr<osgShadow::ViewDependentShadowMap::ViewDependentData> data;
        osg::Vec3d viewpoint; // local; a shadow camera inherits the main camera's
    };
    osg::observer_ptr<osgShadow::ShadowedScene> scene_;
    mutable std::mutex mutex_;
    mutable std::map<const osg::Camera*, Culled> culled_;
    mutable std::string error_;
};

} // namespace grass_osg
