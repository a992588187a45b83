#include "image_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grass_bench {

std::vector<double> luma(const uint8_t* rgba, uint32_t width, uint32_t height) {
    const size_t n = size_t(width) * height;
    std::vector<double> y(n);
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = rgba + 4 * i;
        y[i] = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    }
    return y;
}

namespace {

// One pass of a separable filter, "valid" only: out has (w - n + 1) columns (horizontal) or
// (h - n + 1) rows (vertical).
void filter_rows(const std::vector<double>& in, uint32_t w, uint32_t h, const std::vector<double>& k,
                 std::vector<double>* out) {
    const uint32_t n = uint32_t(k.size()), ow = w - n + 1;
    out->assign(size_t(ow) * h, 0.0);
    for (uint32_t y = 0; y < h; ++y) {
        const double* row = &in[size_t(y) * w];
        double* o = &(*out)[size_t(y) * ow];
        for (uint32_t x = 0; x < ow; ++x) {
            double s = 0.0;
            for (uint32_t t = 0; t < n; ++t) s += k[t] * row[x + t];
            o[x] = s;
        }
    }
}

void filter_cols(const std::vector<double>& in, uint32_t w, uint32_t h, const std::vector<double>& k,
                 std::vector<double>* out) {
    const uint32_t n = uint32_t(k.size()), oh = h - n + 1;
    out->assign(size_t(w) * oh, 0.0);
    for (uint32_t y = 0; y < oh; ++y) {
        double* o = &(*out)[size_t(y) * w];
        for (uint32_t t = 0; t < n; ++t) {
            const double* row = &in[size_t(y + t) * w];
            for (uint32_t x = 0; x < w; ++x) o[x] += k[t] * row[x];
        }
    }
}

// The window-weighted mean of `v` at every valid window position.
std::vector<double> blur(const std::vector<double>& v, uint32_t w, uint32_t h, const std::vector<double>& k) {
    std::vector<double> tmp, out;
    filter_rows(v, w, h, k, &tmp);
    filter_cols(tmp, w - uint32_t(k.size()) + 1, h, k, &out);
    return out;
}

double ssim_term(double ma, double mb, double vaa, double vbb, double vab, double c1, double c2) {
    return ((2.0 * ma * mb + c1) * (2.0 * vab + c2)) / ((ma * ma + mb * mb + c1) * (vaa + vbb + c2));
}

} // namespace

double ssim(const double* a, const double* b, uint32_t width, uint32_t height, const SsimParams& p) {
    const double c1 = (p.k1 * p.range) * (p.k1 * p.range), c2 = (p.k2 * p.range) * (p.k2 * p.range);
    const size_t n = size_t(width) * height;
    if (n == 0) return 1.0;
    const uint32_t win = uint32_t(std::max(1, p.window));
    if (width < win || height < win) {
        // One window over the whole image, uniform weights.
        double ma = 0, mb = 0;
        for (size_t i = 0; i < n; ++i) ma += a[i], mb += b[i];
        ma /= double(n);
        mb /= double(n);
        double vaa = 0, vbb = 0, vab = 0;
        for (size_t i = 0; i < n; ++i) {
            vaa += (a[i] - ma) * (a[i] - ma);
            vbb += (b[i] - mb) * (b[i] - mb);
            vab += (a[i] - ma) * (b[i] - mb);
        }
        return ssim_term(ma, mb, vaa / double(n), vbb / double(n), vab / double(n), c1, c2);
    }
    // Normalised 1D Gaussian; the 2D window is its outer product (as fspecial('gaussian')).
    std::vector<double> k(win);
    double sum = 0.0;
    for (uint32_t t = 0; t < win; ++t) {
        const double x = double(t) - 0.5 * double(win - 1);
        k[t] = std::exp(-x * x / (2.0 * p.sigma * p.sigma));
        sum += k[t];
    }
    for (double& v : k) v /= sum;
    const std::vector<double> va(a, a + n), vb(b, b + n);
    std::vector<double> aa(n), bb(n), ab(n);
    for (size_t i = 0; i < n; ++i) {
        aa[i] = a[i] * a[i];
        bb[i] = b[i] * b[i];
        ab[i] = a[i] * b[i];
    }
    const std::vector<double> mu_a = blur(va, width, height, k), mu_b = blur(vb, width, height, k);
    const std::vector<double> e_aa = blur(aa, width, height, k), e_bb = blur(bb, width, height, k),
                              e_ab = blur(ab, width, height, k);
    double total = 0.0;
    for (size_t i = 0; i < mu_a.size(); ++i) {
        const double ma = mu_a[i], mb = mu_b[i];
        total += ssim_term(ma, mb, e_aa[i] - ma * ma, e_bb[i] - mb * mb, e_ab[i] - ma * mb, c1, c2);
    }
    return total / double(mu_a.size());
}

double ssim_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height) {
    const std::vector<double> ya = luma(a, width, height), yb = luma(b, width, height);
    return ssim(ya.data(), yb.data(), width, height);
}

double psnr_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height) {
    const size_t n = size_t(width) * height;
    double se = 0.0;
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = double(a[4 * i + c]) - double(b[4 * i + c]);
            se += d * d;
        }
    }
    if (se == 0.0 || n == 0) return std::numeric_limits<double>::infinity();
    const double mse = se / double(3 * n);
    return 10.0 * std::log10(255.0 * 255.0 / mse);
}

double srgb_to_linear(double encoded) {
    const double c = encoded / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

uint8_t linear_to_srgb8(double linear) {
    const double l = std::clamp(linear, 0.0, 1.0);
    const double c = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
    return uint8_t(std::lround(c * 255.0));
}

std::vector<uint8_t> downsample_rgba(const uint8_t* rgba, uint32_t width, uint32_t height, uint32_t factor,
                                     uint32_t* out_width, uint32_t* out_height) {
    const uint32_t f = std::max(1u, factor), ow = width / f, oh = height / f;
    *out_width = ow;
    *out_height = oh;
    std::vector<uint8_t> out(size_t(ow) * oh * 4);
    double decode[256];
    for (int v = 0; v < 256; ++v) decode[v] = srgb_to_linear(v);
    for (uint32_t y = 0; y < oh; ++y) {
        for (uint32_t x = 0; x < ow; ++x) {
            double sum[4] = {0, 0, 0, 0};
            for (uint32_t j = 0; j < f; ++j) {
                const uint8_t* p = rgba + 4 * (size_t(y * f + j) * width + size_t(x) * f);
                for (uint32_t i = 0; i < f; ++i, p += 4) {
                    for (int c = 0; c < 3; ++c) sum[c] += decode[p[c]];
                    sum[3] += p[3];
                }
            }
            const double n = double(f) * f;
            uint8_t* o = &out[4 * (size_t(y) * ow + x)];
            for (int c = 0; c < 3; ++c) o[c] = linear_to_srgb8(sum[c] / n);
            o[3] = uint8_t(std::lround(sum[3] / n));
        }
    }
    return out;
}

double rms_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height) {
    const size_t n = size_t(width) * height;
    if (n == 0) return 0.0;
    double se = 0.0;
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = double(a[4 * i + c]) - double(b[4 * i + c]);
            se += d * d;
        }
    }
    return std::sqrt(se / double(3 * n));
}

std::vector<RowBand> row_bands(const uint8_t* rgba, uint32_t width, uint32_t height, uint32_t count) {
    std::vector<RowBand> bands;
    if (count == 0 || height < count || width == 0) return bands;
    const uint32_t step = height / count;
    for (uint32_t k = 0; k < count; ++k) {
        RowBand b;
        b.y0 = k * step;
        b.y1 = k + 1 == count ? height : (k + 1) * step;
        double sum[3] = {0, 0, 0};
        size_t grass = 0;
        for (uint32_t y = b.y0; y < b.y1; ++y) {
            const uint8_t* p = rgba + 4 * size_t(y) * width;
            for (uint32_t x = 0; x < width; ++x, p += 4) {
                for (int c = 0; c < 3; ++c) sum[c] += p[c];
                grass += is_grass(p);
            }
        }
        const double n = double(b.y1 - b.y0) * width;
        for (int c = 0; c < 3; ++c) b.mean[c] = sum[c] / n;
        b.coverage = double(grass) / n;
        bands.push_back(b);
    }
    return bands;
}

std::vector<uint8_t> difference_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height, double gain) {
    const size_t n = size_t(width) * height;
    std::vector<uint8_t> out(4 * n);
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = std::fabs(double(a[4 * i + c]) - double(b[4 * i + c])) * gain;
            out[4 * i + c] = uint8_t(std::min(255.0, std::round(d)));
        }
        out[4 * i + 3] = 255;
    }
    return out;
}

} // namespace grass_bench
