"""grass from Python: a thin ctypes binding of the C API (grass.h, grass_gl.h, grass_vk.h).

    import grass
    with grass.Context() as ctx:                      # a CPU context: plans, draws nothing
        patch = ctx.create_patch()
        field = ctx.create_field(patch, cells_x=400, cells_z=300)
        view = grass.view_desc(eye=(50, 1.7, -5), target=(50, 0, 40), size=(640, 360))
        with ctx.frame(view):
            pass                                      # GL: ctx.render_gl(); Vulkan: ctx.vk_record(cmd)
        print(ctx.frame_stats().blades_drawn)

Every failure raises a GrassError: the library's (result, message_id, message), an argument
the binding refused before calling it (ArgumentError, also a ValueError and TypeError), a
closed context or object (ClosedError), or a Python callback that raised (its __cause__).
Each context serialises its calls with its own lock (threads: see docs/python.md). Objects
(Context, Patch, Field, Map) are context managers and have destroy(). The raw C functions
are grass.lib.<name> (unchecked: ctx.call(fn, ...) runs one under the context's lock), the C
structs and constants grass.<c name> (from grass._ffi).
"""
import contextlib
import ctypes
import numbers
import threading
import warnings

from . import _callbacks, _checks, _ffi, _pixels
from ._errors import ArgumentError, ClosedError, GrassError, MessageId, Result, short
from ._ffi import *  # noqa: F401,F403 - the C structs, enums and constants under their C names
from ._ffi import (GRASS_DEPTH_LESS, GRASS_ERROR_INVALID_ARGUMENT, GRASS_ERROR_INVALID_STATE, GRASS_HEADER_VERSION,
                   GRASS_LOD_TEST_CALLBACK, GRASS_LOG_ERROR, GRASS_LOG_WARNING, GRASS_MAX_LOD_TESTS, GRASS_MAX_TIERS,
                   GRASS_MSG_NONE, GRASS_SUCCESS, GRASS_TIER_KIND_COUNT)
from .camera import look_at, perspective

__version__ = _ffi.__version__
__all__ = ["lib", "GrassError", "ArgumentError", "ClosedError", "Result", "MessageId", "Context", "Patch", "Field",
           "Map", "patch_desc", "field_desc", "view_desc", "map_desc", "tier_desc", "lod_test", "quality_preset", "look_at",
           "perspective", "__version__"] + [n for n in dir(_ffi) if n.startswith(("grass_", "GRASS_"))]

lib = _ffi.load_library()
_MSG = _ffi.ENUMS["grass_message_id"]
_MAP_ROLES = ("density", "color", "ambient", "diffuse", "height")


def patch_desc(**fields):
    """grass_default_patch_desc() with `fields` changed (each checked against its C type)."""
    return _checks.fill("grass.patch_desc", lib.grass_default_patch_desc(), fields)


def field_desc(**fields):
    """grass_default_field_desc() with `fields` changed (pointers through create_field's arguments)."""
    return _checks.fill("grass.field_desc", lib.grass_default_field_desc(), fields)


def quality_preset(level):
    """grass_quality_preset(level): the knobs of a quality preset (a GRASS_QUALITY_* level)."""
    return lib.grass_quality_preset(_checks.enum("grass.quality_preset", "level", level, "grass_quality_level"))


def view_desc(eye=None, target=None, size=None, fovy=0.9, near=0.05, far=1000.0, clip_z_zero_to_one=False,
              up=(0.0, 1.0, 0.0), **fields):
    """grass_default_view_desc() with the camera set: at `eye` looking at `target` (world
    metres, y up unless `up` says otherwise), a perspective of `fovy` radians for a viewport
    of size = (width, height) at (0, 0). GL clip z is -1..1; pass clip_z_zero_to_one=True (and
    flip y yourself) for Vulkan. Then `fields` (e.g. flags=GRASS_VIEW_FLAG_DEBUG_TIERS) are set."""
    where = "grass.view_desc"
    view = lib.grass_default_view_desc()
    if eye is not None or target is not None:
        if eye is None or target is None:
            _checks.fail(where, "eye" if eye is None else "target", None, "eye and target go together")
        view.view[:] = look_at(eye, target, up, where=where)
        view.camera_position[:] = _checks.vector(where, "eye", eye, 3)
    if size is not None:
        if isinstance(size, (str, bytes)) or not hasattr(size, "__len__") or len(size) != 2:
            _checks.fail(where, "size", size, "it must be (width, height)")
        if not all(isinstance(v, numbers.Integral) and 1 <= v <= 2 ** 31 - 1 for v in size):
            _checks.fail(where, "size", size, f"width and height must be integers in 1..{2 ** 31 - 1}")
        view.viewport[:] = [0, 0, int(size[0]), int(size[1])]
        view.projection[:] = perspective(fovy, size[0] / size[1], near, far, clip_z_zero_to_one, where=where)
    return _checks.fill(where, view, fields)


def map_desc(pixels, width=None, height=None, format=None, row_pitch=0):
    """A grass_map_desc for `pixels`: a numpy array of shape (height, width) for one channel
    or (height, width, 4) for RGBA, dtype uint8, uint16 or float32 (row 0 first, rows run
    along field +z); or a bytes-like object with width, height (and format, row_pitch) given,
    whose length must be what the library reads. Returns (desc, keep): keep the second alive
    until the call that takes the desc returns."""
    desc = lib.grass_default_map_desc()
    return desc, _pixels.map_desc(desc, "grass.map_desc", "pixels", pixels, width, height, format, row_pitch)


def tier_desc(kind, slices=0):
    """A grass_tier_desc: `kind` a GRASS_TIER_* kind, `slices` per axis for volume tiers."""
    where = "grass.tier_desc"
    return grass_tier_desc(_checks.enum(where, "kind", kind, "grass_tier_kind"),  # noqa: F405
                           _checks.integer(where, "slices", slices, 0, 2 ** 32 - 1))


def lod_test(callback, tier=0, **fields):
    """A GRASS_LOD_TEST_CALLBACK grass_lod_test for tier `tier` calling callback(node) -> a
    grass_lod_answer, with node a grass_lod_node. An exception or another answer becomes a
    GrassError of the begin_frame that called it (the node gets GRASS_LOD_DISCARD)."""
    where = "grass.lod_test"
    _checks.callable_(where, "callback", callback)
    test = _checks.fill(where, grass_lod_test(kind=GRASS_LOD_TEST_CALLBACK), dict(tier=tier, **fields))  # noqa: F405
    test.callback = _callbacks.lod_callback(callback)
    return test


class _Object:
    """A patch, field or map of a context: destroy() or a with block destroys it."""
    _destroy_fn = None
    _kind = None

    def __init__(self, context, handle):
        self.context = context
        self.id = handle

    def _require(self, where):
        if self.id is None:
            raise ClosedError(f"{where}: the {self._kind} is destroyed")
        if self.context._ctx is None:
            raise ClosedError(f"{where}: the {self._kind}'s context is closed")
        return self.id

    def destroy(self):
        """Destroys it; nothing to do when it or its context is destroyed already."""
        if self.id is not None and self.context._ctx is not None:
            self.context._call(f"{type(self).__name__}.destroy", getattr(lib, self._destroy_fn), self.id)
        self.id = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.destroy()


class Patch(_Object):
    """A grass type (grass_patch_id)."""
    _destroy_fn, _kind = "grass_destroy_patch", "patch"

    def info(self):
        info = grass_patch_info()  # noqa: F405
        self.context._call("Patch.info", lib.grass_get_patch_info, self._require("Patch.info"), ctypes.byref(info))
        return info

    def thresholds(self):
        """The per-blade density thresholds, as a list of floats."""
        n = self.info().blade_count
        out = (ctypes.c_float * n)()
        self.context._call("Patch.thresholds", lib.grass_get_patch_thresholds, self._require("Patch.thresholds"),
                           out, n)
        return list(out)


class Field(_Object):
    """A field (grass_field_id). Keeps the lod test callbacks it was made with alive."""
    _destroy_fn, _kind = "grass_destroy_field", "field"

    def destroy(self):
        super().destroy()
        self.keep = None


class Map(_Object):
    """A design map (grass_map_id): width, height and format as made."""
    _destroy_fn, _kind = "grass_destroy_map", "map"

    def update(self, x, y, pixels, **kw):
        """Replaces the texels of the rectangle at (x, y) the size of `pixels` (as map_desc;
        same format as the map). The library refuses a rectangle that leaves the map."""
        where = "Map.update"
        handle = self._require(where)
        x = _checks.integer(where, "x", x, 0, 2 ** 32 - 1)
        y = _checks.integer(where, "y", y, 0, 2 ** 32 - 1)
        desc = lib.grass_default_map_desc()
        keep = _pixels.map_desc(desc, where, "pixels", pixels, **_map_kw(where, kw))
        if x + desc.width > self.width or y + desc.height > self.height:
            _checks.fail(where, "(x, y)", (x, y), f"a {desc.width} x {desc.height} region there leaves the "
                         f"{self.width} x {self.height} map", _MSG["GRASS_MSG_MAP_REGION"])
        self.context._call(where, lib.grass_update_map, handle, x, y, ctypes.byref(desc))
        del keep


def _flat_array(where, name, value, n, ctype):
    """A flat ctypes array of a sequence of numbers, or of n-tuples; its length a multiple of n."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__"):
        _checks.fail(where, name, value, f"it must be a sequence of numbers, {n} a vertex")
    flat = []
    for i, item in enumerate(value):
        if hasattr(item, "__len__") and not isinstance(item, (str, bytes)):
            flat.extend(item)
        else:
            flat.append(item)
    if not flat or len(flat) % n != 0:
        _checks.fail(where, name, f"{len(flat)} values", f"it must hold a positive multiple of {n} values")
    try:
        return (ctype * len(flat))(*flat)
    except (TypeError, OverflowError) as e:
        raise ArgumentError(f"{where}: {name} holds a value that is not a {ctype.__name__}: {e}",
                            _ffi.ENUMS["grass_message_id"]["GRASS_MSG_OUT_OF_RANGE"]) from None


def _map_kw(where, kw):
    for name in kw:
        if name not in ("width", "height", "format", "row_pitch"):
            _checks.fail(where, name, kw[name], "it is not an argument (width, height, format, row_pitch)")
    return kw


class Context:
    """A grass context. Context() has no GPU backend (plans and stats only);
    Context.gl(get_proc_address) draws with the current GL context; Context.vk(vk_desc)
    records into Vulkan command buffers. `log(level, message_id, message)` receives every
    message up to `log_level`; errors also go into the GrassError raised. Calls are
    serialised by the context's own lock; `with ctx.frame(view)` holds it for the frame."""

    def __init__(self, log=None, log_level=GRASS_LOG_WARNING, depth_mode=GRASS_DEPTH_LESS,
                 cache_directory=None, _create=None, _where="grass.Context"):
        self._ctx = None
        self._lock = threading.RLock()
        self._in_call = False
        self._last = None
        self._thread = threading.local()
        self._user_log = _checks.callable_(_where, "log", log, allow_none=True)
        desc = lib.grass_default_context_desc()
        desc.log_level = _checks.enum(_where, "log_level", log_level, "grass_log_level")
        desc.depth_mode = _checks.enum(_where, "depth_mode", depth_mode, "grass_depth_mode")
        if cache_directory is not None:
            desc.cache_directory = _checks.path_bytes(_where, "cache_directory", cache_directory)
        self._log_fn = grass_log_fn(self._on_log)  # noqa: F405 - kept alive as long as the context
        desc.log_fn = self._log_fn
        out = ctypes.c_void_p()
        scope = _callbacks.enter()
        try:
            if _create is None:
                result = lib.grass_create_context(GRASS_HEADER_VERSION, ctypes.byref(desc), ctypes.byref(out))
            else:
                result = _create(desc, out)
        finally:
            _callbacks.leave(scope)
        last = self._last or (GRASS_MSG_NONE, "")
        if scope.errors and out.value:  # a callback failed: the context is not handed out
            lib.grass_destroy_context(out.value)
        self._raise_for(_where, result, last, scope.errors)
        self._ctx = out.value

    @classmethod
    def gl(cls, get_proc_address, **kw):
        """A GL context (grass_gl_create_context): the host's GL 4.5 context must be current.
        get_proc_address(name: bytes) -> int address or None, e.g. grass.headless's."""
        where = "grass.Context.gl"
        _checks.callable_(where, "get_proc_address", get_proc_address)
        loader = _callbacks.gl_loader(get_proc_address)

        def create(desc, out):
            gl = lib.grass_default_gl_desc()
            gl.get_proc_address = loader
            return lib.grass_gl_create_context(GRASS_HEADER_VERSION, ctypes.byref(desc), ctypes.byref(gl),
                                               ctypes.byref(out))
        self = cls(_create=create, _where=where, **kw)
        self._loader = loader  # grass loads its entry points at creation; kept alive anyway
        return self

    @classmethod
    def vk(cls, vk_desc, get_instance_proc_addr=None, **kw):
        """A Vulkan context (grass_vk_create_context) from a filled grass_vk_desc. Its handles
        are raw Vulkan handles the binding cannot check. get_instance_proc_addr(name: bytes)
        -> int or None, if given, replaces the desc's loader with a wrapped Python one."""
        where = "grass.Context.vk"
        desc = grass_vk_desc.from_buffer_copy(_checks.instance(where, "vk_desc", vk_desc, grass_vk_desc))  # noqa
        _checks.no_pointers(where, "vk_desc", desc, allowed=("get_instance_proc_addr", "instance",
                                                             "physical_device", "device"))
        loader = None
        if _checks.callable_(where, "get_instance_proc_addr", get_instance_proc_addr, allow_none=True):
            loader = desc.get_instance_proc_addr = _callbacks.vk_loader(get_instance_proc_addr)
        self = cls(_create=lambda d, out: lib.grass_vk_create_context(
            GRASS_HEADER_VERSION, ctypes.byref(d), ctypes.byref(desc), ctypes.byref(out)), _where=where, **kw)
        self._loader = loader
        return self

    def _on_log(self, user_data, level, message_id, message):
        try:
            text = message.decode(errors="replace") if message else ""
            if level == GRASS_LOG_ERROR:
                self._last = (message_id, text)
            if self._user_log:
                self._user_log(level, message_id, text)
        except BaseException as e:  # noqa: B036 - nothing may cross back into C
            _callbacks._raised("log", e)

    def _raise_for(self, where, result, last, errors):
        """Raises the GrassError of a call: a callback's problem first (its exception is the
        cause), else the library's error."""
        if errors:
            sentence, exception = errors[0]
            if isinstance(exception, (KeyboardInterrupt, SystemExit)):
                raise exception
            text = f"{where}: {sentence}"
            if result != GRASS_SUCCESS:
                text += f"; the call then failed: {last[1]}"
            error = GrassError(result if result != GRASS_SUCCESS else GRASS_ERROR_INVALID_ARGUMENT,
                               last[0] if result != GRASS_SUCCESS else GRASS_MSG_NONE, text)
            self._thread.last_error = text
            raise error from exception
        if result != GRASS_SUCCESS:
            self._thread.last_error = last[1]
            raise GrassError(result, *last)

    def _open(self, where):
        if self._ctx is None:
            raise ClosedError(f"{where}: the context is closed (destroy() was called)")
        return self._ctx

    def _call(self, where, fn, *args, undo=None):
        """fn(context, *args) under the context's lock; raises its error, or a callback's.
        undo(context) destroys what a successful call made when a callback failed during it."""
        with self._lock:
            handle = self._open(where)
            if self._in_call:
                raise GrassError(GRASS_ERROR_INVALID_STATE, GRASS_MSG_NONE,
                                 f"{where}: called from inside a grass callback of this context, during another "
                                 f"call on it (grass contexts are not re-entrant)")
            self._in_call, self._last = True, None
            scope = _callbacks.enter()
            try:
                result = fn(handle, *args)
                last = self._last
                if result != GRASS_SUCCESS and last is None:
                    last = (GRASS_MSG_NONE, lib.grass_get_last_error(handle).decode(errors="replace"))
                if scope.errors and result == GRASS_SUCCESS and undo is not None:
                    undo(handle)
            finally:
                self._in_call = False
                _callbacks.leave(scope)
            self._raise_for(where, result, last, scope.errors)

    def call(self, fn, *args):
        """A raw grass.lib function on this context: fn(ctx.handle, *args) under the context's
        lock, raising a GrassError if it fails. Its arguments are not checked (raw layer)."""
        _checks.callable_("Context.call", "fn", fn)
        self._call(f"Context.call({getattr(fn, '__name__', short(fn))})", fn, *args)

    # ---- lifetime
    def destroy(self):
        """grass_destroy_context: destroys every object of the context too (GL: the GL
        context must be current). Nothing to do when it is destroyed already."""
        with self._lock:
            if self._in_call:
                raise GrassError(GRASS_ERROR_INVALID_STATE, GRASS_MSG_NONE,
                                 "Context.destroy: called from inside a grass callback of this context")
            handle, self._ctx = self._ctx, None  # closed already for callbacks during the destruction
            if handle:
                self._in_call = True
                scope = _callbacks.enter()
                try:
                    lib.grass_destroy_context(handle)
                finally:
                    self._in_call = False
                    _callbacks.leave(scope)
                self._raise_for("Context.destroy (the context is destroyed)", GRASS_SUCCESS, None, scope.errors)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.destroy()

    def __del__(self):
        with contextlib.suppress(Exception):
            self.destroy()

    @property
    def handle(self):
        """The grass_context* as an int for the raw functions in grass.lib; None when closed."""
        return self._ctx

    @property
    def backend(self):
        """GRASS_BACKEND_NONE, _GL or _VULKAN."""
        with self._lock:
            return lib.grass_get_context_backend(self._open("Context.backend"))

    @property
    def last_error(self):
        """The message of the last GrassError a call on this context raised in this thread, or ""."""
        self._open("Context.last_error")
        return getattr(self._thread, "last_error", "")

    # ---- objects
    def _own(self, where, name, value, cls, id_type):
        """The id of a Patch/Map of this context (or a raw id struct)."""
        if isinstance(value, cls):
            if value.context is not self:
                _checks.fail(where, name, value, f"it is a {cls.__name__} of another context",
                             _MSG["GRASS_MSG_FOREIGN_HANDLE"])
            return value._require(where)
        return _checks.instance(where, name, value, id_type, f" or a {cls.__name__} of this context")

    def create_patch(self, desc=None, **fields):
        """A grass type from `desc` (a grass_patch_desc) or the default desc with `fields`."""
        where = "Context.create_patch"
        self._open(where)
        desc = _copy(where, "desc", desc, grass_patch_desc) if desc is not None else lib.grass_default_patch_desc()  # noqa
        _checks.fill(where, desc, fields)
        out = grass_patch_id()  # noqa: F405
        self._call(where, lib.grass_create_patch, ctypes.byref(desc), ctypes.byref(out),
                   undo=lambda h: lib.grass_destroy_patch(h, out))
        return Patch(self, out)

    def create_map(self, pixels, **kw):
        """A design map from a numpy array or a buffer (see map_desc)."""
        where = "Context.create_map"
        self._open(where)
        desc = lib.grass_default_map_desc()
        keep = _pixels.map_desc(desc, where, "pixels", pixels, **_map_kw(where, kw))
        out = grass_map_id()  # noqa: F405
        self._call(where, lib.grass_create_map, ctypes.byref(desc), ctypes.byref(out),
                   undo=lambda h: lib.grass_destroy_map(h, out))
        del keep
        made = Map(self, out)
        made.width, made.height, made.format = desc.width, desc.height, desc.format
        return made

    def create_field(self, patch=None, desc=None, density_map=None, maps=None, tiers=None, lod_tests=None,
                     **fields):
        """A field: `desc` (a grass_field_desc) or the default desc, with `patch` (a Patch),
        `density_map` (pixels as for create_map, copied into this field), `maps` (a dict by
        role: density, color, ambient, diffuse, height as Map objects; height_scale,
        cell_to_map as numbers), `tiers` and `lod_tests` (sequences of grass_tier_desc /
        grass_lod_test, callbacks made by grass.lod_test) and `fields` set."""
        where = "Context.create_field"
        self._open(where)
        desc = _copy(where, "desc", desc, grass_field_desc) if desc is not None else lib.grass_default_field_desc()  # noqa
        keep = []
        if patch is not None:
            desc.patch = self._own(where, "patch", patch, Patch, grass_patch_id)  # noqa: F405
        if density_map is not None:
            map_d = lib.grass_default_map_desc()
            keep += [map_d, _pixels.map_desc(map_d, where, "density_map", density_map)]
            desc.density_map = ctypes.pointer(map_d)
        if maps is not None:
            if not isinstance(maps, dict):
                _checks.fail(where, "maps", maps, "it must be a dict by role")
            for role, value in maps.items():
                if role in _MAP_ROLES:
                    setattr(desc.maps, role, self._own(where, f"maps[{role!r}]", value, Map, grass_map_id))  # noqa
                elif role in ("height_scale", "cell_to_map"):
                    _checks.fill(where, desc.maps, {role: value})
                else:
                    _checks.fail(where, "maps", role, f"its keys must be {', '.join(_MAP_ROLES)}, height_scale or "
                                 "cell_to_map")
        if tiers is not None:
            tiers = _sequence(where, "tiers", tiers, grass_tier_desc, GRASS_MAX_TIERS)  # noqa: F405
            array = (grass_tier_desc * len(tiers))(*tiers)  # noqa: F405
            keep.append(array)
            desc.tiers, desc.tier_count = array, len(tiers)
        if lod_tests is not None:
            lod_tests = _sequence(where, "lod_tests", lod_tests, grass_lod_test, GRASS_MAX_LOD_TESTS)  # noqa: F405
            for i, test in enumerate(lod_tests):
                address = ctypes.cast(test.callback, ctypes.c_void_p).value
                if address:
                    callback = _callbacks.LOD_CALLBACKS.get(address)
                    if callback is None:
                        _checks.fail(where, f"lod_tests[{i}].callback", test.callback,
                                     "make callback lod tests with grass.lod_test(fn): a raw function pointer "
                                     "cannot report a Python exception")
                    keep.append(callback)
            array = (grass_lod_test * len(lod_tests))(*lod_tests)  # noqa: F405
            keep.append(array)
            desc.lod_tests, desc.lod_test_count = array, len(lod_tests)
        _checks.fill(where, desc, fields)
        out = grass_field_id()  # noqa: F405
        self._call(where, lib.grass_create_field, ctypes.byref(desc), ctypes.byref(out),
                   undo=lambda h: lib.grass_destroy_field(h, out))
        field = Field(self, out)
        field.keep = keep  # lod test callbacks are called at every grass_begin_frame
        return field

    def create_mesh_field(self, patch, positions, normals, indices, uvs=None, vertex_density=None, maps=None,
                          desc=None, **fields):
        """A mesh field (grass_create_mesh_field): grass on a triangle mesh. `positions` and
        `normals` hold 3 numbers a vertex, `uvs` 2, `vertex_density` 1 (each a flat sequence or
        a sequence of tuples), `indices` 3 a triangle; `maps` a dict with density and/or color
        (Map objects); `desc` a grass_mesh_field_desc to start from and `fields` set on it
        (density, density_source, seeding, transform, ...). Arrays are copied by the call."""
        where = "Context.create_mesh_field"
        self._open(where)
        desc = (_copy(where, "desc", desc, grass_mesh_field_desc) if desc is not None  # noqa: F405
                else lib.grass_default_mesh_field_desc())
        desc.patch = self._own(where, "patch", patch, Patch, grass_patch_id)  # noqa: F405
        keep = []
        vertex_count = None
        for name, value, n in (("positions", positions, 3), ("normals", normals, 3), ("uvs", uvs, 2),
                               ("vertex_density", vertex_density, 1)):
            if value is None:
                continue
            array = _flat_array(where, name, value, n, ctypes.c_float)
            count = len(array) // n
            if vertex_count is not None and count != vertex_count:
                _checks.fail(where, name, f"{count} vertices", f"it must hold {vertex_count} vertices, as positions")
            vertex_count = count
            keep.append(array)
            setattr(desc, name, ctypes.cast(array, ctypes.POINTER(ctypes.c_float)))
        index_array = _flat_array(where, "indices", indices, 3, ctypes.c_uint32)
        keep.append(index_array)
        desc.indices = ctypes.cast(index_array, ctypes.POINTER(ctypes.c_uint32))
        desc.vertex_count, desc.index_count = vertex_count, len(index_array)
        if vertex_density is not None and "density_source" not in fields:
            desc.density_source = GRASS_MESH_DENSITY_PER_VERTEX  # noqa: F405
        if maps is not None:
            if not isinstance(maps, dict) or not set(maps) <= {"density", "color"}:
                _checks.fail(where, "maps", maps, "it must be a dict with density and/or color")
            for role, value in maps.items():
                setattr(desc.maps, role, self._own(where, f"maps[{role!r}]", value, Map, grass_map_id))  # noqa
            if "density" in maps and "density_source" not in fields:
                desc.density_source = GRASS_MESH_DENSITY_MAP  # noqa: F405
        _checks.fill(where, desc, fields)
        out = grass_field_id()  # noqa: F405
        self._call(where, lib.grass_create_mesh_field, ctypes.byref(desc), ctypes.byref(out),
                   undo=lambda h: lib.grass_destroy_field(h, out))
        return Field(self, out)

    def apply_quality(self, quality, cell_size, patch=None):
        """grass_apply_quality: returns (patch desc, tiers, lod tests) for fields of
        `cell_size` metres; `quality` is a grass_quality_desc or a GRASS_QUALITY_* level."""
        where = "Context.apply_quality"
        self._open(where)
        if isinstance(quality, grass_quality_desc):  # noqa: F405
            quality = _copy(where, "quality", quality, grass_quality_desc)  # noqa: F405
        else:
            quality = lib.grass_quality_preset(_checks.enum(where, "quality", quality, "grass_quality_level"))
        cell_size = _checks.real(where, "cell_size", cell_size, finite=False)
        patch = _copy(where, "patch", patch, grass_patch_desc) if patch is not None else lib.grass_default_patch_desc()  # noqa
        tiers = (grass_tier_desc * GRASS_MAX_TIERS)()  # noqa: F405
        tests = (grass_lod_test * GRASS_MAX_LOD_TESTS)()  # noqa: F405
        tier_count, test_count = ctypes.c_uint32(), ctypes.c_uint32()
        self._call(where, lib.grass_apply_quality, ctypes.byref(quality), cell_size, ctypes.byref(patch), tiers,
                   ctypes.byref(tier_count), tests, ctypes.byref(test_count))
        return patch, list(tiers[:tier_count.value]), list(tests[:test_count.value])

    # ---- frames
    def begin_frame(self, view):
        """grass_begin_frame(view): `view` a grass_view_desc (grass.view_desc(...))."""
        where = "Context.begin_frame"
        view = _copy(where, "view", view, grass_view_desc, " (grass.view_desc(...))")  # noqa: F405
        self._call(where, lib.grass_begin_frame, ctypes.byref(view))

    def begin_host_frame(self, frame_index, completed_frame_index=0, time=0.0):
        """grass_begin_host_frame: begins the host's frame `frame_index` (> every earlier one),
        knowing frames up to `completed_frame_index` finished on the GPU; plan its views with
        plan_view and draw them with render_gl_view / vk_record_view."""
        where = "Context.begin_host_frame"
        frame = lib.grass_default_frame_desc()
        frame.frame_index = _checks.integer(where, "frame_index", frame_index, 1, 2 ** 64 - 1)
        frame.completed_frame_index = _checks.integer(where, "completed_frame_index", completed_frame_index, 0,
                                                      2 ** 64 - 1)
        frame.time = _checks.real(where, "time", time, low=-1e9, high=1e9)
        self._call(where, lib.grass_begin_host_frame, ctypes.byref(frame))

    def plan_view(self, view):
        """grass_plan_view(view): plans one more view of the begun frame; returns its index."""
        where = "Context.plan_view"
        view = _copy(where, "view", view, grass_view_desc, " (grass.view_desc(...))")  # noqa: F405
        index = ctypes.c_uint32(0)
        self._call(where, lib.grass_plan_view, ctypes.byref(view), ctypes.byref(index))
        return index.value

    def end_frame(self):
        self._call("Context.end_frame", lib.grass_end_frame)

    @contextlib.contextmanager
    def frame(self, view):
        """begin_frame(view) ... end_frame(), also when the block raises; the block holds
        the context's lock, so no other thread's call lands inside the frame."""
        with self._lock:
            self.begin_frame(view)
            try:
                yield self
            finally:
                self.end_frame()

    def render_gl(self):
        """grass_gl_render: draws the begun frame into the bound GL draw framebuffer."""
        self._call("Context.render_gl", lib.grass_gl_render)

    def render_gl_view(self, view):
        """grass_gl_render_view: draws view `view` (plan_view's index) of the begun frame."""
        where = "Context.render_gl_view"
        self._call(where, lib.grass_gl_render_view, _checks.integer(where, "view", view, 0, 2 ** 32 - 1))

    def vk_prepare(self, command_buffer):
        """grass_vk_prepare into `command_buffer`, a raw VkCommandBuffer as an int, outside any
        render pass."""
        where = "Context.vk_prepare"
        prepare = lib.grass_default_vk_prepare_desc()
        prepare.command_buffer = _checks.integer(where, "command_buffer", command_buffer, 0, 2 ** 64 - 1) or None
        self._call(where, lib.grass_vk_prepare, ctypes.byref(prepare))

    def vk_prepare_frame(self, command_buffer):
        """The 0.4 name of vk_prepare (grass_vk_prepare_frame became grass_vk_prepare in 0.5)."""
        warnings.warn("Context.vk_prepare_frame was renamed Context.vk_prepare in grass 0.5", DeprecationWarning,
                      stacklevel=2)
        self.vk_prepare(command_buffer)

    def vk_record(self, command_buffer):
        """grass_vk_record into `command_buffer`, a raw VkCommandBuffer as an int."""
        where = "Context.vk_record"
        record = lib.grass_default_vk_record_desc()
        record.command_buffer = _checks.integer(where, "command_buffer", command_buffer, 0, 2 ** 64 - 1) or None
        self._call(where, lib.grass_vk_record, ctypes.byref(record))

    def vk_record_view(self, view, command_buffer):
        """grass_vk_record_view: records view `view` (plan_view's index) into `command_buffer`."""
        where = "Context.vk_record_view"
        index = _checks.integer(where, "view", view, 0, 2 ** 32 - 1)
        record = lib.grass_default_vk_record_desc()
        record.command_buffer = _checks.integer(where, "command_buffer", command_buffer, 0, 2 ** 64 - 1) or None
        self._call(where, lib.grass_vk_record_view, index, ctypes.byref(record))

    # ---- stats
    def frame_stats(self):
        stats = grass_frame_stats()  # noqa: F405
        self._call("Context.frame_stats", lib.grass_get_frame_stats, ctypes.byref(stats))
        return stats

    def memory_stats(self):
        stats = grass_memory_stats()  # noqa: F405
        self._call("Context.memory_stats", lib.grass_get_memory_stats, ctypes.byref(stats))
        return stats

    def tier_gpu_ms(self):
        """(ms per tier kind, available) of the latest finished timed frame."""
        ms = (ctypes.c_double * GRASS_TIER_KIND_COUNT)()
        available = ctypes.c_uint32()
        self._call("Context.tier_gpu_ms", lib.grass_get_tier_gpu_ms, ms, ctypes.byref(available))
        return list(ms), bool(available.value)


def _copy(where, name, value, cls, hint=""):
    """A copy of the struct `value` (a caller's desc is never changed) with no pointer set."""
    _checks.instance(where, name, value, cls, hint)
    return _checks.no_pointers(where, name, cls.from_buffer_copy(value))


def _sequence(where, name, value, cls, most):
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or not hasattr(value, "__getitem__"):
        _checks.fail(where, name, value, f"it must be a list of {cls.__name__}")
    if len(value) > most:
        _checks.fail(where, name, f"{len(value)} items", f"it must hold at most {most}")
    for i, item in enumerate(value):
        _checks.instance(where, f"{name}[{i}]", item, cls)
    return list(value)
