// grass-measure bench: the subcommand and the run (bench.hpp explains the measures; the
// reports are bench_report.cpp's).
#include "bench.hpp"
#include "bench_scenes.hpp"

#include <grass/grass.h>

#include "accuracy.hpp"
#include "cli.hpp"
#include "file_bytes.hpp"
#include "headless_host.hpp"
#include "image_io.hpp"
#include "image_metrics.hpp"
#include "measure.hpp"
#include "reference_cache.hpp"
#include "scene.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace grass_measure {
namespace bench {

using grass_sample::median;

const char* const kLevelNames[GRASS_QUALITY_LEVEL_COUNT] = {"reference", "high", "default", "low", "fastest"};

namespace {

// ---- One scene x preset x backend: a host, a context, a field, every camera ---------------

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// One setup to render: a preset, or (--sweep) DEFAULT with one knob changed.
struct Variant {
    grass_quality_desc q;
    int level = GRASS_QUALITY_DEFAULT; // the preset's level; a sweep's variants: DEFAULT's
    std::string name;                  // Row::preset and the progress line
    std::string file;                  // images: <scene>-<camera>-<backend>-<file>.png
    std::string knob, value;           // the sweep's columns ("preset" and the level's name for a preset)
    // The sweep's blade_culling rows: per-blade culling (grass_set_blade_culling) on the field.
    bool culled = false;
    grass_blade_culling_desc culling = grass_default_blade_culling_desc();
    // The blades' dynamic tessellation the preset means (grass_quality_blade_tessellation);
    // off with --full-tessellation.
    grass_blade_tessellation_desc tessellation = grass_default_blade_tessellation_desc();
};

Variant preset_variant(int level) {
    Variant v;
    v.q = grass_quality_preset(grass_quality_level(level));
    v.tessellation = grass_quality_blade_tessellation(grass_quality_level(level));
    v.level = level;
    v.name = v.file = v.value = kLevelNames[level];
    v.knob = "preset";
    return v;
}

// The ground truth of one scene and camera, shared by both backends: the reference rendered
// supersampled with the scene's seeds (A, what every frame is measured against) and with the
// other seeds (B), and B's error against A (the seed-to-seed error every error is divided by).
struct Truth {
    grass_host::Image a, b;
    grass_bench::ImageError seed;
};

// The reference's timed frame per camera, of one scene and backend: the cost every other frame
// of that scene and backend is set against.
struct Reference {
    double ms[kCameraCount] = {};
};

// A host with a target of the given size and samples, a context, and a field of the scene made
// with grass_apply_quality(q); the patch and mirror seeds moved by seed_offset.
struct Session {
    std::unique_ptr<grass_host::Host> host;
    grass_context* ctx = nullptr;
    grass_patch_desc pd{};
    double field_ms = 0;
    Session() = default;
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;
    ~Session() {
        if (ctx) grass_destroy_context(ctx);
    }
};

bool open_session(const Options& opt, grass_backend backend, const PreparedScene& ps, const grass_quality_desc& q,
                  uint64_t seed_offset, uint32_t width, uint32_t height, Session* session, std::string* error,
                  const grass_blade_culling_desc* culling = nullptr,
                  const grass_blade_tessellation_desc* tessellation = nullptr) {
    const char* be = grass_sample::backend_name(backend);
    const grass_sample::Scene& scene = ps.scene;
    grass_host::TargetDesc td = grass_sample::target_desc(scene);
    td.width = width;
    td.height = height;
    td.samples = q.msaa_samples;
    session->host = grass_host::Host::create(backend, td, error);
    if (!session->host) {
        *error = std::string("cannot create the ") + be + " host: " + *error;
        return false;
    }
    grass_context_desc cd = grass_default_context_desc();
    cd.log_fn = grass_sample::log_to_stderr;
    cd.cache_directory = opt.cache.c_str();
    const grass_result created = session->host->create_context(cd, &session->ctx);
    if (created != GRASS_SUCCESS) {
        *error = std::string("grass_create_context failed: ") + grass_result_string(created);
        return false;
    }
    grass_context* ctx = session->ctx;
    session->pd = scene.patch;
    session->pd.seed += seed_offset;
    std::vector<grass_tier_desc> tiers;
    std::vector<grass_lod_test> tests;
    if (!lod_setup(ctx, q, scene, &session->pd, &tiers, &tests, error)) return false;
    const auto t_field = std::chrono::steady_clock::now();
    grass_patch_id patch{};
    grass_field_desc fd = scene.field;
    fd.mirror_seed += uint32_t(seed_offset);
    const char* call = "grass_create_patch";
    grass_result r = grass_create_patch(ctx, &session->pd, &patch);
    if (r == GRASS_SUCCESS) {
        call = "grass_create_map";
        r = grass_sample::create_scene_maps(ctx, scene, &fd.maps);
    }
    fd.patch = patch;
    fd.tiers = tiers.data();
    fd.tier_count = uint32_t(tiers.size());
    fd.lod_tests = tests.data();
    fd.lod_test_count = uint32_t(tests.size());
    grass_field_id field{};
    if (r == GRASS_SUCCESS) {
        call = "grass_create_field";
        r = grass_create_field(ctx, &fd, &field);
    }
    if (r == GRASS_SUCCESS && culling) {
        call = "grass_set_blade_culling";
        r = grass_set_blade_culling(ctx, field, culling);
    }
    if (r == GRASS_SUCCESS && tessellation) {
        call = "grass_set_blade_tessellation";
        r = grass_set_blade_tessellation(ctx, field, tessellation);
    }
    session->field_ms = seconds_since(t_field) * 1e3;
    if (r != GRASS_SUCCESS) {
        *error = std::string(ps.bench->name) + ": the field was refused: " + call +
                 " failed: " + grass_result_string(r) + " (" + grass_get_last_error(ctx) + ")";
        return false;
    }
    return true;
}

grass_view_desc camera_view(const Session& session, const PreparedScene& ps, int ci) {
    grass_view_desc view = grass_host::make_view(*session.host, ps.cams[ci][0], ps.cams[ci][1], ps.scene.fov_degrees,
                                                 0.05f, ps.scene.far_m);
    grass_sample::apply_light(ps.scene, &view);
    return view;
}

// The text that names everything defining a reference image: what it is (`kind`), the
// backend that renders it, the library's version and its blade-drawing sources (hashed when
// the build was configured), the scene, the camera, the size and the samples.
std::string reference_key(const PreparedScene& ps, int ci, const std::string& kind, grass_backend backend,
                          uint32_t width, uint32_t height, uint32_t supersample, uint64_t seed_offset) {
    const grass_quality_desc q = grass_quality_preset(GRASS_QUALITY_REFERENCE);
    std::ostringstream k;
    k.precision(9);
    k << "grass-measure reference: " << kind << " backend " << grass_sample::backend_name(backend) << " grass "
      << GRASS_VERSION_MAJOR << '.' << GRASS_VERSION_MINOR << '.' << GRASS_VERSION_PATCH << " sources "
      << GRASS_REFERENCE_SOURCE_HASH << ' ' << ps.identity << " seed+" << seed_offset << " camera "
      << ps.bench->cameras[ci].name;
    for (int e = 0; e < 2; ++e) k << ' ' << ps.cams[ci][e][0] << ',' << ps.cams[ci][e][1] << ',' << ps.cams[ci][e][2];
    k << " size " << width << 'x' << height << " supersample " << supersample << " msaa " << q.msaa_samples
      << " subdivisions " << q.blade_subdivisions;
    return k.str();
}

// One reference image (blades everywhere) of a scene and camera, rendered supersample times
// larger and box-downsampled in linear light to the bench's size (grass_bench::downsample_rgba),
// from the cache when it has it. Rendered on GL (one truth serves both backends; the bench
// reports how far the backends' references differ).
bool truth_image(const Options& opt, const PreparedScene& ps, int ci, uint64_t seed_offset,
                 std::chrono::steady_clock::time_point t_start, grass_host::Image* out, std::string* error) {
    const grass_backend backend = GRASS_BACKEND_GL;
    const uint32_t k = opt.supersample, w = opt.width * k, h = opt.height * k;
    const std::string key = reference_key(ps, ci, "truth", backend, opt.width, opt.height, k, seed_offset);
    CachedReference ref;
    const char* what = seed_offset == 0 ? "A" : "B";
    if (load_reference(opt.references, key, &ref)) {
        std::fprintf(stderr, "[%6.0f s] %-13s %-7s truth %s from the cache (%s, rendered in %.0f s)\n",
                     seconds_since(t_start), ps.bench->name, ps.bench->cameras[ci].name, what,
                     reference_hash(key).c_str(), ref.render_s);
        *out = std::move(ref.image);
        return true;
    }
    const auto t0 = std::chrono::steady_clock::now();
    Session session;
    if (!open_session(opt, backend, ps, grass_quality_preset(GRASS_QUALITY_REFERENCE), seed_offset, w, h, &session,
                      error))
        return false;
    grass_host::Image big;
    const grass_result r = session.host->render(session.ctx, camera_view(session, ps, ci), nullptr, &big, error);
    if (r != GRASS_SUCCESS) {
        *error = std::string(ps.bench->name) + " truth: rendering failed: " + grass_result_string(r) + " (" +
                 grass_get_last_error(session.ctx) + ") " + *error;
        return false;
    }
    ref.image.rgba =
        grass_bench::downsample_rgba(big.rgba.data(), big.width, big.height, k, &ref.image.width, &ref.image.height);
    ref.render_s = seconds_since(t0);
    std::fprintf(stderr, "[%6.0f s] %-13s %-7s truth %s rendered at %ux%u in %.1f s (%s)\n", seconds_since(t_start),
                 ps.bench->name, ps.bench->cameras[ci].name, what, w, h, ref.render_s, reference_hash(key).c_str());
    if (!store_reference(opt.references, key, ref, error)) return false;
    *out = std::move(ref.image);
    return true;
}

// The truths of every measured camera of a scene.
bool make_truths(const Options& opt, const PreparedScene& ps, std::chrono::steady_clock::time_point t_start,
                 Truth truth[kCameraCount], std::string* error) {
    for (const int ci : ps.cameras) {
        if (!truth_image(opt, ps, ci, 0, t_start, &truth[ci].a, error) ||
            !truth_image(opt, ps, ci, opt.seed_step, t_start, &truth[ci].b, error))
            return false;
        truth[ci].seed =
            grass_bench::image_error(truth[ci].a.rgba.data(), truth[ci].b.rgba.data(), opt.width, opt.height);
    }
    return true;
}

// The key of the reference's timed frames (the real scenes': one frame, no warm-up).
std::string timed_reference_key(const Options& opt, const PreparedScene& ps, int ci, grass_backend backend) {
    const int frames = ps.bench->real ? 1 : opt.frames;
    return reference_key(ps, ci, "timed frames " + std::to_string(frames), backend, opt.width, opt.height, 1, 0);
}

// The reference's frame times from the cache, for a run without the reference preset.
void cached_reference_times(const Options& opt, const PreparedScene& ps, grass_backend backend, Reference* ref) {
    for (const int ci : ps.cameras) {
        CachedReference cached;
        if (load_reference(opt.references, timed_reference_key(opt, ps, ci, backend), &cached))
            ref->ms[ci] = cached.frame_ms;
    }
}

// Renders one variant of one scene on one backend: a host with the variant's sample count,
// a context, a field made with grass_apply_quality, then every selected camera (one
// warm-up and opt.frames timed frames each; the reference of a real scene: one frame, timed).
// The reference preset's frame times go into *ref, and its frames into the cache (a cached
// one is not rendered again); every frame is measured against the truth. Appends a row per
// camera; a failed frame is reported and sets *status to 1; false (with *error) when the run
// cannot go on.
bool render_variant(const Options& opt, grass_backend backend, const PreparedScene& ps, const Variant& v,
                    const Truth truth[kCameraCount], Reference* ref, std::chrono::steady_clock::time_point t_start,
                    std::vector<Row>* rows, int* status, std::string* error) {
    const char* be = grass_sample::backend_name(backend);
    const BenchScene& bs = *ps.bench;
    const grass_quality_desc& q = v.q;
    const bool is_reference = v.level == GRASS_QUALITY_REFERENCE && v.knob == "preset";
    Session session;
    if (!open_session(opt, backend, ps, q, 0, opt.width, opt.height, &session, error, v.culled ? &v.culling : nullptr,
                      opt.full_tessellation ? nullptr : &v.tessellation)) {
        *error += std::string(" (") + v.name + ")";
        return false;
    }
    grass_context* ctx = session.ctx;
    const int first = is_reference && bs.real ? 1 : 0; // frame 0: the warm-up
    const int frames = is_reference && bs.real ? 1 : opt.frames;
    for (const int ci : ps.cameras) {
        const grass_view_desc view = camera_view(session, ps, ci);
        Row row;
        row.scene = bs.name;
        row.camera = bs.cameras[ci].name;
        row.backend = be;
        row.preset = v.name;
        row.knob = v.knob;
        row.value = v.value;
        row.level = v.level;
        row.msaa = q.msaa_samples;
        row.blades = session.pd.blade_count;
        row.subdivisions = session.pd.subdivisions;
        row.field_ms = session.field_ms;
        grass_host::Image image;
        const std::string key = is_reference ? timed_reference_key(opt, ps, ci, backend) : std::string();
        CachedReference cached;
        grass_result r = GRASS_SUCCESS;
        if (is_reference && load_reference(opt.references, key, &cached)) {
            image = std::move(cached.image);
            row.frame_ms = row.frame_min_ms = cached.frame_ms;
            row.cached = true;
        } else {
            std::vector<double> wall, plan, gpu[GRASS_TIER_KIND_COUNT];
            grass_frame_stats stats{};
            for (int f = first; f <= frames && r == GRASS_SUCCESS; ++f) {
                grass_host::Image scratch;
                const auto f0 = std::chrono::steady_clock::now();
                r = session.host->render(ctx, view, nullptr, f == first ? &image : &scratch, error);
                const double ms = seconds_since(f0) * 1e3;
                if (r == GRASS_SUCCESS)
                    grass_sample::check(grass_get_frame_stats(ctx, &stats), "grass_get_frame_stats", ctx);
                if (f == 0) continue; // the warm-up: uploads, first use of the pipelines
                wall.push_back(ms);
                plan.push_back(stats.plan_ms);
                double g[GRASS_TIER_KIND_COUNT] = {0, 0, 0};
                grass_bool available = 0;
                grass_sample::check(grass_get_tier_gpu_ms(ctx, g, &available), "grass_get_tier_gpu_ms", ctx);
                if (available) {
                    for (int t = 0; t < GRASS_TIER_KIND_COUNT; ++t) gpu[t].push_back(g[t]);
                }
            }
            if (r != GRASS_SUCCESS) {
                std::fprintf(stderr, "grass-measure bench: %s %s %s %s: rendering failed: %s (%s) %s\n", bs.name,
                             row.camera.c_str(), be, row.preset.c_str(), grass_result_string(r),
                             grass_get_last_error(ctx), error->c_str());
                *status = 1;
                continue;
            }
            row.frame_ms = median(wall);
            row.frame_min_ms = *std::min_element(wall.begin(), wall.end());
            row.plan_ms = median(plan);
            row.gpu_available = !gpu[0].empty();
            for (int t = 0; t < GRASS_TIER_KIND_COUNT && row.gpu_available; ++t) row.gpu_ms[t] = median(gpu[t]);
            row.triangles = stats.triangles;
            for (int t = 0; t < GRASS_TIER_KIND_COUNT; ++t) row.instances[t] = stats.instances[t];
            if (is_reference) {
                cached.image = image;
                cached.frame_ms = row.frame_ms;
                cached.render_s = std::accumulate(wall.begin(), wall.end(), 0.0) / 1e3;
                if (!store_reference(opt.references, key, cached, error)) return false;
            }
        }
        const std::string stem = opt.out + "/images/" + bs.name + "-" + row.camera + "-" + be + "-" + v.file;
        if (!grass_host::write_png(stem + ".png", image, error)) return false;
        if (is_reference) ref->ms[ci] = row.frame_ms;
        // Without the reference's frame (--preset without reference) the cost is unknown.
        row.ratio = ref->ms[ci] > 0 ? row.frame_ms / ref->ms[ci] : std::numeric_limits<double>::quiet_NaN();
        // Against the truth of the scene's seeds, normalised by the other seeds' error.
        const grass_host::Image& t = truth[ci].a;
        const uint8_t* img = image.rgba.data();
        row.ssim = grass_bench::ssim_rgba(t.rgba.data(), img, image.width, image.height);
        row.psnr = grass_bench::psnr_rgba(t.rgba.data(), img, image.width, image.height);
        row.ssim_other = grass_bench::ssim_rgba(truth[ci].b.rgba.data(), img, image.width, image.height);
        row.error = grass_bench::image_error(t.rgba.data(), img, image.width, image.height);
        row.seed = truth[ci].seed;
        row.norm = grass_bench::normalised(row.error, row.seed);
        row.grass_share = grass_bench::row_bands(img, image.width, image.height, 1)[0].coverage;
        row.truth_grass_share = grass_bench::row_bands(t.rgba.data(), t.width, t.height, 1)[0].coverage;
        row.native_reference = is_reference ? image : grass_host::Image{};
        grass_host::Image diff;
        diff.width = image.width;
        diff.height = image.height;
        diff.rgba = grass_bench::difference_rgba(t.rgba.data(), img, image.width, image.height, 4.0);
        if (!grass_host::write_png(stem + "-error.png", diff, error)) return false;
        std::fprintf(stderr,
                     "[%6.0f s] %-13s %-7s %s %-9s frame %8.1f ms (x%.3f)%s  1-SSIM/seed %.2f %.2f %.2f  RMS/seed "
                     "%.2f %.2f %.2f  band colour %+.1f (seed %.1f)  %llu triangles\n",
                     seconds_since(t_start), bs.name, row.camera.c_str(), be, row.preset.c_str(), row.frame_ms,
                     row.ratio, row.cached ? " cached" : "", row.norm.ssim_error[0], row.norm.ssim_error[1],
                     row.norm.ssim_error[2], row.norm.rms[0], row.norm.rms[1], row.norm.rms[2], row.error.band_colour,
                     std::fabs(row.seed.band_colour), static_cast<unsigned long long>(row.triangles));
        rows->push_back(row);
    }
    if (session.host->validation_messages() != 0) {
        std::fprintf(stderr, "grass-measure bench: %u validation messages:\n%s\n", session.host->validation_messages(),
                     session.host->validation_log().c_str());
        *status = 1;
    }
    return true;
}

// ---- --sweep: one knob at a time from DEFAULT ---------------------------------------------

// The sweep's setups: the reference (what every frame is measured against), DEFAULT (the
// baseline), then for each knob of grass_quality_desc but blades_everywhere a few values
// around DEFAULT's within the knob's range (grass.h), the other knobs at DEFAULT's. A value
// equal to DEFAULT's is left out (the baseline row has it). Then the knob blade_culling:
// DEFAULT with Jahrmann's per-blade culling tests (grass_set_blade_culling) one at a time and
// all together, at his values, the distance tests over the geometry tier (distance_max 0).
// `only`: the knobs to sweep (empty: all).
std::vector<Variant> sweep_variants(const std::vector<std::string>& only) {
    const auto wanted = [&](const std::string& knob) {
        return only.empty() || std::find(only.begin(), only.end(), knob) != only.end();
    };
    const grass_quality_desc base = grass_quality_preset(GRASS_QUALITY_DEFAULT);
    std::vector<Variant> v = {preset_variant(GRASS_QUALITY_REFERENCE), preset_variant(GRASS_QUALITY_DEFAULT)};
    struct Knob {
        const char* name;
        std::vector<double> values;
        double current;
        void (*set)(grass_quality_desc*, double);
    };
    const Knob knobs[] = {
        {"distance_scale",
         {0.5, 2.0},
         base.distance_scale,
         [](grass_quality_desc* q, double x) { q->distance_scale = float(x); }},
        {"transition_scale",
         {0.0, 0.5, 1.2},
         base.transition_scale,
         [](grass_quality_desc* q, double x) { q->transition_scale = float(x); }},
        {"slice_scale",
         {0.5, 2.0},
         base.slice_scale,
         [](grass_quality_desc* q, double x) { q->slice_scale = float(x); }},
        {"macro_cell_scale",
         {0.5, 2.0},
         base.macro_cell_scale,
         [](grass_quality_desc* q, double x) { q->macro_cell_scale = float(x); }},
        {"blade_subdivisions",
         {2, 8},
         double(base.blade_subdivisions),
         [](grass_quality_desc* q, double x) { q->blade_subdivisions = uint32_t(x); }},
        {"blade_fraction",
         {0.5, 0.75},
         base.blade_fraction,
         [](grass_quality_desc* q, double x) { q->blade_fraction = float(x); }},
        // Not 2: the headless hosts are meant for 1 or 4 samples (headless_host.hpp), and on
        // llvmpipe a 2-sample target renders the very image of DEFAULT's 4.
        {"msaa_samples",
         {1},
         double(base.msaa_samples),
         [](grass_quality_desc* q, double x) { q->msaa_samples = uint32_t(x); }},
    };
    for (const Knob& k : knobs) {
        if (!wanted(k.name)) continue;
        for (const double x : k.values) {
            if (float(x) == float(k.current)) continue;
            Variant s;
            s.q = base;
            k.set(&s.q, x);
            s.level = GRASS_QUALITY_DEFAULT;
            s.knob = k.name;
            s.value = fmt("%g", x);
            s.name = s.knob + "=" + s.value;
            s.file = "sweep-" + s.knob + "-" + s.value;
            v.push_back(s);
        }
    }
    if (!wanted("blade_culling")) return v;
    struct Culling {
        const char* value;
        void (*set)(grass_blade_culling_desc*);
    };
    const Culling cullings[] = {
        {"orientation", [](grass_blade_culling_desc* c) { c->orientation = 1; }},
        {"frustum", [](grass_blade_culling_desc* c) { c->view_frustum = 1; }},
        {"distance_index", [](grass_blade_culling_desc* c) { c->distance = GRASS_DISTANCE_CULLING_BLADE_INDEX; }},
        {"distance_threshold", [](grass_blade_culling_desc* c) { c->distance = GRASS_DISTANCE_CULLING_THRESHOLD; }},
        {"jahrmann",
         [](grass_blade_culling_desc* c) {
             c->orientation = c->view_frustum = 1;
             c->distance = GRASS_DISTANCE_CULLING_BLADE_INDEX;
         }},
    };
    for (const Culling& c : cullings) {
        Variant s = preset_variant(GRASS_QUALITY_DEFAULT);
        s.culled = true;
        c.set(&s.culling);
        s.knob = "blade_culling";
        s.value = c.value;
        s.name = s.knob + "=" + s.value;
        s.file = "sweep-" + s.knob + "-" + s.value;
        v.push_back(s);
    }
    return v;
}

// The DEFAULT row of r's backend, scene and camera; null when that frame failed.

// The scene or camera called `name` (kScenes' names, kScenes[0]'s camera names); -1 for none.
int scene_index(const std::string& name) {
    for (int s = 0; s < kSceneCount; ++s)
        if (name == kScenes[s].name) return s;
    return -1;
}
int preset_index(const std::string& name) {
    for (int l = 0; l < GRASS_QUALITY_LEVEL_COUNT; ++l)
        if (name == kLevelNames[l]) return l;
    return -1;
}
int camera_index(const std::string& name) {
    for (int c = 0; c < kCameraCount; ++c)
        if (name == kScenes[0].cameras[c].name) return c;
    return -1;
}
// The cameras' names from kScenes, ", " between them: the first `count` of them.
std::string camera_names(int count) {
    std::string list;
    for (int c = 0; c < count; ++c) list += std::string(c ? ", " : "") + kScenes[0].cameras[c].name;
    return list;
}

// A repeatable option naming a scene or camera (`index` finds the name; `list` the names for
// the error): each name's index appended to *out.
void add_names_option(CLI::App& app, const std::string& option, int (*index)(const std::string&), const char* what,
                      const std::string& list, const std::string& help, std::vector<int>* out) {
    const CLI::Validator is_name(
        [index, what, list](std::string& text) {
            return index(text) >= 0 ? std::string()
                                    : "unknown " + std::string(what) + " \"" + text + "\" (" + list + ")";
        },
        what);
    app.add_option_function<std::string>(
           option, [index, out](const std::string& name) { out->push_back(index(name)); }, help)
        ->check(is_name)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->trigger_on_parse();
}

// The reference cache's directory when --references is not given: $XDG_CACHE_HOME or
// ~/.cache, then grass-measure/references; ./grass-measure-references without a home.
std::string default_reference_dir() {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    if (xdg && *xdg) return std::string(xdg) + "/grass-measure/references";
    if (home && *home) return std::string(home) + "/.cache/grass-measure/references";
    return "grass-measure-references";
}

// On each Vulkan reference row whose GL reference row is there too: the mean and largest
// difference of their images over R, G, B, in sRGB levels (Row::backend_diff_*).
void note_backend_agreement(std::vector<Row>* rows) {
    for (Row& vk : *rows) {
        if (vk.backend != "vk" || vk.native_reference.rgba.empty()) continue;
        for (const Row& gl : *rows) {
            if (gl.backend != "gl" || gl.scene != vk.scene || gl.camera != vk.camera ||
                gl.native_reference.rgba.size() != vk.native_reference.rgba.size() || gl.native_reference.rgba.empty())
                continue;
            const auto& a = gl.native_reference.rgba;
            const auto& b = vk.native_reference.rgba;
            double sum = 0, most = 0;
            for (size_t i = 0; i < a.size(); ++i) {
                if (i % 4 == 3) continue;
                const double d = std::fabs(double(a[i]) - double(b[i]));
                sum += d;
                most = std::max(most, d);
            }
            vk.backend_diff_mean = sum / (double(a.size()) * 0.75);
            vk.backend_diff_max = most;
        }
    }
}

int run(Options opt, bool quick) {
    if (quick || opt.sweep) {
        if (opt.scenes.empty()) opt.scenes = {0};
        if (opt.cameras.empty()) opt.cameras = {1};
    }
    if (opt.scenes.empty())
        for (int s = 0; s < kSceneCount; ++s) opt.scenes.push_back(s);
    if (opt.cache.empty()) opt.cache = opt.out + "/cache";
    if (opt.references.empty()) opt.references = default_reference_dir();
    const std::string docs = opt.docs.empty() ? opt.out : opt.docs;
    if (!grass_sample::make_dirs(opt.out + "/images") || !grass_sample::make_dirs(opt.cache) ||
        !grass_sample::make_dirs(docs) || !grass_sample::make_dirs(opt.references)) {
        throw grass_sample::Failure("cannot create " + opt.out + ", " + opt.cache + ", " + opt.references + " or " +
                                    docs);
    }

    std::vector<Variant> variants;
    if (opt.sweep) {
        variants = sweep_variants(opt.knobs);
    } else {
        for (int level = 0; level < GRASS_QUALITY_LEVEL_COUNT; ++level) {
            if (opt.presets.empty() || std::count(opt.presets.begin(), opt.presets.end(), level) > 0)
                variants.push_back(preset_variant(level));
        }
    }
    const auto t_start = std::chrono::steady_clock::now();
    std::vector<Row> rows;
    int status = 0;
    for (const int si : opt.scenes) {
        PreparedScene ps;
        std::string error;
        if (!prepare_scene(opt, kScenes[si], &ps, &error)) throw grass_sample::Failure(error);
        Truth truth[kCameraCount];
        if (!make_truths(opt, ps, t_start, truth, &error)) throw grass_sample::Failure(error);
        for (const grass_backend backend : opt.backends) {
            // The reference comes first (variants[0]): every other frame's cost is set against it.
            Reference reference;
            if (variants.front().level != GRASS_QUALITY_REFERENCE) cached_reference_times(opt, ps, backend, &reference);
            for (const Variant& v : variants) {
                if (!render_variant(opt, backend, ps, v, truth, &reference, t_start, &rows, &status, &error)) {
                    throw grass_sample::Failure(error);
                }
            }
        }
    }
    note_backend_agreement(&rows);
    auto scene_rank = [&](const Row& r) {
        int s = 0, c = 0;
        for (int k = 0; k < kSceneCount; ++k)
            if (r.scene == kScenes[k].name) s = k;
        for (int k = 0; k < kCameraCount; ++k)
            if (r.camera == kScenes[0].cameras[k].name) c = k;
        return s * kCameraCount + c;
    };
    for (Row& r : rows) r.native_reference = grass_host::Image{}; // no longer needed
    if (opt.sweep) {
        // Rows in the order backend, scene, camera, then the sweep's order.
        auto rank = [&](const Row& r) { return (r.backend == "vk") * kSceneCount * kCameraCount + scene_rank(r); };
        std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) { return rank(a) < rank(b); });
        const double total_s = seconds_since(t_start);
        const std::string md = sweep_markdown(rows, opt, total_s);
        if (!grass_sample::write_text(docs + "/sweep.csv", sweep_csv(rows, opt)) ||
            !grass_sample::write_text(docs + "/sweep.md", md)) {
            throw grass_sample::Failure("cannot write into " + docs);
        }
        std::printf("%s\ngrass-bench: %zu frames in %.0f s; wrote %s/sweep.csv, sweep.md; images in %s/images\n",
                    md.c_str(), rows.size(), total_s, docs.c_str(), opt.out.c_str());
        return status;
    }
    // Rows in the order scene, camera, backend, preset.
    auto rank = [&](const Row& r) {
        return (scene_rank(r) * 2 + (r.backend == "vk")) * GRASS_QUALITY_LEVEL_COUNT + r.level;
    };
    std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) { return rank(a) < rank(b); });
    const double total_s = seconds_since(t_start);
    const std::string md = markdown(rows, opt, total_s);
    if (!grass_sample::write_text(docs + "/bench.csv", csv(rows, opt)) ||
        !grass_sample::write_text(docs + "/bench.md", md) ||
        !grass_sample::write_text(docs + "/cost-vs-error.svg", svg(rows))) {
        throw grass_sample::Failure("cannot write into " + docs);
    }
    std::printf(
        "%s\ngrass-bench: %zu frames in %.0f s; wrote %s/bench.csv, bench.md, cost-vs-error.svg; images in %s/images\n",
        md.c_str(), rows.size(), total_s, docs.c_str(), opt.out.c_str());
    return status;
}

} // namespace
} // namespace bench

Subcommand add_bench(CLI::App& measure) {
    auto o = std::make_shared<bench::Options>();
    auto quick = std::make_shared<bool>(false);
    CLI::App* app = measure.add_subcommand(
        "bench", "Frame cost and image error of every quality preset against the reference (blades everywhere), "
                 "per scene, camera and backend; writes every frame, a CSV, a Markdown table and an SVG plot "
                 "(docs/quality.md).");
    app->add_option_function<std::string>(
           "--backend",
           [o](const std::string& b) {
               grass_backend one = GRASS_BACKEND_GL;
               if (grass_sample::parse_backend(b, &one))
                   o->backends = {one};
               else
                   o->backends = {GRASS_BACKEND_GL, GRASS_BACKEND_VULKAN};
           },
           "backends: gl, vk or both")
        ->check(CLI::Validator(
            [](std::string& b) {
                grass_backend one;
                return grass_sample::parse_backend(b, &one) || b == "both"
                           ? std::string()
                           : "\"" + b + "\" is not a backend (gl, vk or both)";
            },
            "gl|vk|both"))
        ->default_str("both");
    bench::add_names_option(*app, "--scene", bench::scene_index, "scene", "football, park, hills",
                            "football, park or hills (repeatable; default all)", &o->scenes);
    bench::add_names_option(*app, "--camera", bench::camera_index, "camera", bench::camera_names(bench::kCameraCount),
                            bench::camera_names(bench::kCameraCount) + " (repeatable; default " +
                                bench::camera_names(bench::kDefaultCameraCount) +
                                ", the real scenes player; the game cameras third .. flight only when named)",
                            &o->cameras);
    bench::add_names_option(*app, "--preset", bench::preset_index, "preset", "reference, high, default, low, fastest",
                            "reference, high, default, low or fastest (repeatable; default all). Without reference "
                            "the cost against it is n/a, unless the reference's frame is in the cache",
                            &o->presets);
    app->add_flag("--quick", *quick, "one scene and one camera (the reduced football, player): a smoke run");
    app->add_flag("--sweep", o->sweep,
                  "instead of the presets: DEFAULT with one knob at a time changed (a few values each around "
                  "DEFAULT's), the REFERENCE and DEFAULT presets as yardsticks; writes sweep.csv and sweep.md (not "
                  "bench.*). Without --scene/--camera: football, player");
    app->add_option("--knob", o->knobs,
                    "--sweep: only this knob (repeatable): distance_scale, transition_scale, slice_scale, "
                    "macro_cell_scale, blade_subdivisions, blade_fraction, msaa_samples, blade_culling");
    app->add_flag("--full-tessellation", o->full_tessellation,
                  "every preset draws its blades with all their subdivisions at every distance (the frames "
                  "before the blades' dynamic tessellation, grass_quality_blade_tessellation)");
    app->add_option("--frames", o->frames, "timed frames per preset after one warm-up (median)")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    grass_sample::add_size_option(*app, &o->width, &o->height, 16, 4096, "image size");
    app->add_option("--out", o->out, "every frame and difference image")->capture_default_str();
    app->add_option("--docs", o->docs, "bench.csv, bench.md and cost-vs-error.svg (default: --out)");
    app->add_option("--scenes", o->scene_dir, "the scene files")->capture_default_str();
    app->add_option("--cache", o->cache, "baked-slice cache (default OUT/cache)");
    app->add_option("--references", o->references,
                    "the reference images' cache (default $XDG_CACHE_HOME or ~/.cache, then grass-measure/references)");
    app->add_option("--supersample", o->supersample,
                    "the truth is rendered this many times larger per axis (with the reference's 4 samples) and "
                    "box-downsampled; 1: the reference at the bench's size")
        ->capture_default_str()
        ->check(CLI::Range(1, 8));
    return {app, [o, quick]() { return bench::run(*o, *quick); }};
}

} // namespace grass_measure
