"""Design map pixels for grass_create_map and grass_update_map: a numpy array or a bytes-like
object, checked so that the library reads exactly the bytes the caller holds (its dtype,
shape and layout, or its length against width, height, row_pitch and format)."""
import ctypes
import numbers

from . import _checks
from ._ffi import ENUMS

_FORMATS = ENUMS["grass_map_format"]
_BAD_MAP = ENUMS["grass_message_id"]["GRASS_MSG_BAD_MAP"]
# format -> (channels, bytes per channel); numpy (dtype, channels) -> format
_TEXELS = {"R8_UNORM": (1, 1), "R16_UNORM": (1, 2), "R32_FLOAT": (1, 4), "RGBA8_UNORM": (4, 1),
           "RGBA16_UNORM": (4, 2), "RGBA32_FLOAT": (4, 4)}
TEXELS = {_FORMATS["GRASS_MAP_FORMAT_" + k]: v for k, v in _TEXELS.items()}
_NUMPY_FORMATS = {("uint8", 1): _FORMATS["GRASS_MAP_FORMAT_R8_UNORM"],
                  ("uint16", 1): _FORMATS["GRASS_MAP_FORMAT_R16_UNORM"],
                  ("float32", 1): _FORMATS["GRASS_MAP_FORMAT_R32_FLOAT"],
                  ("uint8", 4): _FORMATS["GRASS_MAP_FORMAT_RGBA8_UNORM"],
                  ("uint16", 4): _FORMATS["GRASS_MAP_FORMAT_RGBA16_UNORM"],
                  ("float32", 4): _FORMATS["GRASS_MAP_FORMAT_RGBA32_FLOAT"]}


def _fail(where, name, value, requirement):
    _checks.fail(where, name, value, requirement, _BAD_MAP)


def map_desc(desc, where, name, pixels, width=None, height=None, format=None, row_pitch=0):
    """Fills the grass_map_desc `desc` for `pixels` (see grass.map_desc); returns what must
    stay alive until the call that reads the desc returns."""
    if hasattr(pixels, "__array_interface__") and hasattr(pixels, "dtype"):
        return _from_array(desc, where, name, pixels, width, height, format, row_pitch)
    try:
        view = memoryview(pixels)
    except TypeError:
        _fail(where, name, pixels, "it must be a numpy array or a bytes-like object (bytes, bytearray, memoryview)")
    if not view.contiguous:
        _fail(where, name, pixels, "it must be a contiguous buffer (copy it with bytes())")
    if width is None or height is None:
        _fail(where, "width" if width is None else "height", None,
              f"it must be given for {name} from a buffer (a numpy array gives its own)")
    desc.width = _checks.integer(where, "width", width, 1, 2 ** 32 - 1)
    desc.height = _checks.integer(where, "height", height, 1, 2 ** 32 - 1)
    desc.format = _checks.enum(where, "format", _FORMATS["GRASS_MAP_FORMAT_R8_UNORM"] if format is None else format,
                               "grass_map_format")
    desc.row_pitch = _checks.integer(where, "row_pitch", row_pitch, 0, 2 ** 32 - 1)
    channels, size = TEXELS[desc.format]
    row_bytes = desc.width * channels * size
    pitch = desc.row_pitch or row_bytes
    if pitch >= row_bytes:  # else the library refuses the pitch before it reads a byte
        needed, most = pitch * (desc.height - 1) + row_bytes, pitch * desc.height
        if not needed <= view.nbytes <= most:
            fmt = next(k for k, v in _FORMATS.items() if v == desc.format)[len("GRASS_MAP_FORMAT_"):]
            rows = f" with a row_pitch of {desc.row_pitch}" if desc.row_pitch else ""
            amount = str(needed) if needed == most else f"{needed}..{most}"
            raise _checks.ArgumentError(
                f"{where}: {name} holds {view.nbytes} bytes; a {desc.width} x {desc.height} {fmt} map{rows} reads "
                f"{amount} bytes", _BAD_MAP)
    buffer = (ctypes.c_char * view.nbytes).from_buffer_copy(view.cast("B")) if view.nbytes else None
    desc.pixels = ctypes.addressof(buffer) if buffer is not None else None
    return buffer


def _from_array(desc, where, name, pixels, width, height, format, row_pitch):
    import numpy as np
    shape, dtype = tuple(pixels.shape), str(pixels.dtype)
    channels = 1 if len(shape) == 2 else shape[2] if len(shape) == 3 else None
    fmt = _NUMPY_FORMATS.get((dtype, channels))
    if fmt is None or shape[0] < 1 or shape[1] < 1:
        _fail(where, name, f"an array of shape {shape} and dtype {dtype}",
              "it must be (h, w) or (h, w, 4) of uint8, uint16 or float32 (native byte order), h and w at least 1")
    array = np.ascontiguousarray(pixels)
    for arg, value, wanted in (("width", width, shape[1]), ("height", height, shape[0])):
        if value is not None and (not isinstance(value, numbers.Integral) or value != wanted):
            _fail(where, arg, value, f"it must be None or the array's ({wanted}) for {name} from an array")
    if format is not None and format != fmt:
        _fail(where, "format", format, f"it must be None or {fmt}, the format of a {dtype} array with {channels} "
              f"channel(s)")
    if row_pitch not in (0, None):
        _fail(where, "row_pitch", row_pitch, f"it must be 0 for {name} from an array (rows are packed)")
    desc.pixels = array.ctypes.data
    desc.height, desc.width = shape[0], shape[1]
    desc.format, desc.row_pitch = fmt, 0
    return array
