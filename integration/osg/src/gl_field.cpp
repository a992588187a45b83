#include "gl_field.hpp"

#include <grass/grass_gl.h>

#include <osg/ContextData>
#include <osg/GLExtensions>
#include <osg/Notify>

#include <atomic>
#include <cstring>

namespace grass_osg {

namespace {

std::atomic<int> live_fields{0};

grass_gl_proc GRASS_API_PTR load_gl(void*, const char* name) {
    void* address = osg::getGLExtensionFuncPtr(name);
    grass_gl_proc proc = nullptr;
    static_assert(sizeof(proc) == sizeof(address), "function and object pointers of one size");
    std::memcpy(&proc, &address, sizeof(proc));
    return proc;
}

void GRASS_API_PTR log_to_osg(void*, grass_log_level level, grass_message_id id, const char* message) {
    const osg::NotifySeverity severity = level == GRASS_LOG_ERROR     ? osg::WARN
                                         : level == GRASS_LOG_WARNING ? osg::NOTICE
                                                                      : osg::INFO;
    OSG_NOTIFY(severity) << "grass (message " << int(id) << "): " << message << std::endl;
}

} // namespace

std::unique_ptr<FieldDrawable::GlField> FieldDrawable::GlField::create(const FieldDesc& desc, std::string* error) {
    std::unique_ptr<GlField> f(new GlField);
    grass_context_desc cd = grass_default_context_desc();
    cd.log_fn = log_to_osg;
    cd.depth_mode = desc.depth_mode;
    cd.cache_directory = desc.cache_directory.empty() ? nullptr : desc.cache_directory.c_str();
    grass_gl_desc gl = grass_default_gl_desc();
    gl.get_proc_address = load_gl;
    grass_result r = grass_gl_create_context(GRASS_HEADER_VERSION, &cd, &gl, &f->context_);
    if (r != GRASS_SUCCESS) {
        *error = std::string("grass_gl_create_context: ") + grass_result_string(r);
        return nullptr;
    }
    ++live_fields;
    grass_field_desc fd = desc.field;
    r = grass_create_patch(f->context_, &desc.patch, &fd.patch);
    if (r == GRASS_SUCCESS && !desc.height_map.values.empty()) {
        grass_map_desc md = grass_default_map_desc();
        md.pixels = desc.height_map.values.data();
        md.width = desc.height_map.width;
        md.height = desc.height_map.height;
        md.format = GRASS_MAP_FORMAT_R32_FLOAT;
        r = grass_create_map(f->context_, &md, &fd.maps.height);
        fd.maps.height_scale = desc.height_map.scale;
    }
    grass_field_id field{};
    if (r == GRASS_SUCCESS) r = grass_create_field(f->context_, &fd, &field);
    if (r != GRASS_SUCCESS) {
        *error = grass_get_last_error(f->context_);
        return nullptr; // ~GlField destroys the context and what it made
    }
    return f;
}

FieldDrawable::GlField::~GlField() {
    if (context_) {
        grass_destroy_context(context_);
        --live_fields;
    }
}

int FieldDrawable::GlField::live() { return live_fields.load(); }

GrassContextQueue::GrassContextQueue(unsigned int contextID)
    : osg::GraphicsObjectManager("grass_osg::GrassContextQueue", contextID) {}

GrassContextQueue::~GrassContextQueue() = default;

void GrassContextQueue::add(std::unique_ptr<FieldDrawable::GlField> field) {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(std::move(field));
}

void GrassContextQueue::flushDeletedGLObjects(double, double&) { flushAllDeletedGLObjects(); }

void GrassContextQueue::flushAllDeletedGLObjects() {
    std::vector<std::unique_ptr<FieldDrawable::GlField>> doomed;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        doomed.swap(queue_);
    }
    doomed.clear(); // destroyed here, with the GL context current
}

void GrassContextQueue::deleteAllGLObjects() { flushAllDeletedGLObjects(); }

void GrassContextQueue::discardAllGLObjects() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!queue_.empty()) {
        OSG_WARN << "grass_osg: OSG context " << _contextID << " closed without being current: " << queue_.size()
                 << " grass context(s) left undestroyed" << std::endl;
    }
    for (auto& field : queue_) (void)field.release();
    queue_.clear();
}

void queue_for_deletion(unsigned int contextID, std::unique_ptr<FieldDrawable::GlField> field) {
    if (field) osg::get<GrassContextQueue>(contextID)->add(std::move(field));
}

} // namespace grass_osg
