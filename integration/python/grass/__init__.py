"""grass from Python: a thin ctypes binding of the C API (grass.h, grass_gl.h, grass_vk.h).

    import grass
    with grass.Context() as ctx:                      # a CPU context: plans, draws nothing
        patch = ctx.create_patch()
        field = ctx.create_field(patch, cells_x=400, cells_z=300)
        view = grass.view_desc(eye=(50, 1.7, -5), target=(50, 0, 40), size=(640, 360))
        with ctx.frame(view):
            pass                                      # GL: ctx.render_gl(); Vulkan: ctx.vk_record(cmd)
        print(ctx.frame_stats().blades_drawn)

Every call that fails raises GrassError(result, message_id, message). Objects (Context,
Patch, Field, Map) are context managers and have destroy(). The raw C functions are
grass.lib.<name>, the C structs and constants grass.<c name> (from grass._ffi).
"""
import contextlib
import ctypes
from enum import IntEnum

from . import _ffi
from ._ffi import *  # noqa: F401,F403 - the C structs, enums and constants under their C names
from .camera import look_at, perspective

__all__ = ["lib", "GrassError", "Result", "MessageId", "Context", "Patch", "Field", "Map", "patch_desc",
           "field_desc", "view_desc", "quality_preset", "look_at", "perspective"] + \
    [n for n in dir(_ffi) if n.startswith(("grass_", "GRASS_"))]

lib = _ffi.load_library()
Result = IntEnum("Result", _ffi.ENUMS["grass_result"])
MessageId = IntEnum("MessageId", _ffi.ENUMS["grass_message_id"])


class GrassError(Exception):
    """A grass call that did not return GRASS_SUCCESS: result (Result), message_id (MessageId
    of the last error the context logged, GRASS_MSG_NONE when unknown) and message."""

    def __init__(self, result, message_id=0, message=""):
        self.result = Result(result)
        try:
            self.message_id = MessageId(message_id)
        except ValueError:
            self.message_id = message_id
        self.message = message
        super().__init__(f"{self.result.name} ({getattr(self.message_id, 'name', message_id)}): {message}")


def _fill(struct, fields):
    """Sets struct fields from keyword arguments; sequences fill arrays."""
    for name, value in fields.items():
        if not any(name == f[0] for f in struct._fields_):
            raise AttributeError(f"{type(struct).__name__} has no field {name!r}")
        current = getattr(struct, name)
        if isinstance(current, ctypes.Array):
            if len(value) != len(current):
                raise ValueError(f"{type(struct).__name__}.{name} takes {len(current)} values, got {len(value)}")
            current[:] = list(value)
        elif isinstance(value, str):
            setattr(struct, name, value.encode())
        else:
            setattr(struct, name, value)
    return struct


def patch_desc(**fields):
    """grass_default_patch_desc() with `fields` changed."""
    return _fill(lib.grass_default_patch_desc(), fields)


def field_desc(**fields):
    """grass_default_field_desc() with `fields` changed."""
    return _fill(lib.grass_default_field_desc(), fields)


def quality_preset(level):
    """grass_quality_preset(level): the knobs of a quality preset."""
    return lib.grass_quality_preset(level)


def view_desc(eye=None, target=None, size=None, fovy=0.9, near=0.05, far=1000.0, clip_z_zero_to_one=False,
              **fields):
    """grass_default_view_desc() with the camera set: at `eye` looking at `target` (world
    metres, y up), a perspective of `fovy` radians for a viewport of size = (width, height)
    at (0, 0). GL clip z is -1..1; pass clip_z_zero_to_one=True (and flip y yourself) for
    Vulkan. Then `fields` (e.g. flags=GRASS_VIEW_FLAG_DEBUG_TIERS) are set."""
    view = lib.grass_default_view_desc()
    if eye is not None:
        view.camera_position[:] = list(eye)
        view.view[:] = look_at(eye, target)
    if size is not None:
        view.viewport[:] = [0, 0, int(size[0]), int(size[1])]
        view.projection[:] = perspective(fovy, size[0] / size[1], near, far, clip_z_zero_to_one)
    return _fill(view, fields)


class _Object:
    """A patch, field or map of a context: destroy() or a with block destroys it."""
    _destroy_fn = None

    def __init__(self, context, handle):
        self.context = context
        self.id = handle

    def destroy(self):
        if self.id is not None and self.context._ctx:
            self.context._check(getattr(lib, self._destroy_fn)(self.context._ctx, self.id))
        self.id = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.destroy()


class Patch(_Object):
    """A grass type (grass_patch_id)."""
    _destroy_fn = "grass_destroy_patch"

    def info(self):
        info = grass_patch_info()  # noqa: F405
        self.context._check(lib.grass_get_patch_info(self.context._ctx, self.id, ctypes.byref(info)))
        return info

    def thresholds(self):
        """The per-blade density thresholds, as a list of floats."""
        n = self.info().blade_count
        out = (ctypes.c_float * n)()
        self.context._check(lib.grass_get_patch_thresholds(self.context._ctx, self.id, out, n))
        return list(out)


class Field(_Object):
    """A field (grass_field_id). Keeps the lod test callbacks it was made with alive."""
    _destroy_fn = "grass_destroy_field"

    def destroy(self):
        super().destroy()
        self.keep = None


_NUMPY_FORMATS = {("uint8", 1): GRASS_MAP_FORMAT_R8_UNORM, ("uint16", 1): GRASS_MAP_FORMAT_R16_UNORM,  # noqa: F405
                  ("float32", 1): GRASS_MAP_FORMAT_R32_FLOAT, ("uint8", 4): GRASS_MAP_FORMAT_RGBA8_UNORM,  # noqa: F405
                  ("uint16", 4): GRASS_MAP_FORMAT_RGBA16_UNORM,  # noqa: F405
                  ("float32", 4): GRASS_MAP_FORMAT_RGBA32_FLOAT}  # noqa: F405


def map_desc(pixels, width=None, height=None, format=None, row_pitch=0):
    """A grass_map_desc for `pixels`: a numpy array of shape (height, width) for one channel
    or (height, width, 4) for RGBA, dtype uint8, uint16 or float32 (row 0 first, rows run
    along field +z); or any buffer with width, height and format given. Returns (desc,
    keep): keep the second alive until the call that takes the desc returns."""
    desc = lib.grass_default_map_desc()
    shape = getattr(pixels, "shape", None)
    if shape is not None:
        import numpy as np
        array = np.ascontiguousarray(pixels)
        channels = 1 if array.ndim == 2 else array.shape[2]
        fmt = _NUMPY_FORMATS.get((str(array.dtype), channels))
        if array.ndim not in (2, 3) or fmt is None:
            raise ValueError(f"a map is (h, w) or (h, w, 4) of uint8, uint16 or float32, not {array.shape} "
                             f"{array.dtype}")
        desc.pixels = array.ctypes.data
        desc.height, desc.width = array.shape[0], array.shape[1]
        desc.format = fmt if format is None else format
        return desc, array
    buffer = (ctypes.c_char * len(pixels)).from_buffer_copy(pixels)
    desc.pixels = ctypes.addressof(buffer)
    desc.width, desc.height = width, height
    desc.format = GRASS_MAP_FORMAT_R8_UNORM if format is None else format  # noqa: F405
    desc.row_pitch = row_pitch
    return desc, buffer


class Map(_Object):
    """A design map (grass_map_id)."""
    _destroy_fn = "grass_destroy_map"

    def update(self, x, y, pixels, **kw):
        """Replaces the texels of the rectangle at (x, y) the size of `pixels` (as map_desc)."""
        desc, keep = map_desc(pixels, **kw)
        self.context._check(lib.grass_update_map(self.context._ctx, self.id, x, y, ctypes.byref(desc)))
        del keep


class Context:
    """A grass context. Context() has no GPU backend (plans and stats only);
    Context.gl(get_proc_address) draws with the current GL context; Context.vk(vk_desc)
    records into Vulkan command buffers. `log(level, message_id, message)` receives every
    message up to `log_level`; errors also go into the GrassError raised."""

    def __init__(self, log=None, log_level=GRASS_LOG_WARNING, depth_mode=GRASS_DEPTH_LESS,  # noqa: F405
                 cache_directory=None, _create=None):
        self._ctx = None
        self._user_log = log
        self._last = (GRASS_MSG_NONE, "")  # noqa: F405
        self._log_fn = grass_log_fn(self._on_log)  # noqa: F405 - kept alive as long as the context
        desc = lib.grass_default_context_desc()
        desc.log_fn = self._log_fn
        desc.log_level = log_level
        desc.depth_mode = depth_mode
        if cache_directory is not None:
            desc.cache_directory = str(cache_directory).encode()
        out = ctypes.c_void_p()
        if _create is None:
            result = lib.grass_create_context(GRASS_HEADER_VERSION, ctypes.byref(desc), ctypes.byref(out))  # noqa
        else:
            result = _create(desc, out)
        self._check(result)
        self._ctx = out.value

    @classmethod
    def gl(cls, get_proc_address, **kw):
        """A GL context (grass_gl_create_context): the host's GL 4.5 context must be current.
        get_proc_address(name: bytes) -> int address or None, e.g. grass.headless's."""
        holder = {}

        def create(desc, out):
            gl = lib.grass_default_gl_desc()
            holder["fn"] = grass_gl_get_proc_address_fn(lambda user, name: get_proc_address(name))  # noqa: F405
            gl.get_proc_address = holder["fn"]
            return lib.grass_gl_create_context(GRASS_HEADER_VERSION, ctypes.byref(desc), ctypes.byref(gl),  # noqa
                                               ctypes.byref(out))
        self = cls(_create=create, **kw)
        self._loader = holder["fn"]  # grass loads its entry points at creation; kept alive anyway
        return self

    @classmethod
    def vk(cls, vk_desc, **kw):
        """A Vulkan context (grass_vk_create_context) from a filled grass_vk_desc."""
        return cls(_create=lambda desc, out: lib.grass_vk_create_context(
            GRASS_HEADER_VERSION, ctypes.byref(desc), ctypes.byref(vk_desc), ctypes.byref(out)), **kw)  # noqa

    def _on_log(self, user_data, level, message_id, message):
        text = message.decode(errors="replace") if message else ""
        if level == GRASS_LOG_ERROR:  # noqa: F405
            self._last = (message_id, text)
        if self._user_log:
            self._user_log(level, message_id, text)

    def _check(self, result):
        if result != GRASS_SUCCESS:  # noqa: F405
            message_id, message = self._last
            if not message and self._ctx:
                message = lib.grass_get_last_error(self._ctx).decode(errors="replace")
            self._last = (GRASS_MSG_NONE, "")  # noqa: F405
            raise GrassError(result, message_id, message)
        self._last = (GRASS_MSG_NONE, "")  # noqa: F405

    # ---- lifetime
    def destroy(self):
        """grass_destroy_context: destroys every object of the context too (GL: the GL
        context must be current)."""
        if self._ctx:
            lib.grass_destroy_context(self._ctx)
        self._ctx = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.destroy()

    def __del__(self):
        with contextlib.suppress(Exception):
            self.destroy()

    @property
    def handle(self):
        """The grass_context* as an int, for the raw functions in grass.lib."""
        return self._ctx

    @property
    def backend(self):
        return lib.grass_get_context_backend(self._ctx)

    @property
    def last_error(self):
        return lib.grass_get_last_error(self._ctx).decode(errors="replace")

    # ---- objects
    def create_patch(self, desc=None, **fields):
        """A grass type from `desc` (a grass_patch_desc) or the default desc with `fields`."""
        desc = _fill(desc if desc is not None else lib.grass_default_patch_desc(), fields)
        out = grass_patch_id()  # noqa: F405
        self._check(lib.grass_create_patch(self._ctx, ctypes.byref(desc), ctypes.byref(out)))
        return Patch(self, out)

    def create_map(self, pixels, **kw):
        """A design map from a numpy array or a buffer (see map_desc)."""
        desc, keep = map_desc(pixels, **kw)
        out = grass_map_id()  # noqa: F405
        self._check(lib.grass_create_map(self._ctx, ctypes.byref(desc), ctypes.byref(out)))
        del keep
        return Map(self, out)

    def create_field(self, patch=None, desc=None, density_map=None, maps=None, tiers=None, lod_tests=None,
                     **fields):
        """A field: `desc` (a grass_field_desc) or the default desc, with `patch` (a Patch),
        `density_map` (pixels as for create_map, copied into this field), `maps` (a dict of
        Map objects by role: density, color, ambient, diffuse, height), `tiers` and
        `lod_tests` (sequences of grass_tier_desc / grass_lod_test) and `fields` set."""
        desc = desc if desc is not None else lib.grass_default_field_desc()
        keep = []
        if patch is not None:
            desc.patch = patch.id if isinstance(patch, Patch) else patch
        if density_map is not None:
            map_d, pixels = map_desc(density_map)
            keep += [map_d, pixels]
            desc.density_map = ctypes.pointer(map_d)
        for role, m in (maps or {}).items():
            setattr(desc.maps, role, m.id if isinstance(m, Map) else m)
        if tiers is not None:
            array = (grass_tier_desc * len(tiers))(*tiers)  # noqa: F405
            keep.append(array)
            desc.tiers, desc.tier_count = array, len(tiers)
        if lod_tests is not None:
            array = (grass_lod_test * len(lod_tests))(*lod_tests)  # noqa: F405
            keep += [array] + [t.callback for t in lod_tests]
            desc.lod_tests, desc.lod_test_count = array, len(lod_tests)
        _fill(desc, fields)
        out = grass_field_id()  # noqa: F405
        self._check(lib.grass_create_field(self._ctx, ctypes.byref(desc), ctypes.byref(out)))
        field = Field(self, out)
        field.keep = keep  # lod test callbacks are called at every grass_begin_frame
        return field

    def apply_quality(self, quality, cell_size, patch=None):
        """grass_apply_quality: returns (patch desc, tiers, lod tests) for fields of
        `cell_size` metres; `quality` is a grass_quality_desc or a GRASS_QUALITY_* level."""
        if isinstance(quality, int):
            quality = lib.grass_quality_preset(quality)
        patch = patch if patch is not None else lib.grass_default_patch_desc()
        tiers = (grass_tier_desc * GRASS_MAX_TIERS)()  # noqa: F405
        tests = (grass_lod_test * GRASS_MAX_LOD_TESTS)()  # noqa: F405
        tier_count, test_count = ctypes.c_uint32(), ctypes.c_uint32()
        self._check(lib.grass_apply_quality(self._ctx, ctypes.byref(quality), cell_size, ctypes.byref(patch), tiers,
                                            ctypes.byref(tier_count), tests, ctypes.byref(test_count)))
        return patch, list(tiers[:tier_count.value]), list(tests[:test_count.value])

    # ---- frames
    def begin_frame(self, view):
        self._check(lib.grass_begin_frame(self._ctx, ctypes.byref(view)))

    def end_frame(self):
        self._check(lib.grass_end_frame(self._ctx))

    @contextlib.contextmanager
    def frame(self, view):
        """begin_frame(view) ... end_frame(), also when the block raises."""
        self.begin_frame(view)
        try:
            yield self
        finally:
            self.end_frame()

    def render_gl(self):
        """grass_gl_render: draws the begun frame into the bound GL draw framebuffer."""
        self._check(lib.grass_gl_render(self._ctx))

    def vk_prepare_frame(self, command_buffer):
        self._check(lib.grass_vk_prepare_frame(self._ctx, command_buffer))

    def vk_record(self, command_buffer):
        record = lib.grass_default_vk_record_desc()
        record.command_buffer = command_buffer
        self._check(lib.grass_vk_record(self._ctx, ctypes.byref(record)))

    # ---- stats
    def frame_stats(self):
        stats = grass_frame_stats()  # noqa: F405
        self._check(lib.grass_get_frame_stats(self._ctx, ctypes.byref(stats)))
        return stats

    def memory_stats(self):
        stats = grass_memory_stats()  # noqa: F405
        self._check(lib.grass_get_memory_stats(self._ctx, ctypes.byref(stats)))
        return stats

    def tier_gpu_ms(self):
        """(ms per tier kind, available) of the latest finished timed frame."""
        ms = (ctypes.c_double * GRASS_TIER_KIND_COUNT)()  # noqa: F405
        available = ctypes.c_uint32()
        self._check(lib.grass_get_tier_gpu_ms(self._ctx, ms, ctypes.byref(available)))
        return list(ms), bool(available.value)
