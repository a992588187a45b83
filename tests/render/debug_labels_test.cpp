// Debug labels and object names (grass.h, grass_debug_labels), seen where a frame debugger
// sees them. Vulkan: through the host's vkGetInstanceProcAddr (vk_intercept.hpp), which hands
// grass recording wrappers of vkSetDebugUtilsObjectNameEXT and vkCmdBegin/EndDebugUtilsLabelEXT
// and records every object grass creates: each one is named "grass ...", the labels nest and
// balance, and each pass and tier kind has its label; validation stays silent. GL: through the
// loader the host hands grass (TargetDesc::gl_proc_filter), which records every object grass
// creates, its glObjectLabel calls and its debug groups; glGetObjectLabel on the host's side
// reads the names back. Off, nothing is named or labelled.
#include "render_fixture.hpp"

#if defined(GRASS_HAS_VULKAN)
#    include "vk_intercept.hpp"

#    include <vulkan/vulkan.h>
#endif
#if defined(GRASS_HAS_GL)
#    include <GL/glcorearb.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

namespace grass_test {
namespace {

// Every pass and tier kind the scene below records, in the order of a frame.
const char* const kFrameLabels[] = {"grass interaction pass", "grass draw", "grass blades", "grass volumes",
                                    "grass images"};

struct Scene {
    std::unique_ptr<grass_host::Host> host;
    grass_context* ctx = nullptr;
    std::string log;
    std::vector<grass_message_id> ids;
    ~Scene() {
        if (ctx) grass_destroy_context(ctx);
        if (host) {
            EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
        }
    }
};

// A 16 m x 64 m field, blades to 3 m, volumes to 10 m, images beyond, seen along it, with a
// collider (the interaction pass); `labels` chained to the context desc, or nothing chained.
// `all_tiers` false: an 8 m x 8 m field of blades alone, in view (no slices to bake: faster).
void make_scene(Scene* s, grass_backend backend, const grass_host::TargetDesc& target, const grass_debug_labels* labels,
                bool all_tiers = true) {
    std::string error;
    s->host = grass_host::Host::create(backend, target, &error);
    ASSERT_TRUE(s->host) << error;
    grass_debug_labels_desc ld = grass_default_debug_labels_desc();
    grass_context_desc cd = grass_default_context_desc();
    if (labels) {
        ld.labels = *labels;
        cd.next = &ld;
    }
    cd.log_user_data = s;
    cd.log_fn = [](void* user, grass_log_level, grass_message_id id, const char* message) {
        auto* scene = static_cast<Scene*>(user);
        scene->log += std::to_string(int(id)) + ": " + message + "\n";
        scene->ids.push_back(id);
    };
    ASSERT_EQ(s->host->create_context(cd, &s->ctx), GRASS_SUCCESS) << s->log;
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 256;
    grass_patch_id patch{};
    ASSERT_EQ(grass_create_patch(s->ctx, &pd, &patch), GRASS_SUCCESS) << s->log;
    if (!all_tiers) {
        grass_field_id field{};
        ASSERT_EQ(create_blade_field(s->ctx, patch, 32, &field), GRASS_SUCCESS) << s->log;
        return;
    }
    grass_tier_desc tiers[3] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 4}, {GRASS_TIER_IMAGE, 0}};
    grass_lod_test tests[3] = {};
    for (int i = 0; i < 3; ++i) {
        tests[i].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[i].tier = uint32_t(i);
    }
    tests[0].end = tests[1].begin = 3.0f;
    tests[1].end = tests[2].begin = 10.0f;
    tests[2].end = INFINITY;
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cells_x = 64;
    d.cells_z = 256;
    d.tiers = tiers;
    d.tier_count = 3;
    d.lod_tests = tests;
    d.lod_test_count = 3;
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(s->ctx, &d, &field), GRASS_SUCCESS) << s->log;
    grass_collider ball{};
    ball.shape = GRASS_COLLIDER_SPHERE;
    ball.radius = 0.3f;
    ball.center[0] = 8.0;
    ball.center[1] = 0.2;
    ball.center[2] = 2.0;
    ASSERT_EQ(grass_set_colliders(s->ctx, &ball, 1), GRASS_SUCCESS) << s->log;
}

void render_frames(Scene* s, int frames) {
    const double eye[3] = {8.0, 1.5, 0.5}, look[3] = {8.0, 0.0, 6.0};
    for (int i = 0; i < frames; ++i) {
        grass_view_desc v = grass_host::make_view(*s->host, eye, look, 60.0f, 0.05f, 200.0f);
        v.time = 0.05 * i;
        grass_host::Image image;
        std::string error;
        ASSERT_EQ(s->host->render(s->ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << error << s->log;
    }
}

bool grass_name(const std::string& name) { return name.rfind("grass ", 0) == 0 && name.size() > 6; }

// The labels of `events` ("+name" / "-") nest and balance; returns the names begun.
std::multiset<std::string> check_balanced(const std::vector<std::string>& events) {
    std::multiset<std::string> begun;
    int depth = 0;
    for (const std::string& e : events) {
        if (e == "-") {
            depth -= 1;
            EXPECT_GE(depth, 0) << "a label ended that was not begun";
        } else {
            depth += 1;
            begun.insert(e.substr(1));
            EXPECT_TRUE(grass_name(e.substr(1))) << e;
        }
    }
    EXPECT_EQ(depth, 0) << "labels left open";
    return begun;
}

#if defined(GRASS_HAS_VULKAN)

namespace vi = vk_intercept;

grass_host::TargetDesc vk_target() {
    grass_host::TargetDesc t;
    t.width = 96;
    t.height = 64;
    t.vk_get_instance_proc_addr = vi::get_instance_proc_addr();
    return t;
}

struct VkDebugUtilsHidden {
    explicit VkDebugUtilsHidden(bool hide) { vi::hide_debug_utils(hide); }
    ~VkDebugUtilsHidden() { vi::hide_debug_utils(false); }
};

TEST(VkDebugLabels, EveryObjectGrassMakesIsNamedAndEachPassAndTierIsLabelled) {
    vi::clear_debug_records();
    {
        Scene s; // AUTO: the test host enables VK_EXT_debug_utils on its instance
        make_scene(&s, GRASS_BACKEND_VULKAN, vk_target(), nullptr);
        ASSERT_FALSE(HasFatalFailure());
        render_frames(&s, 3);
        ASSERT_FALSE(HasFatalFailure());

        const std::vector<vi::Handle> made = vi::made();
        const std::map<vi::Handle, std::string> names = vi::names();
        std::map<int32_t, int> made_per_type, named_per_type;
        for (const vi::Handle& h : made) {
            made_per_type[h.type] += 1;
            const auto n = names.find(h);
            if (n == names.end()) continue;
            named_per_type[h.type] += 1;
            EXPECT_TRUE(grass_name(n->second)) << "object type " << h.type << " named \"" << n->second << "\"";
        }
        EXPECT_EQ(named_per_type, made_per_type) << "objects made and named, per VkObjectType";
        for (const VkObjectType type :
             {VK_OBJECT_TYPE_BUFFER, VK_OBJECT_TYPE_IMAGE, VK_OBJECT_TYPE_IMAGE_VIEW, VK_OBJECT_TYPE_DEVICE_MEMORY,
              VK_OBJECT_TYPE_SAMPLER, VK_OBJECT_TYPE_DESCRIPTOR_POOL, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT,
              VK_OBJECT_TYPE_PIPELINE_LAYOUT, VK_OBJECT_TYPE_PIPELINE}) {
            EXPECT_GT(made_per_type[int32_t(type)], 0) << "the scene makes no object of type " << type;
        }

        const std::multiset<std::string> begun = check_balanced(vi::label_events());
        EXPECT_GE(begun.count("grass uploads"), 1u);
        for (const char* label : kFrameLabels) EXPECT_EQ(begun.count(label), 3u) << label << ", one per frame";
        EXPECT_EQ(begun.count("grass blade window pass"), 3u) << "one per frame (the collider's)";
    }
    vi::clear_debug_records();
}

TEST(VkDebugLabels, OffNamesNothingAndLabelsNothing) {
    vi::clear_debug_records();
    {
        Scene s;
        const grass_debug_labels off = GRASS_DEBUG_LABELS_OFF;
        make_scene(&s, GRASS_BACKEND_VULKAN, vk_target(), &off, false);
        ASSERT_FALSE(HasFatalFailure());
        render_frames(&s, 2);
        EXPECT_GT(vi::made().size(), 10u);
        EXPECT_TRUE(vi::names().empty()) << vi::names().size() << " objects named";
        EXPECT_TRUE(vi::label_events().empty()) << vi::label_events().size() << " label calls";
    }
    vi::clear_debug_records();
}

TEST(VkDebugLabels, WithoutTheExtensionOnIsAWarningAndAutoIsSilent) {
    const VkDebugUtilsHidden hidden(true);
    for (const grass_debug_labels labels : {GRASS_DEBUG_LABELS_ON, GRASS_DEBUG_LABELS_AUTO}) {
        vi::clear_debug_records();
        Scene s;
        make_scene(&s, GRASS_BACKEND_VULKAN, vk_target(), &labels, false);
        ASSERT_FALSE(HasFatalFailure());
        render_frames(&s, 1);
        const bool warned = std::count(s.ids.begin(), s.ids.end(), GRASS_MSG_DEBUG_LABELS_UNAVAILABLE) == 1;
        EXPECT_EQ(warned, labels == GRASS_DEBUG_LABELS_ON) << s.log;
        EXPECT_TRUE(vi::names().empty());
        EXPECT_TRUE(vi::label_events().empty());
    }
    vi::clear_debug_records();
}

#endif

#if defined(GRASS_HAS_GL)

// What grass did through its GL loader.
struct GlRecord {
    std::vector<std::pair<GLenum, GLuint>> made; // (glObjectLabel identifier, name)
    std::map<std::pair<GLenum, GLuint>, std::string> labels;
    std::vector<std::string> groups; // "+name" / "-"
} gl_record;

PFNGLCREATEBUFFERSPROC real_create_buffers = nullptr;
PFNGLCREATETEXTURESPROC real_create_textures = nullptr;
PFNGLCREATESAMPLERSPROC real_create_samplers = nullptr;
PFNGLCREATEVERTEXARRAYSPROC real_create_vertex_arrays = nullptr;
PFNGLCREATEQUERIESPROC real_create_queries = nullptr;
PFNGLCREATEPROGRAMPROC real_create_program = nullptr;
PFNGLOBJECTLABELPROC real_object_label = nullptr;
PFNGLPUSHDEBUGGROUPPROC real_push = nullptr;
PFNGLPOPDEBUGGROUPPROC real_pop = nullptr;

void record_made(GLenum identifier, GLsizei n, const GLuint* names) {
    for (GLsizei i = 0; i < n; ++i) gl_record.made.push_back({identifier, names[i]});
}
void APIENTRY create_buffers(GLsizei n, GLuint* names) {
    real_create_buffers(n, names);
    record_made(GL_BUFFER, n, names);
}
void APIENTRY create_textures(GLenum target, GLsizei n, GLuint* names) {
    real_create_textures(target, n, names);
    record_made(GL_TEXTURE, n, names);
}
void APIENTRY create_samplers(GLsizei n, GLuint* names) {
    real_create_samplers(n, names);
    record_made(GL_SAMPLER, n, names);
}
void APIENTRY create_vertex_arrays(GLsizei n, GLuint* names) {
    real_create_vertex_arrays(n, names);
    record_made(GL_VERTEX_ARRAY, n, names);
}
void APIENTRY create_queries(GLenum target, GLsizei n, GLuint* names) {
    real_create_queries(target, n, names);
    record_made(GL_QUERY, n, names);
}
GLuint APIENTRY create_program() {
    const GLuint program = real_create_program();
    record_made(GL_PROGRAM, 1, &program);
    return program;
}
void APIENTRY object_label(GLenum identifier, GLuint name, GLsizei length, const GLchar* label) {
    gl_record.labels[{identifier, name}] = length < 0 ? std::string(label) : std::string(label, size_t(length));
    real_object_label(identifier, name, length, label);
}
void APIENTRY push_group(GLenum source, GLuint id, GLsizei length, const GLchar* message) {
    gl_record.groups.push_back("+" + (length < 0 ? std::string(message) : std::string(message, size_t(length))));
    real_push(source, id, length, message);
}
void APIENTRY pop_group() {
    gl_record.groups.push_back("-");
    real_pop();
}

void (*gl_filter(const char* name, void (*real)(void)))(void) {
#    define GRASS_GL_WRAP(gl_name, pointer, Type, wrapper)       \
        if (std::strcmp(name, gl_name) == 0) {                   \
            pointer = reinterpret_cast<Type>(real);              \
            return reinterpret_cast<void (*)(void)>(&(wrapper)); \
        }
    GRASS_GL_WRAP("glCreateBuffers", real_create_buffers, PFNGLCREATEBUFFERSPROC, create_buffers)
    GRASS_GL_WRAP("glCreateTextures", real_create_textures, PFNGLCREATETEXTURESPROC, create_textures)
    GRASS_GL_WRAP("glCreateSamplers", real_create_samplers, PFNGLCREATESAMPLERSPROC, create_samplers)
    GRASS_GL_WRAP("glCreateVertexArrays", real_create_vertex_arrays, PFNGLCREATEVERTEXARRAYSPROC, create_vertex_arrays)
    GRASS_GL_WRAP("glCreateQueries", real_create_queries, PFNGLCREATEQUERIESPROC, create_queries)
    GRASS_GL_WRAP("glCreateProgram", real_create_program, PFNGLCREATEPROGRAMPROC, create_program)
    GRASS_GL_WRAP("glObjectLabel", real_object_label, PFNGLOBJECTLABELPROC, object_label)
    GRASS_GL_WRAP("glPushDebugGroup", real_push, PFNGLPUSHDEBUGGROUPPROC, push_group)
    GRASS_GL_WRAP("glPopDebugGroup", real_pop, PFNGLPOPDEBUGGROUPPROC, pop_group)
#    undef GRASS_GL_WRAP
    return real;
}

grass_host::TargetDesc gl_target() {
    grass_host::TargetDesc t;
    t.width = 96;
    t.height = 64;
    t.gl_proc_filter = &gl_filter;
    return t;
}

// The label glGetObjectLabel reads back, through the host's own GL.
std::string read_label(const grass_host::Host& host, GLenum identifier, GLuint name) {
    const auto get = reinterpret_cast<PFNGLGETOBJECTLABELPROC>(host.gl_proc_address("glGetObjectLabel"));
    char label[128] = {};
    GLsizei length = 0;
    get(identifier, name, sizeof(label), &length, label);
    return std::string(label, size_t(length));
}

bool gl_debug_context(const grass_host::Host& host) {
    GLint flags = 0;
    reinterpret_cast<PFNGLGETINTEGERVPROC>(host.gl_proc_address("glGetIntegerv"))(GL_CONTEXT_FLAGS, &flags);
    return (flags & GL_CONTEXT_FLAG_DEBUG_BIT) != 0;
}

TEST(GlDebugLabels, EveryObjectGrassMakesIsLabelledAndTheDebugGroupsBalance) {
    gl_record = GlRecord{};
    Scene s;
    const grass_debug_labels on = GRASS_DEBUG_LABELS_ON; // also on OSMesa, which has no debug context
    make_scene(&s, GRASS_BACKEND_GL, gl_target(), &on);
    ASSERT_FALSE(HasFatalFailure());
    render_frames(&s, 3);
    ASSERT_FALSE(HasFatalFailure());

    std::map<GLenum, int> made_per_kind, labelled_per_kind;
    for (const auto& object : gl_record.made) {
        made_per_kind[object.first] += 1;
        const auto l = gl_record.labels.find(object);
        if (l == gl_record.labels.end()) continue;
        labelled_per_kind[object.first] += 1;
        EXPECT_TRUE(grass_name(l->second)) << std::hex << object.first << " labelled \"" << l->second << "\"";
        EXPECT_EQ(read_label(*s.host, object.first, object.second), l->second) << "glGetObjectLabel";
    }
    EXPECT_EQ(labelled_per_kind, made_per_kind) << "objects made and labelled, per glObjectLabel identifier";
    for (const GLenum kind : {GL_BUFFER, GL_TEXTURE, GL_SAMPLER, GL_VERTEX_ARRAY, GL_PROGRAM}) {
        EXPECT_GT(made_per_kind[kind], 0) << "the scene makes no object of kind 0x" << std::hex << kind;
    }

    const std::multiset<std::string> begun = check_balanced(gl_record.groups);
    EXPECT_EQ(begun.count("grass render"), 3u);
    for (const char* label : kFrameLabels) {
        if (std::strcmp(label, "grass draw") == 0) continue; // GL: "grass render"
        EXPECT_EQ(begun.count(label), 3u) << label << ", one per frame";
    }
}

TEST(GlDebugLabels, OffLabelsOnlyTheCurrentContextCheckAndPushesNoGroup) {
    for (const grass_debug_labels labels : {GRASS_DEBUG_LABELS_OFF, GRASS_DEBUG_LABELS_AUTO}) {
        gl_record = GlRecord{};
        Scene s;
        make_scene(&s, GRASS_BACKEND_GL, gl_target(), &labels, false);
        ASSERT_FALSE(HasFatalFailure());
        render_frames(&s, 2);
        // AUTO is on exactly in a debug context (the EGL host asks for one; OSMesa has none).
        const bool on = labels == GRASS_DEBUG_LABELS_AUTO && gl_debug_context(*s.host);
        EXPECT_GT(gl_record.made.size(), 10u);
        if (on) {
            EXPECT_EQ(gl_record.labels.size(), gl_record.made.size());
            EXPECT_FALSE(gl_record.groups.empty());
            continue;
        }
        // The one label grass always sets: its current-context check's vertex array (grass_gl.h).
        ASSERT_EQ(gl_record.labels.size(), 1u);
        EXPECT_EQ(gl_record.labels.begin()->first.first, GLenum(GL_VERTEX_ARRAY));
        EXPECT_EQ(gl_record.labels.begin()->second.rfind("grass context ", 0), 0u);
        EXPECT_TRUE(gl_record.groups.empty()) << gl_record.groups.size() << " group calls";
    }
}

#endif

TEST(DebugLabelsDesc, ABadValueOrAnUnknownChainedStructIsRefusedNamingIt) {
    grass_debug_labels_desc ld = grass_default_debug_labels_desc();
    EXPECT_EQ(ld.type, GRASS_STRUCT_TYPE_DEBUG_LABELS_DESC);
    EXPECT_EQ(ld.labels, GRASS_DEBUG_LABELS_AUTO);
    EXPECT_EQ(ld.next, nullptr);
    std::string log;
    grass_context_desc cd = grass_default_context_desc();
    cd.log_user_data = &log;
    cd.log_fn = [](void* user, grass_log_level, grass_message_id, const char* m) {
        *static_cast<std::string*>(user) += std::string(m) + "\n";
    };
    cd.next = &ld;
    grass_context* ctx = nullptr;
    ld.labels = static_cast<grass_debug_labels>(7);
    EXPECT_EQ(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(log.find("labels 7"), std::string::npos) << log;
    ld.labels = GRASS_DEBUG_LABELS_OFF;
    grass_view_desc other = grass_default_view_desc();
    ld.next = &other;
    EXPECT_EQ(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_NE(log.find("link 2"), std::string::npos) << log;
    ld.next = &ld; // a loop
    EXPECT_EQ(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_EQ(ctx, nullptr);
    ld.next = nullptr;
    ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx), GRASS_SUCCESS) << log;
    grass_destroy_context(ctx);
}

} // namespace
} // namespace grass_test
