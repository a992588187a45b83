#include "terrain_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grass_sample {

TerrainRaster rasterise_terrain(const std::vector<TerrainVertex>& triangles, double x0, double z0, double size_x,
                                double size_z, uint32_t width, uint32_t height) {
    TerrainRaster r;
    r.width = width;
    r.height = height;
    const size_t n = size_t(width) * height;
    r.y.assign(n, std::numeric_limits<double>::quiet_NaN());
    r.a[0].assign(n, 0.0f);
    r.a[1].assign(n, 0.0f);
    const double tx = size_x / width, tz = size_z / height; // texel size
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const TerrainVertex& p0 = triangles[t];
        const TerrainVertex& p1 = triangles[t + 1];
        const TerrainVertex& p2 = triangles[t + 2];
        // Texel coordinates: texel i's centre is at u = i + 0.5.
        const double u0 = (p0.x - x0) / tx, v0 = (p0.z - z0) / tz;
        const double u1 = (p1.x - x0) / tx, v1 = (p1.z - z0) / tz;
        const double u2 = (p2.x - x0) / tx, v2 = (p2.z - z0) / tz;
        const double area = (u1 - u0) * (v2 - v0) - (u2 - u0) * (v1 - v0);
        if (std::fabs(area) < 1e-12) continue; // edge-on from above
        const double lo_u = std::min({u0, u1, u2}), hi_u = std::max({u0, u1, u2});
        const double lo_v = std::min({v0, v1, v2}), hi_v = std::max({v0, v1, v2});
        const long i0 = std::max(0L, long(std::ceil(lo_u - 0.5))), i1 = std::min(long(width) - 1, long(hi_u - 0.5));
        const long j0 = std::max(0L, long(std::ceil(lo_v - 0.5))), j1 = std::min(long(height) - 1, long(hi_v - 0.5));
        const double eps = 1e-9 * std::fabs(area); // shared edges cover their texels from both sides
        for (long j = j0; j <= j1; ++j) {
            const double v = j + 0.5;
            for (long i = i0; i <= i1; ++i) {
                const double u = i + 0.5;
                // Barycentric weights from edge functions, signed like the area.
                const double w0 = ((u1 - u) * (v2 - v) - (u2 - u) * (v1 - v)) / area;
                const double w1 = ((u2 - u) * (v0 - v) - (u0 - u) * (v2 - v)) / area;
                const double w2 = 1.0 - w0 - w1;
                if (w0 < -eps || w1 < -eps || w2 < -eps) continue;
                const double y = w0 * p0.y + w1 * p1.y + w2 * p2.y;
                const size_t texel = size_t(j) * width + size_t(i);
                if (r.covered(texel) && r.y[texel] >= y) continue;
                r.y[texel] = y;
                for (int k = 0; k < 2; ++k) r.a[k][texel] = float(w0 * p0.a[k] + w1 * p1.a[k] + w2 * p2.a[k]);
            }
        }
    }
    return r;
}

void fill_uncovered_heights(const TerrainRaster& raster, std::vector<double>* heights) {
    const long w = long(raster.width), h = long(raster.height);
    heights->assign(raster.y.size(), 0.0);
    for (long j = 0; j < h; ++j) {
        for (long i = 0; i < w; ++i) {
            const size_t texel = size_t(j * w + i);
            if (raster.covered(texel)) {
                (*heights)[texel] = raster.y[texel];
                continue;
            }
            double sum = 0.0;
            int count = 0;
            for (long dj = -1; dj <= 1; ++dj) {
                for (long di = -1; di <= 1; ++di) {
                    const long x = i + di, z = j + dj;
                    if (x < 0 || z < 0 || x >= w || z >= h) continue;
                    const size_t near = size_t(z * w + x);
                    if (raster.covered(near)) sum += raster.y[near], ++count;
                }
            }
            (*heights)[texel] = count ? sum / count : std::numeric_limits<double>::quiet_NaN();
        }
    }
}

} // namespace grass_sample
