"""Planning only: a CPU context (no GPU) shows what a camera would draw, with stats.

    ~/grass-venv/bin/python integration/python/examples/plan_only.py    # installed as docs/python.md says
"""
import grass

with grass.Context() as ctx:
    patch = ctx.create_patch()                                   # the default grass type
    field = ctx.create_field(patch, cells_x=400, cells_z=300)    # 100 m x 75 m of 0.25 m cells
    for height in (1.7, 10.0, 60.0):
        view = grass.view_desc(eye=(50.0, height, 10.0), target=(50.0, 0.0, 45.0), size=(1280, 720))
        with ctx.frame(view):
            pass                                                 # a GL or Vulkan context would draw here
        s = ctx.frame_stats()
        print(f"camera at {height:5.1f} m: {s.cells_drawn} cells of blades, {s.blades_drawn} blades, "
              f"{s.triangles} triangles; instances per tier kind (geometry, volume, image) {list(s.instances)}; "
              f"{s.draws} draws; plan {s.plan_ms:.2f} ms")
