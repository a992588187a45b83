// grass_osg: a grass field as an OpenSceneGraph drawable (OSG 3.6, GL backend).
//
// Put a FieldDrawable in a Geode (or any Group) and OSG draws the field in its scene: the
// camera, projection and viewport come from OSG's osg::State at draw time, the depth
// buffer is OSG's (grass hides behind OSG's models and hides those behind it), and the GL
// state grass touches is restored, so OSG's state cache stays true. The drawable's local
// coordinates are grass's world: grass is y-up, so in OSG's usual z-up world give the field
// z_up_base_transform() (or put the drawable under a transform that does the same).
//
// One grass context per OSG graphics context (osg::State::getContextID()): several views
// or cameras on one GL context share it, several GL contexts each get their own. They are
// made at the first draw in their GL context and destroyed when OSG releases the drawable's
// GL objects (releaseGLObjects, a scene-graph rebuild, the context's close).
//
// See docs/integration.md for the whole contract, docs/adapters.md for this adapter.
#pragma once

#include <grass/grass.h>

#include <osg/BoundingBox>
#include <osg/Drawable>

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace osgShadow {
class ShadowedScene;
}

namespace grass_osg {

class VdsmLink;

// An optional terrain under the field: grass_map_stack.height as 32-bit floats 0..1, row 0
// first (rows along the field's +z, texels along +x), times `scale` metres.
struct HeightMap {
    std::vector<float> values; // width * height values; empty: no terrain
    uint32_t width = 0, height = 0;
    float scale = 1.0f; // metres for a value of 1
};

// How grass's linear colour reaches the target (grass.h, GRASS_VIEW_FLAG_ENCODE_SRGB).
enum class OutputEncoding {
    // Read at each draw: a target that encodes (GL_FRAMEBUFFER_SRGB on and an sRGB colour
    // buffer) gets linear colour; any other gets it encoded in the shader. OSG's windows
    // and FBOs are usually plain RGBA8: then grass encodes.
    Automatic,
    Linear,    // never encode (a float HDR target the host tone-maps)
    EncodeSrgb // always encode
};

struct FieldDesc {
    grass_patch_desc patch = grass_default_patch_desc();
    // The field. Its `patch`, `density_map` and `maps` are the drawable's to fill (from
    // `patch` and `height_map`); `next` must stay NULL.
    grass_field_desc field = grass_default_field_desc();
    HeightMap height_map;
    grass_depth_mode depth_mode = GRASS_DEPTH_LESS; // the OSG scene's depth convention
    std::string cache_directory;                    // grass_context_desc.cache_directory; "" = none
};

// The lights of the view, in the drawable's local (grass world) coordinates.
struct Lights {
    float sun_direction[3] = {0.35f, 0.8f, 0.25f};
    float sun_color[3] = {1.0f, 0.95f, 0.85f};
    float ambient_color[3] = {0.30f, 0.36f, 0.45f};
};

// A field's base_transform for OSG's z-up convention: grass's field plane (x, z) becomes
// OSG's (x, -y) plane, grass's up (y) OSG's +z, and the field starts at `origin` (OSG
// coordinates).
void z_up_base_transform(const double origin[3], double out_base_transform[16]);

class FieldDrawable : public osg::Drawable {
public:
    // Checks the desc with a context that draws nothing (its patch, field and height map
    // are created there once); throws std::invalid_argument carrying grass's message, which
    // names the argument and the value, when grass refuses it.
    explicit FieldDrawable(const FieldDesc& desc);
    // A copy draws the same field with GL resources of its own.
    FieldDrawable(const FieldDrawable& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);

    // osg::Object's cloning (META_Object needs a default constructor, which a field lacks).
    osg::Object* cloneType() const override { return new FieldDrawable(desc_); }
    osg::Object* clone(const osg::CopyOp& copyop) const override { return new FieldDrawable(*this, copyop); }
    bool isSameKindAs(const osg::Object* object) const override {
        return dynamic_cast<const FieldDrawable*>(object) != nullptr;
    }
    const char* libraryName() const override { return "grass_osg"; }
    const char* className() const override { return "FieldDrawable"; }

    const FieldDesc& desc() const { return desc_; }

    // grass_view_flags for every draw (debug views, GRASS_VIEW_FLAG_NO_DEPTH_TEST).
    // GRASS_VIEW_FLAG_ENCODE_SRGB is decided by the output encoding.
    void setViewFlags(uint32_t flags) { flags_ = flags; }
    uint32_t getViewFlags() const { return flags_; }
    void setOutputEncoding(OutputEncoding encoding) { encoding_ = encoding; }
    OutputEncoding getOutputEncoding() const { return encoding_; }
    void setLights(const Lights& lights) { lights_ = lights; }
    const Lights& getLights() const { return lights_; }

    // Shadows under osgShadow::ViewDependentShadowMap (docs/adapters.md, "OSG's shadows"):
    // give the ShadowedScene the drawable is in (a descendant of it, with the technique set)
    // and grass casts into VDSM's map (a depth pass drawn when VDSM's shadow camera draws
    // the drawable, choosing its blades as the main camera does) and receives it (OSG's
    // map copied into a depth array of the adapter's, read with its matrix). The drawable's
    // node mask decides, as for OSG's models, whether VDSM's cameras draw it
    // (ShadowSettings' casts mask). Lights::sun_direction should point at VDSM's light.
    // It sets the drawable's cull callback (nullptr takes it off): an application's own cull
    // callback on the drawable would replace it. nullptr (the default): no shadows, and
    // every draw is as before.
    void setShadowedScene(osgShadow::ShadowedScene* scene);
    osgShadow::ShadowedScene* getShadowedScene() const;

    // The field's box in local coordinates: every cell, the blades' reach past their cells
    // and their height, and the terrain's lowest and highest displacement. OSG culls, sorts
    // and fits its near and far planes with it.
    osg::BoundingBox computeBoundingBox() const override;

    // Draws one grass frame with the camera of this draw (grass_begin_frame,
    // grass_gl_render, grass_end_frame). Errors go to osg::notify and lastError().
    void drawImplementation(osg::RenderInfo& renderInfo) const override;

    // Hands the grass context of `state`'s GL context (all of them for nullptr) to OSG's
    // deletion queue of that context: it is destroyed with the context current, at OSG's
    // next flush of deleted GL objects or at the context's close.
    void releaseGLObjects(osg::State* state = nullptr) const override;
    void resizeGLObjectBuffers(unsigned int maxSize) override;

    // The grass context drawing in OSG graphics context `contextID`, or nullptr before the
    // first draw there (for stats: grass_get_frame_stats, grass_get_memory_stats).
    grass_context* grassContext(unsigned int contextID) const;
    // The last error of any draw, "" when none.
    std::string lastError() const;

    // Grass contexts the adapter holds now, over every drawable and GL context, including
    // those waiting in a deletion queue.
    static int liveGrassContexts();

    class GlField; // one grass context with its patch, map and field, in one GL context

protected:
    ~FieldDrawable() override;

private:
    void setUp();
    GlField* fieldFor(osg::State& state) const;
    void fail(const std::string& message) const;

    FieldDesc desc_;
    uint32_t flags_ = 0;
    OutputEncoding encoding_ = OutputEncoding::Automatic;
    Lights lights_;
    osg::ref_ptr<VdsmLink> vdsm_;                               // the cull callback while a ShadowedScene is set
    float patch_min_[3] = {0, 0, 0}, patch_max_[3] = {1, 1, 1}; // the patch's bounds in patch units
    float height_min_ = 0.0f, height_max_ = 0.0f;               // terrain, metres

    mutable std::mutex mutex_; // draws of several GL contexts may run on several threads
    mutable std::map<unsigned int, std::unique_ptr<GlField>> fields_;
    mutable std::string last_error_;
};

} // namespace grass_osg
