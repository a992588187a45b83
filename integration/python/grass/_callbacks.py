"""Python callbacks handed to grass, wrapped: ctypes cannot carry an exception out of a
callback (it prints it and returns garbage), so each trampoline catches everything, returns
a safe value (NULL, or GRASS_LOD_DISCARD), checks what the Python function returned, and
records the problem for the binding call under way on this thread, which raises it as a
GrassError (the exception is its __cause__) once the C call has returned."""
import ctypes
import numbers
import sys
import threading
import weakref

from ._errors import short
from ._ffi import ENUMS, grass_gl_get_proc_address_fn, grass_lod_test_fn, grass_vk_get_instance_proc_addr_fn

_state = threading.local()
_LOD = ENUMS["grass_lod_answer"]


class Scope:
    """The problems recorded by callbacks during one binding call on this thread."""

    def __init__(self):
        self.errors = []  # (sentence, exception or None)


def enter():
    stack = getattr(_state, "stack", None)
    if stack is None:
        stack = _state.stack = []
    scope = Scope()
    stack.append(scope)
    return scope


def leave(scope):
    _state.stack.remove(scope)


def record(sentence, exception=None):
    stack = getattr(_state, "stack", None)
    if stack:
        stack[-1].errors.append((sentence, exception))
    else:  # a callback called from a raw grass.lib call: nobody to raise to
        print(f"grass: {sentence} (in a raw grass.lib call)", file=sys.stderr)


def _raised(what, e):
    record(f"{what} raised {type(e).__name__}: {short(str(e), 200)}", e)


def _address(what, value):
    if value is None:
        return None
    if isinstance(value, numbers.Integral) and not isinstance(value, bool) and 0 <= value < 2 ** 64:
        return int(value) or None
    record(f"{what} returned {short(value)}; it must return an int address or None")
    return None


def proc_loader(what, fn, fn_type):
    """A C loader (user_data, name) -> address calling fn(name: bytes) -> int or None."""
    def trampoline(user_data, name):
        try:
            return _address(what, fn(name))
        except BaseException as e:  # noqa: B036 - nothing may cross back into C
            _raised(what, e)
            return None
    return fn_type(trampoline)


def gl_loader(fn):
    return proc_loader("get_proc_address", fn, grass_gl_get_proc_address_fn)


def vk_loader(fn):
    return proc_loader("get_instance_proc_addr", fn, grass_vk_get_instance_proc_addr_fn)


# The lod test callbacks this module made, by address: create_field refuses any other (a raw
# CFUNCTYPE of a Python function would print its exception and answer garbage).
LOD_CALLBACKS = weakref.WeakValueDictionary()


def lod_callback(fn):
    """A grass_lod_test_fn calling fn(node: grass_lod_node) -> a grass_lod_answer."""
    answers = ", ".join(sorted(_LOD, key=_LOD.get))

    def trampoline(user_data, node):
        try:
            answer = fn(node.contents)
        except BaseException as e:  # noqa: B036 - nothing may cross back into C
            _raised("the lod test callback", e)
            return _LOD["GRASS_LOD_DISCARD"]
        if isinstance(answer, numbers.Integral) and not isinstance(answer, bool) and answer in _LOD.values():
            return int(answer)
        record(f"the lod test callback returned {short(answer)}; it must return one of {answers}")
        return _LOD["GRASS_LOD_DISCARD"]
    callback = grass_lod_test_fn(trampoline)
    LOD_CALLBACKS[ctypes.cast(callback, ctypes.c_void_p).value] = callback
    return callback
