// grass-measure bench's reports: CSV, Markdown and SVG of the presets' rows, CSV and Markdown
// of --sweep's.
#include "bench.hpp"

#include "stats.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace grass_measure {
namespace bench {

using grass_sample::median;

namespace {

const char* const kLevelColors[GRASS_QUALITY_LEVEL_COUNT] = {"#000000", "#1f77b4", "#2ca02c", "#ff7f0e", "#d62728"};

const Row* sweep_baseline(const std::vector<Row>& rows, const Row& r) {
    for (const Row& b : rows) {
        if (b.backend == r.backend && b.scene == r.scene && b.camera == r.camera && b.knob == "preset" &&
            b.level == GRASS_QUALITY_DEFAULT)
            return &b;
    }
    return nullptr;
}

std::string ratio_text(double num, const Row* base) {
    return base && base->frame_ms > 0 ? fmt("%.3f", num / base->frame_ms) : "n/a";
}
// The change of 1 - SSIM against DEFAULT's: positive = further from the reference.
std::string error_change_text(const Row& r, const Row* base) {
    return base ? fmt("%+.4f", base->ssim - r.ssim) : "n/a";
}

// "a / b / c" of the three scales' values.
std::string scales_text(const double* v, const char* f = "%.2f") {
    return fmt(f, v[0]) + " / " + fmt(f, v[1]) + " / " + fmt(f, v[2]);
}
// The CSV's values of the three scales.
std::string scales_csv(const double* v) {
    return fmt("%.5f", v[0]) + ',' + fmt("%.5f", v[1]) + ',' + fmt("%.5f", v[2]);
}
// The largest of the three scales' values.
double worst(const double* v) { return std::max({v[0], v[1], v[2]}); }
// The worst normalised error of a row: 1 - SSIM and RMS, every scale.
double worst_normalised(const Row& r) { return std::max(worst(r.norm.ssim_error), worst(r.norm.rms)); }

} // namespace

// ---- Output -----------------------------------------------------------------------------

std::string csv(const std::vector<Row>& rows, const Options& o) {
    std::ostringstream s;
    s << "scene,camera,backend,preset,width,height,msaa,blades_per_patch,subdivisions,frame_ms,frame_min_ms,cost_ratio,"
         "plan_ms,gpu_ms,gpu_geometry_ms,gpu_volume_ms,gpu_image_ms,ssim,psnr_db,triangles,geometry_instances,"
         "volume_instances,image_instances,field_create_ms,reference_cached,"
         "ssim_error_x1,ssim_error_x2,ssim_error_x4,rms_x1,rms_x2,rms_x4,"
         "seed_ssim_error_x1,seed_ssim_error_x2,seed_ssim_error_x4,seed_rms_x1,seed_rms_x2,seed_rms_x4,"
         "norm_ssim_error_x1,norm_ssim_error_x2,norm_ssim_error_x4,norm_rms_x1,norm_rms_x2,norm_rms_x4,"
         "band_colour_levels,colour_band,seed_band_colour_levels,band_coverage,coverage_band,seed_band_coverage,"
         "supersample,backend_diff_mean_levels,backend_diff_max_levels,ssim_vs_other_seeds,grass_share,"
         "truth_grass_share\n";
    for (const Row& r : rows) {
        s << r.scene << ',' << r.camera << ',' << r.backend << ',' << r.preset << ',' << o.width << ',' << o.height
          << ',' << r.msaa << ',' << r.blades << ',' << r.subdivisions << ',' << fmt("%.2f", r.frame_ms) << ','
          << fmt("%.2f", r.frame_min_ms) << ',' << fmt("%.4f", r.ratio) << ',' << fmt("%.3f", r.plan_ms) << ','
          << gpu_text(r, -1) << ',' << gpu_text(r, 0) << ',' << gpu_text(r, 1) << ',' << gpu_text(r, 2) << ','
          << fmt("%.5f", r.ssim) << ',' << psnr_text(r.psnr) << ',' << r.triangles << ',' << r.instances[0] << ','
          << r.instances[1] << ',' << r.instances[2] << ',' << fmt("%.1f", r.field_ms) << ',' << r.cached << ','
          << scales_csv(r.error.ssim_error) << ',' << scales_csv(r.error.rms) << ',' << scales_csv(r.seed.ssim_error)
          << ',' << scales_csv(r.seed.rms) << ',' << scales_csv(r.norm.ssim_error) << ',' << scales_csv(r.norm.rms)
          << ',' << fmt("%.3f", r.error.band_colour) << ',' << r.error.colour_band << ','
          << fmt("%.3f", r.seed.band_colour) << ',' << fmt("%.4f", r.error.band_coverage) << ','
          << r.error.coverage_band << ',' << fmt("%.4f", r.seed.band_coverage) << ',' << o.supersample << ','
          << fmt("%.3f", r.backend_diff_mean) << ',' << fmt("%.0f", r.backend_diff_max) << ','
          << fmt("%.5f", r.ssim_other) << ',' << fmt("%.4f", r.grass_share) << ',' << fmt("%.4f", r.truth_grass_share)
          << '\n';
    }
    return s.str();
}

std::string markdown(const std::vector<Row>& rows, const Options& o, double total_s) {
    std::ostringstream s;
    s << "# grass-bench results\n\n"
      << "Written by `grass-measure bench` (tools/measure/bench.cpp; docs/quality.md explains it). " << o.width << " x "
      << o.height
      << " pixels, each preset on a target with its own MSAA sample count; frame = wall time of a rendered and "
         "read-back "
         "frame, median of "
      << o.frames
      << " after one warm-up (the real scenes' reference: one frame); cost = frame / the reference's frame (same "
         "scene, camera, backend). The truth: the reference (blades everywhere, 4 samples) rendered "
      << o.supersample << " x " << o.supersample
      << " times larger and box-downsampled in linear light, on GL, with the scene's patch and mirror seeds (A) and "
         "with both seeds + "
      << o.seed_step
      << " (B). Errors against truth A: 1 - SSIM (luma, Gaussian window 11, sigma 1.5) and RMS (sRGB levels) at "
         "full size, x2 and x4 box-downsampled; / seed = divided by truth B's error against A (1.0: as close as "
         "another sample of the truth). Band colour: the mean colour of the image minus the truth's, sRGB levels, in "
         "the one of 12 row bands where it is largest (negative: darker); coverage: the share of grass pixels, "
         "likewise. SSIM and PSNR in the tables below are against truth A too. GPU = grass_get_tier_gpu_ms summed "
         "over the tiers (n/a: no timer result). The run took "
      << fmt("%.0f", total_s) << " s.\n\n";
    s << "## Accuracy: error / seed-to-seed error\n\n"
      << "| scene | camera | backend | preset | cost / reference | 1 - SSIM / seed x1 / x2 / x4 | RMS / seed x1 / x2 "
         "/ x4 | worst / seed | band colour (seed) | band coverage (seed) |\n"
      << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        s << "| " << r.scene << " | " << r.camera << " | " << r.backend << " | " << r.preset << " | "
          << (std::isnan(r.ratio) ? std::string("n/a") : fmt("%.3f", r.ratio)) << (r.cached ? " (cached)" : "") << " | "
          << scales_text(r.norm.ssim_error) << " | " << scales_text(r.norm.rms) << " | "
          << fmt("%.2f", worst_normalised(r)) << " | " << fmt("%+.1f", r.error.band_colour) << " ("
          << fmt("%.1f", std::fabs(r.seed.band_colour)) << ") | " << fmt("%+.3f", r.error.band_coverage) << " ("
          << fmt("%.3f", std::fabs(r.seed.band_coverage)) << ") |\n";
    }
    s << "\n## The seed-to-seed error: truth B against truth A\n\n"
      << "| scene | camera | SSIM x1 / x2 / x4 | RMS x1 / x2 / x4 (levels) | band colour | band coverage | grass "
         "pixels of truth A |\n"
      << "|---|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        // The first row of each scene and camera (every row of one carries its seed-to-seed error).
        if (i > 0 && rows[i - 1].scene == r.scene && rows[i - 1].camera == r.camera) continue;
        const double ssim[3] = {1 - r.seed.ssim_error[0], 1 - r.seed.ssim_error[1], 1 - r.seed.ssim_error[2]};
        s << "| " << r.scene << " | " << r.camera << " | " << scales_text(ssim, "%.3f") << " | "
          << scales_text(r.seed.rms) << " | " << fmt("%+.1f", r.seed.band_colour) << " | "
          << fmt("%+.3f", r.seed.band_coverage) << " | " << fmt("%.3f", r.truth_grass_share) << " |\n";
    }
    bool agreement = false;
    for (const Row& r : rows) agreement = agreement || r.backend_diff_mean >= 0;
    if (agreement) {
        s << "\n## The backends' references (the same seeds, the bench's size): Vulkan against GL\n\n"
          << "| scene | camera | mean difference (levels) | largest (levels) |\n|---|---|---|---|\n";
        for (const Row& r : rows) {
            if (r.backend_diff_mean < 0) continue;
            s << "| " << r.scene << " | " << r.camera << " | " << fmt("%.4f", r.backend_diff_mean) << " | "
              << fmt("%.0f", r.backend_diff_max) << " |\n";
        }
    }
    s << "\n";
    // Summary: per backend and preset, the median over scenes and cameras.
    s << "## Summary: median over scenes and cameras\n\n"
      << "| backend | preset | cost / reference | 1 - SSIM | PSNR (dB) | frame (ms) | plan (ms) |\n"
      << "|---|---|---|---|---|---|---|\n";
    for (const char* be : {"gl", "vk"}) {
        for (int l = 0; l < GRASS_QUALITY_LEVEL_COUNT; ++l) {
            std::vector<double> ratio, err, psnr, frame, plan;
            for (const Row& r : rows) {
                if (r.backend != be || r.level != l) continue;
                ratio.push_back(r.ratio);
                err.push_back(1.0 - r.ssim);
                psnr.push_back(r.psnr);
                frame.push_back(r.frame_ms);
                plan.push_back(r.plan_ms);
            }
            if (ratio.empty()) continue;
            s << "| " << be << " | " << kLevelNames[l] << " | " << fmt("%.3f", median(ratio)) << " | "
              << fmt("%.4f", median(err)) << " | " << psnr_text(median(psnr)) << " | " << fmt("%.1f", median(frame))
              << " | " << fmt("%.2f", median(plan)) << " |\n";
        }
    }
    s << "\n## Every frame\n\n"
      << "| scene | camera | backend | preset | MSAA | blades x subdiv | frame (ms) | cost / ref | plan (ms) | GPU "
         "(ms) | "
         "SSIM | PSNR (dB) | triangles | instances g / v / i |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        s << "| " << r.scene << " | " << r.camera << " | " << r.backend << " | " << r.preset << " | " << r.msaa << " | "
          << r.blades << " x " << r.subdivisions << " | " << fmt("%.1f", r.frame_ms) << " | " << fmt("%.3f", r.ratio)
          << " | " << fmt("%.2f", r.plan_ms) << " | " << gpu_text(r, -1) << " | " << fmt("%.4f", r.ssim) << " | "
          << psnr_text(r.psnr) << " | " << r.triangles << " | " << r.instances[0] << " / " << r.instances[1] << " / "
          << r.instances[2] << " |\n";
    }
    return s.str();
}

// x: cost relative to the reference, log10; y: the worst normalised error (1 - SSIM and RMS at
// the three scales, each divided by the seed-to-seed error). A marker per frame: colour per
// preset, circle GL, square Vulkan; hovering shows the frame.
std::string svg(const std::vector<Row>& rows) {
    const double W = 760, H = 480, L = 70, R = 150, T = 40, B = 60;
    double xmin = 0.0, xmax = 0.0, ymax = 0.0;
    for (const Row& r : rows) {
        if (!(r.ratio > 0) || !std::isfinite(r.ratio)) continue;
        xmin = std::min(xmin, std::floor(std::log10(r.ratio)));
        xmax = std::max(xmax, std::ceil(std::log10(r.ratio)));
        ymax = std::max(ymax, worst_normalised(r));
    }
    if (xmax <= xmin) xmax = xmin + 1;
    // A tidy top for the y axis: 1, 2 or 5 times a power of ten.
    double ytop = 0.01;
    if (ymax > 0) {
        const double p = std::pow(10.0, std::floor(std::log10(ymax)));
        ytop = ymax <= p ? p : ymax <= 2 * p ? 2 * p : ymax <= 5 * p ? 5 * p : 10 * p;
    }
    auto px = [&](double ratio) { return L + (std::log10(ratio) - xmin) / (xmax - xmin) * (W - L - R); };
    auto py = [&](double e) { return H - B - e / ytop * (H - T - B); };
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
      << ' ' << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << L
      << "\" y=\"22\" font-size=\"15\">grass-bench: frame cost against image error, every scene and camera</text>\n";
    // Axes, grid and ticks.
    s << "<g stroke=\"#ddd\">\n";
    for (double d = xmin; d <= xmax + 1e-9; d += 1.0) {
        for (int m = 2; m < 10 && d < xmax; ++m) {
            const double x = px(std::pow(10.0, d) * m);
            s << "<line x1=\"" << fmt("%.1f", x) << "\" y1=\"" << T << "\" x2=\"" << fmt("%.1f", x) << "\" y2=\""
              << H - B << "\" stroke=\"#f2f2f2\"/>\n";
        }
        s << "<line x1=\"" << fmt("%.1f", px(std::pow(10.0, d))) << "\" y1=\"" << T << "\" x2=\""
          << fmt("%.1f", px(std::pow(10.0, d))) << "\" y2=\"" << H - B << "\"/>\n";
    }
    for (int k = 0; k <= 5; ++k) {
        s << "<line x1=\"" << L << "\" y1=\"" << fmt("%.1f", py(ytop * k / 5)) << "\" x2=\"" << W - R << "\" y2=\""
          << fmt("%.1f", py(ytop * k / 5)) << "\"/>\n";
    }
    s << "</g>\n<g stroke=\"black\"><line x1=\"" << L << "\" y1=\"" << H - B << "\" x2=\"" << W - R << "\" y2=\""
      << H - B << "\"/><line x1=\"" << L << "\" y1=\"" << T << "\" x2=\"" << L << "\" y2=\"" << H - B << "\"/></g>\n";
    for (double d = xmin; d <= xmax + 1e-9; d += 1.0) {
        s << "<text x=\"" << fmt("%.1f", px(std::pow(10.0, d))) << "\" y=\"" << H - B + 16
          << "\" text-anchor=\"middle\">" << fmt("%g", std::pow(10.0, d)) << "</text>\n";
    }
    for (int k = 0; k <= 5; ++k) {
        s << "<text x=\"" << L - 6 << "\" y=\"" << fmt("%.1f", py(ytop * k / 5) + 4) << "\" text-anchor=\"end\">"
          << fmt("%g", ytop * k / 5) << "</text>\n";
    }
    s << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 18
      << "\" text-anchor=\"middle\">frame cost / reference's frame cost (log scale)</text>\n"
      << "<text transform=\"translate(18," << (T + H - B) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">worst error / seed-to-seed error</text>\n";
    // Markers.
    for (const Row& r : rows) {
        if (!(r.ratio > 0) || !std::isfinite(r.ratio)) continue;
        const double x = px(r.ratio), y = py(worst_normalised(r));
        const std::string title = "<title>" + r.scene + ", " + r.camera + ", " + r.backend + ", " + r.preset +
                                  ": cost " + fmt("%.3f", r.ratio) + ", error / seed " +
                                  fmt("%.2f", worst_normalised(r)) + "</title>";
        const char* c = kLevelColors[r.level];
        if (r.backend == "gl") {
            s << "<circle cx=\"" << fmt("%.1f", x) << "\" cy=\"" << fmt("%.1f", y) << "\" r=\"4\" fill=\"" << c
              << "\" fill-opacity=\"0.75\">" << title << "</circle>\n";
        } else {
            s << "<rect x=\"" << fmt("%.1f", x - 3.5) << "\" y=\"" << fmt("%.1f", y - 3.5)
              << "\" width=\"7\" height=\"7\" fill=\"none\" stroke=\"" << c << "\" stroke-width=\"1.5\">" << title
              << "</rect>\n";
        }
    }
    // Legend.
    double ly = T + 10;
    for (int l = 0; l < GRASS_QUALITY_LEVEL_COUNT; ++l, ly += 20) {
        s << "<circle cx=\"" << W - R + 20 << "\" cy=\"" << ly << "\" r=\"5\" fill=\"" << kLevelColors[l]
          << "\"/><text x=\"" << W - R + 32 << "\" y=\"" << ly + 4 << "\">" << kLevelNames[l] << "</text>\n";
    }
    ly += 10;
    s << "<circle cx=\"" << W - R + 20 << "\" cy=\"" << ly << "\" r=\"4\" fill=\"#777\"/><text x=\"" << W - R + 32
      << "\" y=\"" << ly + 4 << "\">GL (llvmpipe)</text>\n";
    ly += 20;
    s << "<rect x=\"" << W - R + 16.5 << "\" y=\"" << ly - 3.5
      << "\" width=\"7\" height=\"7\" fill=\"none\" stroke=\"#777\" stroke-width=\"1.5\"/><text x=\"" << W - R + 32
      << "\" y=\"" << ly + 4 << "\">Vulkan (lavapipe)</text>\n";
    s << "</svg>\n";
    return s.str();
}

std::string sweep_csv(const std::vector<Row>& rows, const Options& o) {
    std::ostringstream s;
    s << "backend,scene,camera,knob,value,width,height,msaa,blades_per_patch,subdivisions,frame_ms,frame_min_ms,"
         "cost_vs_default,cost_vs_reference,plan_ms,gpu_ms,ssim,psnr_db,one_minus_ssim_change_vs_default,triangles,"
         "geometry_instances,volume_instances,image_instances,field_create_ms\n";
    for (const Row& r : rows) {
        const Row* b = sweep_baseline(rows, r);
        s << r.backend << ',' << r.scene << ',' << r.camera << ',' << r.knob << ',' << r.value << ',' << o.width << ','
          << o.height << ',' << r.msaa << ',' << r.blades << ',' << r.subdivisions << ',' << fmt("%.2f", r.frame_ms)
          << ',' << fmt("%.2f", r.frame_min_ms) << ',' << ratio_text(r.frame_ms, b) << ',' << fmt("%.4f", r.ratio)
          << ',' << fmt("%.3f", r.plan_ms) << ',' << gpu_text(r, -1) << ',' << fmt("%.5f", r.ssim) << ','
          << psnr_text(r.psnr) << ',' << error_change_text(r, b) << ',' << r.triangles << ',' << r.instances[0] << ','
          << r.instances[1] << ',' << r.instances[2] << ',' << fmt("%.1f", r.field_ms) << '\n';
    }
    return s.str();
}

std::string sweep_markdown(const std::vector<Row>& rows, const Options& o, double total_s) {
    const grass_quality_desc d = grass_quality_preset(GRASS_QUALITY_DEFAULT);
    std::ostringstream s;
    s << "# grass-bench sweep: one knob at a time from DEFAULT\n\n"
      << "Written by `grass-measure bench --sweep` (tools/measure/bench.cpp; docs/quality.md explains the knobs and "
         "the "
         "measures). Each row is DEFAULT with one knob of `grass_quality_desc` changed (the others at DEFAULT's: "
         "distance_scale "
      << fmt("%g", d.distance_scale) << ", transition_scale " << fmt("%g", d.transition_scale) << ", slice_scale "
      << fmt("%g", d.slice_scale) << ", macro_cell_scale " << fmt("%g", d.macro_cell_scale) << ", blade_subdivisions "
      << d.blade_subdivisions << ", blade_fraction " << fmt("%g", d.blade_fraction) << ", msaa_samples "
      << d.msaa_samples << "); the rows `preset` are the REFERENCE and DEFAULT presets themselves. " << o.width << " x "
      << o.height
      << " pixels, each row on a target with its own MSAA sample count; frame = wall time of a rendered and read-back "
         "frame, median of "
      << o.frames
      << " after one warm-up; cost = frame / DEFAULT's or the reference's frame (same backend, scene, "
         "camera); SSIM (luma) and PSNR (sRGB RGB) against the reference's image of the same frame; change of 1 - SSIM "
         "= (1 - SSIM) - DEFAULT's (positive: further from the reference). The run took "
      << fmt("%.0f", total_s) << " s.\n\n";
    // With more than one frame per backend, knob and value: the median over scenes and cameras.
    std::vector<std::string> frames;
    for (const Row& r : rows) {
        const std::string f = r.scene + "/" + r.camera;
        if (std::find(frames.begin(), frames.end(), f) == frames.end()) frames.push_back(f);
    }
    if (frames.size() > 1) {
        s << "## Summary: median over scenes and cameras\n\n"
          << "| backend | knob | value | cost / default | cost / reference | SSIM | change of 1 - SSIM vs default |\n"
          << "|---|---|---|---|---|---|---|\n";
        std::vector<std::string> done;
        for (const Row& r : rows) {
            const std::string key = r.backend + "/" + r.knob + "/" + r.value;
            if (std::find(done.begin(), done.end(), key) != done.end()) continue;
            done.push_back(key);
            std::vector<double> to_default, to_reference, ssim, change;
            for (const Row& x : rows) {
                if (x.backend != r.backend || x.knob != r.knob || x.value != r.value) continue;
                const Row* b = sweep_baseline(rows, x);
                if (b && b->frame_ms > 0) to_default.push_back(x.frame_ms / b->frame_ms);
                if (b) change.push_back(b->ssim - x.ssim);
                to_reference.push_back(x.ratio);
                ssim.push_back(x.ssim);
            }
            s << "| " << r.backend << " | " << r.knob << " | " << r.value << " | "
              << (to_default.empty() ? "n/a" : fmt("%.3f", median(to_default))) << " | "
              << fmt("%.3f", median(to_reference)) << " | " << fmt("%.4f", median(ssim)) << " | "
              << (change.empty() ? "n/a" : fmt("%+.4f", median(change))) << " |\n";
        }
        s << "\n## Every frame\n\n";
    }
    s << "| backend | scene | camera | knob | value | frame (ms) | cost / default | cost / reference | SSIM | PSNR "
         "(dB) | "
         "change of 1 - SSIM vs default | triangles |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        const Row* b = sweep_baseline(rows, r);
        s << "| " << r.backend << " | " << r.scene << " | " << r.camera << " | " << r.knob << " | " << r.value << " | "
          << fmt("%.1f", r.frame_ms) << " | " << ratio_text(r.frame_ms, b) << " | " << fmt("%.3f", r.ratio) << " | "
          << fmt("%.4f", r.ssim) << " | " << psnr_text(r.psnr) << " | " << error_change_text(r, b) << " | "
          << r.triangles << " |\n";
    }
    return s.str();
}

} // namespace bench
} // namespace grass_measure
