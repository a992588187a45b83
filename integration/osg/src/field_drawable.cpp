#include <grass_osg/field_drawable.hpp>

#include "gl_field.hpp"
#include "osg_view.hpp"
#include "vdsm_link.hpp"

#include <grass/grass_gl.h>

#include <osg/Notify>
#include <osg/RenderInfo>
#include <osg/StateSet>

#include <algorithm>
#include <stdexcept>

namespace grass_osg {

namespace {

// The render bin grass draws in: after OSG's opaque bin (0), before its transparent bin
// (10), so transparent models blend over grass and opaque ones have filled the depth first.
constexpr int kGrassRenderBin = 5;

// Validates `desc` as grass would in a GL context, with a context that draws nothing, and
// reads the patch's bounds: throws std::invalid_argument with grass's message.
struct Checked {
    grass_patch_info patch{};
    float height_min = 0.0f, height_max = 0.0f;
};

Checked check(const FieldDesc& desc) {
    grass_context* context = nullptr;
    grass_context_desc cd = grass_default_context_desc();
    cd.depth_mode = desc.depth_mode;
    if (grass_create_context(GRASS_HEADER_VERSION, &cd, &context) != GRASS_SUCCESS) {
        throw std::invalid_argument("grass_osg::FieldDrawable: grass_create_context failed");
    }
    Checked out;
    grass_field_desc fd = desc.field;
    grass_result r = grass_create_patch(context, &desc.patch, &fd.patch);
    if (r == GRASS_SUCCESS) r = grass_get_patch_info(context, fd.patch, &out.patch);
    const HeightMap& h = desc.height_map;
    if (r == GRASS_SUCCESS && !h.values.empty()) {
        grass_map_desc md = grass_default_map_desc();
        md.pixels = h.values.data();
        md.width = h.width;
        md.height = h.height;
        md.format = GRASS_MAP_FORMAT_R32_FLOAT;
        if (h.values.size() != size_t(h.width) * h.height) {
            grass_destroy_context(context);
            throw std::invalid_argument("grass_osg::FieldDrawable: height_map.values holds " +
                                        std::to_string(h.values.size()) +
                                        " values, not width x height = " + std::to_string(size_t(h.width) * h.height));
        }
        r = grass_create_map(context, &md, &fd.maps.height);
        fd.maps.height_scale = h.scale;
        if (r == GRASS_SUCCESS) {
            const auto range = std::minmax_element(h.values.begin(), h.values.end());
            out.height_min = *range.first * h.scale;
            out.height_max = *range.second * h.scale;
        }
    }
    grass_field_id field{};
    if (r == GRASS_SUCCESS) r = grass_create_field(context, &fd, &field);
    const std::string message = r == GRASS_SUCCESS ? "" : grass_get_last_error(context);
    grass_destroy_context(context);
    if (r != GRASS_SUCCESS) throw std::invalid_argument("grass_osg::FieldDrawable: " + message);
    return out;
}

} // namespace

void z_up_base_transform(const double origin[3], double m[16]) {
    // Columns: grass x -> OSG x, grass y (up) -> OSG z, grass z -> OSG -y.
    const double columns[16] = {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, origin[0], origin[1], origin[2], 1};
    std::copy(columns, columns + 16, m);
}

FieldDrawable::FieldDrawable(const FieldDesc& desc) : desc_(desc) {
    if (desc_.field.next) throw std::invalid_argument("grass_osg::FieldDrawable: desc.field.next must be NULL");
    const grass_map_stack& maps = desc_.field.maps;
    if (desc_.field.density_map || maps.density.index || maps.color.index || maps.ambient.index || maps.diffuse.index ||
        maps.height.index) {
        throw std::invalid_argument("grass_osg::FieldDrawable: desc.field.density_map and desc.field.maps must be "
                                    "empty (map ids belong to one grass context; give the terrain as "
                                    "desc.height_map)");
    }
    const Checked c = check(desc_);
    std::copy(c.patch.bounds_min, c.patch.bounds_min + 3, patch_min_);
    std::copy(c.patch.bounds_max, c.patch.bounds_max + 3, patch_max_);
    height_min_ = c.height_min;
    height_max_ = c.height_max;
    setUp();
}

FieldDrawable::FieldDrawable(const FieldDrawable& other, const osg::CopyOp& copyop)
    : osg::Drawable(other, copyop), desc_(other.desc_), flags_(other.flags_), encoding_(other.encoding_),
      lights_(other.lights_), vdsm_(nullptr), height_min_(other.height_min_), height_max_(other.height_max_) {
    std::copy(other.patch_min_, other.patch_min_ + 3, patch_min_);
    std::copy(other.patch_max_, other.patch_max_ + 3, patch_max_);
    setUp();
    // The link notes its own drawable's cameras: a copy gets one of its own.
    if (other.vdsm_) {
        if (getCullCallback() == other.vdsm_.get()) setCullCallback(nullptr);
        setShadowedScene(other.getShadowedScene());
    }
}

void FieldDrawable::setShadowedScene(osgShadow::ShadowedScene* scene) {
    if (vdsm_ && getCullCallback() == vdsm_.get()) setCullCallback(nullptr);
    vdsm_ = scene ? new VdsmLink(scene) : nullptr;
    if (vdsm_) setCullCallback(vdsm_.get());
}

osgShadow::ShadowedScene* FieldDrawable::getShadowedScene() const { return vdsm_ ? vdsm_->scene() : nullptr; }

void FieldDrawable::setUp() {
    // grass draws every frame with the camera of that draw: never a display list.
    setSupportsDisplayList(false);
    setUseDisplayList(false);
    setUseVertexBufferObjects(false);
    getOrCreateStateSet()->setRenderBinDetails(kGrassRenderBin, "RenderBin");
    dirtyBound();
}

FieldDrawable::~FieldDrawable() { releaseGLObjects(nullptr); }

osg::BoundingBox FieldDrawable::computeBoundingBox() const {
    // Field space scaled to metres: cells along x and z, blades rooted in their cell but
    // reaching past it by the patch's bounds, the terrain displacing them along y.
    const double cs = desc_.field.cell_size;
    const double lo[3] = {patch_min_[0] * cs, height_min_ + std::min(0.0, double(patch_min_[1]) * cs),
                          patch_min_[2] * cs};
    const double hi[3] = {(desc_.field.cells_x - 1 + double(patch_max_[0])) * cs,
                          height_max_ + std::max(0.0, double(patch_max_[1]) * cs),
                          (desc_.field.cells_z - 1 + double(patch_max_[2])) * cs};
    // Mirrored cells reflect the patch within its cell: the reach applies on both sides.
    const double reach_x = std::max(0.0, std::max(-lo[0], hi[0] - desc_.field.cells_x * cs));
    const double reach_z = std::max(0.0, std::max(-lo[2], hi[2] - desc_.field.cells_z * cs));
    const double box_lo[3] = {-reach_x, lo[1], -reach_z};
    const double box_hi[3] = {desc_.field.cells_x * cs + reach_x, hi[1], desc_.field.cells_z * cs + reach_z};
    const double* m = desc_.field.base_transform;
    osg::BoundingBox box;
    for (int corner = 0; corner < 8; ++corner) {
        const double p[3] = {corner & 1 ? box_hi[0] : box_lo[0], corner & 2 ? box_hi[1] : box_lo[1],
                             corner & 4 ? box_hi[2] : box_lo[2]};
        box.expandBy(osg::Vec3(float(m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12]),
                               float(m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13]),
                               float(m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14])));
    }
    return box;
}

FieldDrawable::GlField* FieldDrawable::fieldFor(osg::State& state) const {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& slot = fields_[state.getContextID()];
    if (!slot) {
        std::string error;
        slot = GlField::create(desc_, &error);
        if (!slot) {
            last_error_ = error;
            fields_.erase(state.getContextID());
            OSG_WARN << "grass_osg: no grass in OSG context " << state.getContextID() << ": " << error << std::endl;
            return nullptr;
        }
    }
    return slot.get();
}

void FieldDrawable::fail(const std::string& message) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (message != last_error_) OSG_WARN << message << std::endl;
    last_error_ = message;
}

void FieldDrawable::drawImplementation(osg::RenderInfo& renderInfo) const {
    osg::State& state = *renderInfo.getState();
    GlField* field = fieldFor(state);
    if (!field) return;
    grass_view_desc view = grass_default_view_desc();
    std::string error;
    if (!view_from_state(state, &view, &error)) return fail(error);
    std::copy(lights_.sun_direction, lights_.sun_direction + 3, view.sun_direction);
    std::copy(lights_.sun_color, lights_.sun_color + 3, view.sun_color);
    std::copy(lights_.ambient_color, lights_.ambient_color + 3, view.ambient_color);
    view.flags = flags_ & ~uint32_t(GRASS_VIEW_FLAG_ENCODE_SRGB);
    if (encoding_ == OutputEncoding::EncodeSrgb || (encoding_ == OutputEncoding::Automatic && !target_encodes_srgb())) {
        view.flags |= GRASS_VIEW_FLAG_ENCODE_SRGB;
    }
    // VDSM's shadows: its shadow camera's draw is a depth pass, the main camera's receives.
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    grass_lod_origin_desc lod = grass_default_lod_origin_desc();
    grass_shadow_receive_desc receive = grass_default_shadow_receive_desc();
    if (vdsm_) {
        const DrawShadows shadows = vdsm_->forDraw(renderInfo);
        if (!shadows.error.empty()) fail(shadows.error);
        if (shadows.kind == DrawShadows::Kind::Cast) {
            // Any projection VDSM draws with, its default light-space perspective map (a warp
            // whose rays stay parallel to the light) included: grass takes the rays from it.
            pass.pass = GRASS_PASS_DEPTH;
            // VDSM's own casters' polygon offset (factor 1.1, units 4).
            pass.depth_bias_slope = 1.1f;
            pass.depth_bias_constant = 4.0f;
            pass.next = &lod;
            for (int c = 0; c < 3; ++c) lod.position[c] = shadows.lod_origin[c];
            view.flags = 0; // a depth pass takes no debug view flags and writes no colour
            view.next = &pass;
        } else if (shadows.kind == DrawShadows::Kind::Receive) {
            osg::Texture::TextureObject* map = shadows.map->getTextureObject(state.getContextID());
            const uint32_t array = map ? field->shadowMapCopy().copy(map->id(), &error) : 0;
            if (!error.empty()) fail(error);
            if (array) {
                receive.shadow_map = array;
                // grass's own depth in the map is its blades' tops: a point is moved about
                // the blades' height towards the light, or the field shades itself as a slab
                // (docs/engine-frames.md, "Shadows: grass in the host's shadow maps", Bias).
                const double blades = std::max(0.0, double(patch_max_[1]) * desc_.field.cell_size);
                if (shadows.depth_range > 0.0) receive.depth_bias = float(std::min(1.0, blades / shadows.depth_range));
                for (int k = 0; k < 16; ++k) receive.world_to_shadow[0][k] = float(shadows.world_to_shadow.ptr()[k]);
                view.next = &receive;
            }
        }
    }
    // One grass frame per draw: each camera plans with its own frustum. grass restores every
    // piece of GL state it sets (grass_gl.h), so OSG's state cache stays true.
    grass_context* context = field->context();
    grass_result r = grass_begin_frame(context, &view);
    if (r == GRASS_SUCCESS) {
        r = grass_gl_render(context);
        const grass_result end = grass_end_frame(context);
        if (r == GRASS_SUCCESS) r = end;
    }
    if (r != GRASS_SUCCESS) fail(std::string("grass_osg: ") + grass_get_last_error(context));
}

void FieldDrawable::releaseGLObjects(osg::State* state) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = fields_.begin(); it != fields_.end();) {
        if (state && it->first != state->getContextID()) {
            ++it;
            continue;
        }
        queue_for_deletion(it->first, std::move(it->second));
        it = fields_.erase(it);
    }
}

void FieldDrawable::resizeGLObjectBuffers(unsigned int) {} // a map keyed by context id: nothing to resize

grass_context* FieldDrawable::grassContext(unsigned int contextID) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = fields_.find(contextID);
    return it == fields_.end() ? nullptr : it->second->context();
}

std::string FieldDrawable::lastError() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_error_;
}

int FieldDrawable::liveGrassContexts() { return GlField::live(); }

} // namespace grass_osg
