"""A headless render to PNG: GL 4.5 through EGL surfaceless (Mesa), an sRGB target.

    ~/grass-venv/bin/python integration/python/examples/render_png.py [out.png]    # installed as docs/python.md says
"""
import sys

import grass
import grass.headless

out = sys.argv[1] if len(sys.argv) > 1 else "grass-python.png"
width, height = 480, 270
with grass.headless.Target(width, height) as target:                 # current GL context, bound FBO
    with grass.Context.gl(target.get_proc_address) as ctx:
        patch = ctx.create_patch()
        ctx.create_field(patch, cells_x=64, cells_z=64)              # 16 m x 16 m
        view = grass.view_desc(eye=(8.0, 1.6, -1.0), target=(8.0, 0.0, 8.0), size=(width, height))
        target.clear((0.45, 0.62, 0.85))                             # sky colour and depth 1
        with ctx.frame(view):
            ctx.render_gl()
        rgba = target.write_png(out)
        green = grass.headless.green_fraction(rgba)
        print(f"wrote {out}: {green:.0%} of the pixels are grass, {ctx.frame_stats().blades_drawn} blades")
        sys.exit(0 if green > 0.1 else 1)
