// What a GrassField hands its renderer at each sync: the field's settings (compared by
// value: a change rebuilds the field) and the frame's camera and viewport.
#pragma once

#include <grass/grass.h>

#include <QImage>
#include <QSizeF>
#include <QVector3D>

namespace grass_qt {

struct FieldSettings {
    QVector3D position;
    QSizeF extent;
    double cell_size = 25.0;
    double density = 1.0;
    int quality = GRASS_QUALITY_DEFAULT;
    QImage density_map; // Grayscale8, or null
    QImage color_map;   // RGBA8888, or null
};

// The frame as the renderer needs it; valid is false when there is no usable camera or view.
struct FrameInput {
    bool valid = false;
    grass_view_desc view = grass_default_view_desc();
};

} // namespace grass_qt
