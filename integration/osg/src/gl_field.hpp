// One grass context in one OSG graphics context, with the patch, height map and field the
// drawable describes; and the per-context queue that destroys them with their GL context
// current. Private to the adapter.
#pragma once

#include <grass_osg/field_drawable.hpp>

#include "shadow_map_copy.hpp"

#include <osg/GLObjects>

namespace grass_osg {

class FieldDrawable::GlField {
public:
    // Creates them in the current GL context (OSG's, loaded through
    // osg::getGLExtensionFuncPtr). nullptr and *error (grass's message) on failure.
    static std::unique_ptr<GlField> create(const FieldDesc& desc, std::string* error);
    // The GL context must be current.
    ~GlField();
    GlField(const GlField&) = delete;
    GlField& operator=(const GlField&) = delete;

    grass_context* context() const { return context_; }
    // The copy of OSG's shadow map this context's views receive (made at the first).
    ShadowMapCopy& shadowMapCopy() { return shadow_map_copy_; }

    static int live();

private:
    GlField() = default;
    grass_context* context_ = nullptr;
    ShadowMapCopy shadow_map_copy_;
};

// OSG's deletion queue for the grass contexts of one OSG context: OSG calls it with that GL
// context current (osg::ContextData), every frame and when the context closes.
class GrassContextQueue : public osg::GraphicsObjectManager {
public:
    explicit GrassContextQueue(unsigned int contextID);
    void add(std::unique_ptr<FieldDrawable::GlField> field);

    void flushDeletedGLObjects(double currentTime, double& availableTime) override;
    void flushAllDeletedGLObjects() override;
    void deleteAllGLObjects() override;
    // The GL context is gone, or not current on this thread: destroying through it could
    // delete another context's GL names, so the grass contexts are left undestroyed (their
    // host memory stays allocated) and a warning says how many.
    void discardAllGLObjects() override;

protected:
    ~GrassContextQueue() override;

private:
    std::mutex mutex_;
    std::vector<std::unique_ptr<FieldDrawable::GlField>> queue_;
};

// Hands `field` to the deletion queue of OSG context `contextID`.
void queue_for_deletion(unsigned int contextID, std::unique_ptr<FieldDrawable::GlField> field);

} // namespace grass_osg
