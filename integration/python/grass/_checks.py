"""Argument checks made before ctypes converts anything: each refusal is an ArgumentError
that names the argument and its value (cut when long). ctypes would wrap -5 into a uint32,
turn a str into a TypeError about ctypes, or read past a buffer; these do not let it."""
import ctypes
import math
import numbers
import os

from ._errors import ArgumentError, short
from ._ffi import ENUMS

_MSG = ENUMS["grass_message_id"]
_INT_RANGES = {ctypes.c_uint16: (0, 2 ** 16 - 1), ctypes.c_uint32: (0, 2 ** 32 - 1), ctypes.c_uint64: (0, 2 ** 64 - 1),
               ctypes.c_int32: (-2 ** 31, 2 ** 31 - 1), ctypes.c_int: (-2 ** 31, 2 ** 31 - 1)}
_FLOAT_MAX = {ctypes.c_float: 3.4028234663852886e38, ctypes.c_double: 1.7976931348623157e308}
# Struct fields that hold pointers: the Pythonic layer sets them itself from arguments it
# checks (tiers=, lod_tests=, density_map=), never from a number a caller passes.
_POINTER_TYPES = (ctypes.c_void_p, ctypes.c_char_p, ctypes._Pointer, ctypes._CFuncPtr)


def fail(where, name, value, requirement, message_id=_MSG["GRASS_MSG_OUT_OF_RANGE"]):
    raise ArgumentError(f"{where}: {name} is {short(value)}; {requirement}", message_id)


def integer(where, name, value, low, high):
    """An int (bool and numpy ints too) in low..high."""
    if not isinstance(value, numbers.Integral):
        fail(where, name, value, f"it must be an integer in {low}..{high}")
    if not low <= int(value) <= high:
        fail(where, name, value, f"it must be in {low}..{high}")
    return int(value)


def real(where, name, value, finite=True, low=None, high=None, low_open=False):
    """A real number (int or float, not a str or complex); finite unless `finite` is False."""
    if not isinstance(value, numbers.Real):
        fail(where, name, value, "it must be a real number", _MSG["GRASS_MSG_NOT_FINITE"])
    v = float(value)
    if finite and not math.isfinite(v):
        fail(where, name, value, "it must be finite", _MSG["GRASS_MSG_NOT_FINITE"])
    if low is not None and (v < low or (low_open and v == low)):
        fail(where, name, value, f"it must be {'greater than' if low_open else 'at least'} {low}")
    if high is not None and v > high:
        fail(where, name, value, f"it must be at most {high}")
    return v


def vector(where, name, value, n, finite=True):
    """A sequence of `n` real numbers (a list, tuple or numpy array; not a str)."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or not hasattr(value, "__getitem__"):
        fail(where, name, value, f"it must be a sequence of {n} numbers")
    if len(value) != n:
        fail(where, name, value, f"it must hold {n} values, not {len(value)}")
    return [real(where, f"{name}[{i}]", value[i], finite) for i in range(n)]


def enum(where, name, value, enum_name):
    """One of the values of the C enum `enum_name`."""
    values = ENUMS[enum_name]
    if not isinstance(value, numbers.Integral) or int(value) not in values.values():
        fail(where, name, value, f"it must be a {enum_name} ({', '.join(sorted(values, key=values.get))})",
             _MSG["GRASS_MSG_BAD_ENUM"])
    return int(value)


def instance(where, name, value, cls, hint=""):
    if not isinstance(value, cls):
        fail(where, name, value, f"it must be a {cls.__name__}{hint}", _MSG["GRASS_MSG_NULL_ARGUMENT"])
    return value


def callable_(where, name, value, allow_none=False):
    if value is None and allow_none:
        return None
    if not callable(value):
        fail(where, name, value, "it must be a callable" + (" or None" if allow_none else ""),
             _MSG["GRASS_MSG_NULL_ARGUMENT"])
    return value


def path_bytes(where, name, value):
    """A str, bytes or os.PathLike without NUL, as bytes."""
    if not isinstance(value, (str, bytes, os.PathLike)):
        fail(where, name, value, "it must be a path (str, bytes or os.PathLike)")
    data = os.fsencode(value)
    if b"\0" in data:
        fail(where, name, value, "it must not hold a NUL character")
    return data


def no_pointers(where, name, struct, allowed=()):
    """Refuses a struct whose pointer fields (next, arrays, callbacks) are set: the Pythonic
    layer fills those from checked arguments, never from raw addresses."""
    for field, ctype in struct._fields_[:]:
        if field in allowed:
            continue
        if isinstance(ctype, type) and issubclass(ctype, _POINTER_TYPES):
            if _pointer_value(struct, field):
                fail(where, f"{name}.{field}", _pointer_value(struct, field),
                     "it must be NULL here: the Pythonic layer sets it from its own argument",
                     _MSG["GRASS_MSG_NEXT_NOT_NULL"] if field == "next" else _MSG["GRASS_MSG_NULL_ARGUMENT"])
        elif isinstance(ctype, type) and issubclass(ctype, ctypes.Structure):
            no_pointers(where, f"{name}.{field}", getattr(struct, field))
    return struct


def _pointer_value(struct, field):
    offset = getattr(type(struct), field).offset
    return ctypes.c_void_p.from_buffer(struct, offset).value


def fill(where, struct, fields):
    """Sets struct fields from keyword arguments, each checked against its C type; sequences
    fill arrays, nested structs must be of their type, pointer fields are refused."""
    types = dict(struct._fields_)
    for name, value in fields.items():
        if name not in types:
            fail(where, name, value, f"{type(struct).__name__} has no field {name!r}")
        if name == "type":
            fail(where, name, value, "it is the struct's type tag, set by grass_default_*()")
        setattr(struct, name, convert(where, name, value, types[name]))
    return struct


def convert(where, name, value, ctype):
    """`value` checked against the ctypes type `ctype`, ready to assign."""
    if issubclass(ctype, ctypes.Array):
        n = ctype._length_
        if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or not hasattr(value, "__getitem__"):
            fail(where, name, value, f"it must be a sequence of {n} values")
        if len(value) != n:
            fail(where, name, value, f"it must hold {n} values, not {len(value)}")
        return ctype(*[convert(where, f"{name}[{i}]", value[i], ctype._type_) for i in range(n)])
    if issubclass(ctype, ctypes.Structure):
        return instance(where, name, value, ctype)
    if issubclass(ctype, _POINTER_TYPES):
        if name == "cache_directory":
            return path_bytes(where, name, value)
        fail(where, name, value, "it is a pointer the Pythonic layer sets from its own argument (or use grass.lib)",
             _MSG["GRASS_MSG_NEXT_NOT_NULL"] if name == "next" else _MSG["GRASS_MSG_NULL_ARGUMENT"])
    if ctype in _INT_RANGES:
        low, high = _INT_RANGES[ctype]
        return integer(where, name, value, low, high)
    if ctype in _FLOAT_MAX:
        limit = _FLOAT_MAX[ctype]
        v = real(where, name, value, finite=False)
        if math.isfinite(v) and abs(v) > limit:
            fail(where, name, value, f"it must be within +-{limit:g} (a {ctype.__name__[2:]})",
                 _MSG["GRASS_MSG_NOT_FINITE"])
        return v
    raise AssertionError(f"no check for {ctype}")  # a new field type: add its check here
