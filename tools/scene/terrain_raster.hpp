// A terrain mesh rasterised over a grid of map texels, seen from above (along -y): for each
// texel centre the height of the highest triangle over it and two attributes interpolated
// on that triangle (a density, or a texture coordinate). Plain CPU rasterisation with edge
// functions over each triangle's bounding box of texels.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace grass_sample {

struct TerrainVertex {
    double x = 0.0, y = 0.0, z = 0.0; // world, metres (y up)
    float a[2] = {0.0f, 0.0f};        // attributes interpolated across the triangle
};

struct TerrainRaster {
    uint32_t width = 0, height = 0; // texels along x, rows along z
    std::vector<double> y;          // per texel; NaN where no triangle covers its centre
    std::vector<float> a[2];        // per texel, of the highest triangle
    bool covered(size_t texel) const { return y[texel] == y[texel]; }
};

// Rasterises triangles (three vertices each) over the rectangle [x0, x0 + size_x] x
// [z0, z0 + size_z] split into width x height texels; texel (i, j) is sampled at its centre
// (x0 + (i + 0.5) size_x / width, z0 + (j + 0.5) size_z / height). Triangles seen edge-on
// from above cover nothing.
TerrainRaster rasterise_terrain(const std::vector<TerrainVertex>& triangles, double x0, double z0, double size_x,
                                double size_z, uint32_t width, uint32_t height);

// Heights of the texels no triangle covers, from their covered neighbours (the mean of the
// eight around them; NaN when none), so bilinear sampling at the terrain's edge stays on it.
void fill_uncovered_heights(const TerrainRaster& raster, std::vector<double>* heights);

} // namespace grass_sample
