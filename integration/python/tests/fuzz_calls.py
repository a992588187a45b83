"""Random call sequences on the Pythonic layer (run by test_fuzz.py in a fresh interpreter
under faulthandler): random types, shapes, sizes and orders of calls, good values mixed
with bad ones. Every call must succeed or raise a GrassError; any other exception fails the
run (exit 1, printing the seed and the calls), a signal kills it (faulthandler prints where).

    python3 fuzz_calls.py FIRST COUNT [--gl]

runs the sequences seeded FIRST .. FIRST+COUNT-1; --gl makes one headless GL target and
gives every sequence a GL context too (rendering with render_gl) besides the CPU ones."""
import atexit
import collections
import faulthandler
import math
import os
import random
import shutil
import sys
import tempfile
import traceback

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import grass  # noqa: E402

try:
    import numpy as np
except ImportError:  # the fuzz then uses bytes-like pixels only
    np = None

faulthandler.enable()
STATS = collections.defaultdict(lambda: [0, 0])  # op -> [succeeded, refused with a GrassError]
CACHE = tempfile.mkdtemp(prefix="grass-fuzz-")  # a cache_directory some contexts get
atexit.register(shutil.rmtree, CACHE, True)


class Sequence:
    def __init__(self, seed, target, shared):
        self.r = random.Random(seed)
        self.target = target
        self.shared = shared  # [a GL context kept across sequences] (making one compiles shaders)
        self.contexts, self.objects, self.log = [], [], []

    # ---- values: mostly sensible, often not
    def junk(self):
        r = self.r
        return r.choice([None, -5, -1, 0, 1, 3, 2 ** 31, 2 ** 32, 2 ** 40, -2 ** 63, 2 ** 64, 1.5, -0.0, math.nan,
                         math.inf, -math.inf, 1e39, "x", "", b"xyz", bytearray(3), [], [1, 2], (1, 2, 3), {}, object(),
                         True, 3 + 4j, self.any_object(), grass.grass_view_desc(), grass.grass_patch_desc(),
                         grass.grass_tier_desc(), grass.grass_patch_id(), lambda *a: None])

    def any_object(self):
        return self.r.choice(self.objects + self.contexts) if self.objects or self.contexts else None

    def integer(self, low, high):
        return self.r.randint(low, high) if self.r.random() < 0.92 else self.junk()

    def real(self, low, high):
        return self.r.uniform(low, high) if self.r.random() < 0.92 else self.junk()

    def vec(self, n, low, high):
        if self.r.random() < 0.85:
            return tuple(self.r.uniform(low, high) for _ in range(n))
        return self.r.choice([self.junk(), tuple(self.junk() for _ in range(n)), (0.0,) * (n + 1), (1.0,) * n])

    def pixels(self):
        r = self.r
        kind = r.random()
        if kind < 0.35 and np is not None:
            dtype = r.choice(["uint8"] * 4 + ["uint16", "float32", "float32", "int64", "bool", "float64", ">u2"])
            shape = r.choice([(r.randint(0, 24), r.randint(0, 24))] * 4 + [(r.randint(1, 16), r.randint(1, 16), 4),
                              (r.randint(1, 8), r.randint(1, 8), r.randint(1, 5)), (r.randint(0, 40),),
                              (2, 2, 2, 2), ()])
            a = (np.random.default_rng(r.randrange(2 ** 32)).random(shape) * r.choice([1.0, 1.0, 300.0, 70000.0]))
            a = a.astype(dtype)
            if r.random() < 0.3 and a.ndim >= 2:
                a = r.choice([a[::2], a[:, ::2], a.T, a[::-1]])
            return a, {}
        w, h = r.choice([(r.randint(1, 20), r.randint(1, 20))] * 4 + [(4096, 4096), (r.randint(-3, 3), 2)])
        fmt = r.choice([None] * 6 + [grass.GRASS_MAP_FORMAT_R8_UNORM, grass.GRASS_MAP_FORMAT_RGBA16_UNORM,
                        grass.GRASS_MAP_FORMAT_R32_FLOAT, 0, 99, self.junk()])
        size = {1: 1, 2: 8, 3: 4}.get(fmt, 1) if isinstance(fmt, (int, type(None))) else 1
        n = max(0, w * h * size) if isinstance(w, int) and abs(w) < 100 else r.randint(0, 64)
        n = r.choice([n] * 6 + [n - 1, n + 1, r.randint(0, 64)])
        data = bytes(r.getrandbits(8) for _ in range(max(0, min(n, 20000))))
        wrap = r.choice([bytes, bytes, bytearray, memoryview, lambda d: memoryview(bytearray(d * 2))[::2], str, lambda d: None])
        kw = {}
        if r.random() < 0.97:
            kw.update(width=w, height=h)
        if fmt is not None:
            kw["format"] = fmt
        if r.random() < 0.2:
            kw["row_pitch"] = self.integer(0, 64)
        if r.random() < 0.05:
            kw[r.choice(["depth", "pitch"])] = 1
        try:
            value = wrap(data)
        except (TypeError, ValueError):
            value = data
        return value, kw

    def fields(self, struct):
        names = [f[0] for f in struct._fields_] + ["blade_cuont", "type", "next"]
        out = {}
        for _ in range(self.r.choice([0, 0, 0, 1, 1, 2, 3])):
            name = self.r.choice(names)
            ctype = dict(struct._fields_).get(name)
            length = getattr(ctype, "_length_", None)
            if length and self.r.random() < 0.7:
                out[name] = [self.r.uniform(-2, 2) for _ in range(length)]
            elif self.r.random() < 0.75:
                out[name] = self.r.choice([self.r.randint(0, 64), self.r.uniform(0, 2), 1, 0])
            else:
                out[name] = self.junk()
        return out

    def view(self):
        r = self.r
        if r.random() < 0.1:
            return self.junk()
        kw = dict(eye=self.vec(3, -4, 20), target=self.vec(3, -4, 20), size=r.choice([(64, 48), (32, 32), (0, 0),
                                                                                      (r.randint(-2, 9), 3), None]))
        if r.random() < 0.2:
            kw[r.choice(["fovy", "near", "far", "up"])] = r.choice([self.junk(), 0.5, 2.0, (0, 0, 1)])
        if r.random() < 0.1:
            kw.update(self.fields(grass.grass_view_desc))
        if r.random() < 0.1:
            kw.update(eye=(4.0, 2.0, 4.0), target=(4.0, 2.0, 4.0))
        return grass.view_desc(**kw)

    def callback(self):
        r = self.r
        choice = r.random()
        ctx = self.context()
        if choice < 0.6:
            return lambda node: r.choice([grass.GRASS_LOD_DRAW, grass.GRASS_LOD_SPLIT, grass.GRASS_LOD_DISCARD])
        if choice < 0.7:
            return lambda node: 1 / 0
        if choice < 0.8:
            return lambda node: self.junk()
        if choice < 0.9 and ctx is not None:
            return lambda node: ctx.create_patch(blade_count=4) and grass.GRASS_LOD_DRAW
        return lambda node: ctx.destroy() if ctx is not None else 0

    def context(self):
        return self.r.choice(self.contexts) if self.contexts else None

    def pick(self, cls, junk=True):
        """An object of `cls` made so far (any state), or (as an argument) sometimes junk."""
        items = [o for o in self.objects if isinstance(o, cls)]
        if items and (not junk or self.r.random() < 0.92):
            return self.r.choice(items)
        return self.junk() if junk else None

    # ---- calls
    def op_context(self):
        r = self.r
        kw = {}
        if r.random() < 0.3:
            kw["log"] = r.choice([None, lambda *a: None, lambda *a: 1 / 0, self.junk(),
                                  lambda *a: self.context() and self.context().create_patch()])
        if r.random() < 0.2:
            kw["log_level"] = self.integer(0, 2)
        if r.random() < 0.1:
            kw["depth_mode"] = self.integer(0, 1)
        if r.random() < 0.1:
            kw["cache_directory"] = r.choice([CACHE, 5, "a\0b", b"/nonexistent/\xff"])
        if self.target is not None and r.random() < 0.6:
            if self.shared[0] is None or self.shared[0].handle is None or r.random() < 0.05:
                loader = r.choice([self.target.get_proc_address] * 2 + [None, lambda name: 1 / 0,
                                                                        lambda name: "glFoo", lambda name: None])
                self.shared[0] = grass.Context.gl(loader)
            self.contexts.append(self.shared[0])
        else:
            self.contexts.append(grass.Context(**kw))

    def op_patch(self):
        ctx = self.context() or grass.Context()
        if self.r.random() < 0.2:
            made = ctx.create_patch(self.r.choice([grass.patch_desc(blade_count=self.r.randint(1, 300)),
                                                   self.junk()]))
        else:
            fields = self.fields(grass.grass_patch_desc)
            fields.setdefault("blade_count", self.integer(1, 300))
            made = ctx.create_patch(**fields)
        self.objects.append(made)

    def op_map(self):
        ctx = self.context() or grass.Context()
        pixels, kw = self.pixels()
        self.objects.append(ctx.create_map(pixels, **kw))

    def op_update(self):
        m = self.pick(grass.Map, junk=False)
        if m is None:
            return
        pixels, kw = self.pixels()
        m.update(self.integer(0, 20), self.integer(0, 20), pixels, **kw)

    def op_field(self):
        r = self.r
        if not any(isinstance(o, grass.Patch) for o in self.objects):
            self.op_patch()
        patch = self.pick(grass.Patch)
        ctx = patch.context if isinstance(patch, grass.Patch) and r.random() < 0.9 else self.context() or grass.Context()
        kw = dict(patch=patch, cells_x=self.integer(1, 48), cells_z=self.integer(1, 48))
        if r.random() < 0.2:
            kw["density_map"] = self.pixels()[0]
        if r.random() < 0.2:
            kw["maps"] = r.choice([{r.choice(["density", "color", "height", "hue"]): self.pick(grass.Map)},
                                   {"height_scale": self.real(0, 4)}, self.junk()])
        if r.random() < 0.15:
            kw["tiers"] = r.choice([[grass.tier_desc(self.integer(0, 2), slices=self.integer(0, 8))
                                     for _ in range(r.randint(0, 3))], self.junk(), [self.junk()]])
        if r.random() < 0.15:
            kw["lod_tests"] = r.choice([[grass.lod_test(self.callback(), tier=self.integer(0, 2))],
                                        [grass.grass_lod_test(kind=r.randint(0, 5), tier=r.randint(0, 3),  # raw
                                                              begin=r.uniform(0, 10), end=r.uniform(0, 50))],
                                        self.junk()])
        if r.random() < 0.1:
            kw["desc"] = r.choice([grass.field_desc(), self.junk()])
        kw.update(self.fields(grass.grass_field_desc) if r.random() < 0.15 else {})
        self.objects.append(ctx.create_field(**kw))

    def op_frame(self):
        gl = [c for c in self.contexts if c is self.shared[0]]
        ctx = gl[0] if gl and self.r.random() < 0.7 else self.context() or grass.Context()
        view = self.view()
        with ctx.frame(view):
            if self.r.random() < 0.5:
                ctx.render_gl()
            if self.r.random() < 0.1:
                self.step()

    def op_begin(self):
        (self.context() or grass.Context()).begin_frame(self.view())

    def op_end(self):
        (self.context() or grass.Context()).end_frame()

    def op_render(self):
        gl = [c for c in self.contexts if c is self.shared[0]]
        (gl[0] if gl and self.r.random() < 0.8 else self.context() or grass.Context()).render_gl()

    def op_vk(self):
        ctx = self.context() or grass.Context()
        getattr(ctx, self.r.choice(["vk_record", "vk_prepare"]))(self.integer(0, 2 ** 20))

    def op_stats(self):
        ctx = self.context() or grass.Context()
        self.r.choice([ctx.frame_stats, ctx.memory_stats, ctx.tier_gpu_ms, lambda: ctx.backend,
                       lambda: ctx.last_error])()

    def op_info(self):
        p = self.pick(grass.Patch, junk=False)
        if p is None:
            return
        self.r.choice([p.info, p.thresholds])()

    def op_quality(self):
        ctx = self.context() or grass.Context()
        quality = self.r.choice([self.integer(0, 4), grass.quality_preset(self.r.randint(0, 4)), self.junk()])
        patch, tiers, tests = ctx.apply_quality(quality, self.real(0.05, 2),
                                                self.r.choice([None, None, grass.patch_desc(), self.junk()]))
        if self.r.random() < 0.5:
            self.objects.append(ctx.create_field(ctx.create_patch(patch), cells_x=16, cells_z=16, tiers=tiers,
                                                 lod_tests=tests))

    def op_destroy(self):
        pool = self.contexts if self.r.random() < 0.15 or not self.objects else self.objects
        target = self.r.choice(pool) if pool else None
        if target is not None:
            target.destroy()

    def op_helpers(self):
        r = self.r
        r.choice([lambda: grass.patch_desc(**self.fields(grass.grass_patch_desc)),
                  lambda: grass.field_desc(**self.fields(grass.grass_field_desc)),
                  lambda: grass.quality_preset(self.integer(0, 4)),
                  lambda: grass.look_at(self.vec(3, -1, 1), self.vec(3, -1, 1), self.vec(3, -1, 1)),
                  lambda: grass.perspective(self.real(0, 3), self.real(0, 2), self.real(0, 1), self.real(0, 100)),
                  lambda: grass.map_desc(self.pixels()[0], **{k: v for k, v in self.pixels()[1].items()
                                                              if k in ("width", "height", "format", "row_pitch")}),
                  lambda: grass.lod_test(r.choice([self.callback(), self.junk()]), tier=self.integer(0, 3))])()

    def step(self):
        ops = [self.op_context, self.op_patch, self.op_patch, self.op_map, self.op_update, self.op_field,
               self.op_field, self.op_frame, self.op_frame, self.op_begin, self.op_end, self.op_render, self.op_vk,
               self.op_stats, self.op_info, self.op_quality, self.op_destroy, self.op_helpers]
        op = self.r.choice(ops)
        self.log.append(op.__name__)
        try:
            op()
            STATS[op.__name__][0] += 1
        except grass.GrassError:
            STATS[op.__name__][1] += 1

    def run(self):
        try:
            self.op_context()
        except grass.GrassError:
            pass
        for _ in range(self.r.randint(2, 14)):
            self.step()
        for thing in sorted(self.objects, key=lambda o: not isinstance(o, grass.Field)) + self.contexts:
            if thing is self.shared[0]:
                continue
            try:
                thing.destroy()
            except grass.GrassError:
                pass


def main():
    first, count = int(sys.argv[1]), int(sys.argv[2])
    target, shared = None, [None]
    if "--gl" in sys.argv:
        import grass.headless
        target = grass.headless.Target(64, 48)
    for seed in range(first, first + count):
        sequence = Sequence(seed, target, shared)
        try:
            sequence.run()
        except Exception:
            print(f"seed {seed}: a call raised something else than a GrassError after {sequence.log}")
            traceback.print_exc()
            sys.exit(1)
    calls = sum(a + b for a, b in STATS.values())
    print(f"ok: {count} sequences from seed {first}{' with GL' if target else ''}, {calls} calls; succeeded/refused: "
          + ", ".join(f"{name[3:]} {a}/{b}" for name, (a, b) in sorted(STATS.items())))


if __name__ == "__main__":
    main()
