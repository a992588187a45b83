"""Painting a density map from numpy: a mown path and a bare circle, planned and rendered.

    ~/grass-venv/bin/python integration/python/examples/paint_density.py [out.png]    # installed as docs/python.md says
"""
import sys

import numpy as np

import grass
import grass.headless

out = sys.argv[1] if len(sys.argv) > 1 else "grass-density.png"
width, height = 480, 270
size = 128                                                        # map texels over the field
v, u = np.mgrid[0:size, 0:size] / (size - 1)                      # rows run along field +z
density = np.ones((size, size), np.float32)
density[np.abs(u - 0.5) < 0.06] = 0.15                            # a mown path along z
density[(u - 0.25) ** 2 + (v - 0.45) ** 2 < 0.12 ** 2] = 0.0      # a bare circle

with grass.headless.Target(width, height) as target:
    with grass.Context.gl(target.get_proc_address) as ctx:
        patch = ctx.create_patch()
        view = grass.view_desc(eye=(8.0, 2.5, 1.0), target=(8.0, 0.0, 7.0), size=(width, height))
        with ctx.create_map(np.ones((size, size), np.float32)) as density_map:
            field = ctx.create_field(patch, cells_x=64, cells_z=64, maps={"density": density_map})
            with ctx.frame(view):
                pass
            before = ctx.frame_stats().blades_drawn
            density_map.update(0, 0, density)                     # paint at run time
            target.clear((0.45, 0.62, 0.85))
            with ctx.frame(view):
                ctx.render_gl()
            after = ctx.frame_stats().blades_drawn
            target.write_png(out)
            field.destroy()
        print(f"wrote {out}: {before} blades before painting, {after} after")
        sys.exit(0 if 0 < after < before else 1)
