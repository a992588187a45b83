// The window test's comparison (ctest viewer_window_*): a viewer's screenshot against the
// headless grass-render image of the same camera.
//   grass_viewer_compare WINDOW.png HEADLESS.png same|different
// Both images must show grass (at least kMinCoverage of their pixels differ from the sky:
// two all-sky images would agree vacuously). "same": the images match within the stated
// tolerance (docs/records/viewer-window.md measured it); "different": they do not (a wrong
// camera must fail the test). Prints the figures; exits 0 when the expectation holds.
#include "image_metrics.hpp"

#include <png.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

// At most this fraction of the pixels may differ by more than kLevelTolerance levels in any
// channel, and the mean per-channel difference stays below kMeanTolerance levels.
constexpr double kMaxDifferingPixels = 0.005;
constexpr int kLevelTolerance = 2;
constexpr double kMeanTolerance = 0.25;
constexpr double kMinCoverage = 0.2;
constexpr int kGreenMargin = 8; // levels

struct Png {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

bool read_png(const char* path, Png* out) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path)) {
        std::fprintf(stderr, "cannot read %s: %s\n", path, png.message);
        return false;
    }
    png.format = PNG_FORMAT_RGBA;
    out->rgba.resize(PNG_IMAGE_SIZE(png));
    out->width = png.width;
    out->height = png.height;
    if (!png_image_finish_read(&png, nullptr, out->rgba.data(), 0, nullptr)) {
        std::fprintf(stderr, "cannot decode %s: %s\n", path, png.message);
        return false;
    }
    return true;
}

// The fraction of grass pixels: green well above red and blue (the sky is blue, the host's
// ground a dark olive with red and green alike).
double coverage(const Png& p) {
    size_t grass = 0;
    for (size_t i = 0; i < p.rgba.size(); i += 4) {
        const int r = p.rgba[i], g = p.rgba[i + 1], b = p.rgba[i + 2];
        grass += g > r + kGreenMargin && g > b + kGreenMargin ? 1 : 0;
    }
    return double(grass) / double(p.rgba.size() / 4);
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 4 || (std::string(argv[3]) != "same" && std::string(argv[3]) != "different")) {
        std::fprintf(stderr, "usage: grass_viewer_compare WINDOW.png HEADLESS.png same|different\n");
        return 2;
    }
    Png a, b;
    if (!read_png(argv[1], &a) || !read_png(argv[2], &b)) return 1;
    if (a.width != b.width || a.height != b.height) {
        std::fprintf(stderr, "the sizes differ: %ux%u and %ux%u\n", a.width, a.height, b.width, b.height);
        return 1;
    }
    const double cover_a = coverage(a), cover_b = coverage(b);
    size_t differing = 0, max_level = 0;
    double sum = 0.0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) {
            const size_t d = size_t(std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
            sum += double(d);
            max_level = d > max_level ? d : max_level;
            differs = differs || d > size_t(kLevelTolerance);
        }
        differing += differs ? 1 : 0;
    }
    const size_t pixels = a.rgba.size() / 4;
    const double differing_fraction = double(differing) / double(pixels);
    const double mean = sum / double(pixels * 3);
    const double psnr = grass_bench::psnr_rgba(a.rgba.data(), b.rgba.data(), a.width, a.height);
    const double ssim = grass_bench::ssim_rgba(a.rgba.data(), b.rgba.data(), a.width, a.height);
    std::printf("grass coverage %.3f and %.3f; pixels off by more than %d levels: %.4f; mean difference %.3f "
                "levels, largest %zu; PSNR %.1f dB; SSIM %.4f\n",
                cover_a, cover_b, kLevelTolerance, differing_fraction, mean, max_level, psnr, ssim);
    if (cover_a < kMinCoverage || cover_b < kMinCoverage) {
        std::fprintf(stderr, "FAIL: under %.0f%% of an image is grass: nothing drawn?\n", kMinCoverage * 100);
        return 1;
    }
    const bool same = differing_fraction <= kMaxDifferingPixels && mean <= kMeanTolerance;
    const bool want_same = std::string(argv[3]) == "same";
    if (same != want_same) {
        std::fprintf(stderr,
                     "FAIL: the images %s, expected %s (tolerance: at most %.1f%% of the pixels off by more "
                     "than %d levels, mean under %.2f levels)\n",
                     same ? "match" : "differ", want_same ? "a match" : "a difference", kMaxDifferingPixels * 100,
                     kLevelTolerance, kMeanTolerance);
        return 1;
    }
    std::printf("ok: the images %s as expected\n", same ? "match" : "differ");
    return 0;
}
