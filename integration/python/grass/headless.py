"""An offscreen GL target for grass without a window, through ctypes on libEGL: a GL 4.5
core context on Mesa's surfaceless platform and a framebuffer with an sRGB colour
renderbuffer (grass writes linear RGB; GL_FRAMEBUFFER_SRGB encodes it) and a depth
renderbuffer. For tests, examples and servers; an engine has its own context and target.

    with grass.headless.Target(640, 360) as target:
        with grass.Context.gl(target.get_proc_address) as ctx:
            ...
            target.clear((0.45, 0.62, 0.85))
            with ctx.frame(view):
                ctx.render_gl()
            target.write_png("out.png")
"""
import ctypes
import struct
import zlib
from ctypes import CFUNCTYPE, POINTER, c_char_p, c_float, c_int, c_uint, c_void_p

from . import _checks
from ._errors import ClosedError

_EGL_PLATFORM_SURFACELESS_MESA = 0x31DD
_EGL_OPENGL_API = 0x30A2
_EGL_CONTEXT_MAJOR_VERSION, _EGL_CONTEXT_MINOR_VERSION = 0x3098, 0x30FB
_EGL_CONTEXT_OPENGL_PROFILE_MASK, _EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT = 0x30FD, 0x1
_EGL_NONE = 0x3038

GL_SRGB8_ALPHA8, GL_DEPTH_COMPONENT24 = 0x8C43, 0x81A6
GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT = 0x8CE0, 0x8D00
GL_RENDERBUFFER, GL_FRAMEBUFFER, GL_FRAMEBUFFER_COMPLETE = 0x8D41, 0x8D40, 0x8CD5
GL_FRAMEBUFFER_SRGB = 0x8DB9
GL_COLOR, GL_DEPTH = 0x1800, 0x1801
GL_RGBA, GL_UNSIGNED_BYTE = 0x1908, 0x1401
GL_MAX_RENDERBUFFER_SIZE = 0x84E8
MAX_SIZE = 16384  # checked before any EGL call; the GL's own limit is checked once it exists

_GL = {  # name -> (restype, argtypes)
    "glCreateRenderbuffers": (None, [c_int, POINTER(c_uint)]),
    "glNamedRenderbufferStorage": (None, [c_uint, c_uint, c_int, c_int]),
    "glCreateFramebuffers": (None, [c_int, POINTER(c_uint)]),
    "glNamedFramebufferRenderbuffer": (None, [c_uint, c_uint, c_uint, c_uint]),
    "glCheckNamedFramebufferStatus": (c_uint, [c_uint, c_uint]),
    "glBindFramebuffer": (None, [c_uint, c_uint]),
    "glDeleteFramebuffers": (None, [c_int, POINTER(c_uint)]),
    "glDeleteRenderbuffers": (None, [c_int, POINTER(c_uint)]),
    "glEnable": (None, [c_uint]),
    "glDisable": (None, [c_uint]),
    "glClearBufferfv": (None, [c_uint, c_int, POINTER(c_float)]),
    "glReadPixels": (None, [c_int, c_int, c_int, c_int, c_uint, c_uint, c_void_p]),
    "glFinish": (None, []),
    "glGetIntegerv": (None, [c_uint, POINTER(c_int)]),
}


class Target:
    """A current GL 4.5 core context and a bound width x height sRGB + depth framebuffer."""

    def __init__(self, width, height):
        where = "grass.headless.Target"
        self.width = _checks.integer(where, "width", width, 1, MAX_SIZE)
        self.height = _checks.integer(where, "height", height, 1, MAX_SIZE)
        self._context = None
        egl = ctypes.CDLL("libEGL.so.1")
        egl.eglGetProcAddress.restype = c_void_p
        egl.eglGetProcAddress.argtypes = [c_char_p]
        for name in ("eglInitialize", "eglBindAPI", "eglMakeCurrent", "eglDestroyContext", "eglTerminate"):
            getattr(egl, name).restype = c_uint
        egl.eglInitialize.argtypes = [c_void_p, c_void_p, c_void_p]
        egl.eglBindAPI.argtypes = [c_uint]
        egl.eglCreateContext.restype = c_void_p
        egl.eglCreateContext.argtypes = [c_void_p, c_void_p, c_void_p, POINTER(c_int)]
        egl.eglMakeCurrent.argtypes = [c_void_p, c_void_p, c_void_p, c_void_p]
        egl.eglDestroyContext.argtypes = [c_void_p, c_void_p]
        egl.eglTerminate.argtypes = [c_void_p]
        self._egl = egl
        address = egl.eglGetProcAddress(b"eglGetPlatformDisplayEXT")
        if not address:
            raise RuntimeError("EGL lacks eglGetPlatformDisplayEXT")
        get_display = CFUNCTYPE(c_void_p, c_uint, c_void_p, c_void_p)(address)
        self._display = get_display(_EGL_PLATFORM_SURFACELESS_MESA, None, None)
        if not self._display or not egl.eglInitialize(self._display, None, None) or not egl.eglBindAPI(_EGL_OPENGL_API):
            raise RuntimeError("no EGL surfaceless display with desktop GL (Mesa)")
        attributes = (c_int * 7)(_EGL_CONTEXT_MAJOR_VERSION, 4, _EGL_CONTEXT_MINOR_VERSION, 5,
                                 _EGL_CONTEXT_OPENGL_PROFILE_MASK, _EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, _EGL_NONE)
        self._context = egl.eglCreateContext(self._display, None, None, attributes)
        if not self._context or not egl.eglMakeCurrent(self._display, None, None, self._context):
            raise RuntimeError("no GL 4.5 core context through EGL surfaceless")
        self.gl = {}
        for name, (restype, argtypes) in _GL.items():
            address = egl.eglGetProcAddress(name.encode())
            if not address:
                raise RuntimeError(f"GL lacks {name}")
            self.gl[name] = CFUNCTYPE(restype, *argtypes)(address)
        gl = self.gl
        limit = c_int()
        gl["glGetIntegerv"](GL_MAX_RENDERBUFFER_SIZE, ctypes.byref(limit))
        if max(self.width, self.height) > limit.value:
            self._release()
            _checks.fail(where, "(width, height)", (self.width, self.height),
                         f"this GL's renderbuffers are at most {limit.value} texels wide and high")
        self._renderbuffers = (c_uint * 2)()
        gl["glCreateRenderbuffers"](2, self._renderbuffers)
        gl["glNamedRenderbufferStorage"](self._renderbuffers[0], GL_SRGB8_ALPHA8, self.width, self.height)
        gl["glNamedRenderbufferStorage"](self._renderbuffers[1], GL_DEPTH_COMPONENT24, self.width, self.height)
        self._framebuffer = c_uint()
        gl["glCreateFramebuffers"](1, ctypes.byref(self._framebuffer))
        fb = self._framebuffer.value
        gl["glNamedFramebufferRenderbuffer"](fb, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, self._renderbuffers[0])
        gl["glNamedFramebufferRenderbuffer"](fb, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, self._renderbuffers[1])
        if gl["glCheckNamedFramebufferStatus"](fb, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE:
            raise RuntimeError("the sRGB + depth framebuffer is incomplete")
        gl["glBindFramebuffer"](GL_FRAMEBUFFER, fb)

    def _open(self, where):
        if not self._context:
            raise ClosedError(f"grass.headless.Target.{where}: the target is closed")

    def get_proc_address(self, name):
        """The loader for grass.Context.gl: the address of a GL entry point, or None."""
        if not isinstance(name, bytes):
            _checks.fail("grass.headless.Target.get_proc_address", "name", name, "it must be bytes")
        return self._egl.eglGetProcAddress(name)

    def clear(self, color=(0.45, 0.62, 0.85), depth=1.0):
        """Clears colour (linear RGB, sRGB-encoded on the way in) and depth: before grass draws."""
        self._open("clear")
        color = _checks.vector("grass.headless.Target.clear", "color", color, 3)
        depth = _checks.real("grass.headless.Target.clear", "depth", depth)
        self.gl["glEnable"](GL_FRAMEBUFFER_SRGB)
        self.gl["glClearBufferfv"](GL_COLOR, 0, (c_float * 4)(color[0], color[1], color[2], 1.0))
        self.gl["glClearBufferfv"](GL_DEPTH, 0, (c_float * 1)(depth))

    def read_rgba(self):
        """The stored sRGB bytes, RGBA, top row first (bytes of width * height * 4)."""
        self._open("read_rgba")
        self.gl["glDisable"](GL_FRAMEBUFFER_SRGB)
        buffer = ctypes.create_string_buffer(self.width * self.height * 4)
        self.gl["glReadPixels"](0, 0, self.width, self.height, GL_RGBA, GL_UNSIGNED_BYTE, buffer)
        self.gl["glEnable"](GL_FRAMEBUFFER_SRGB)
        row = self.width * 4
        raw = buffer.raw
        return b"".join(raw[y * row:(y + 1) * row] for y in reversed(range(self.height)))

    def write_png(self, path):
        """Writes the target as an RGB PNG; returns the RGBA bytes it read."""
        rgba = self.read_rgba()
        write_png(path, self.width, self.height, rgba)
        return rgba

    def close(self):
        """Deletes the framebuffer and the GL context; nothing to do when closed already."""
        if self._context:
            self.gl["glDeleteFramebuffers"](1, ctypes.byref(self._framebuffer))
            self.gl["glDeleteRenderbuffers"](2, self._renderbuffers)
            self._release()

    def _release(self):
        if self._context:
            self._egl.eglMakeCurrent(self._display, None, None, None)
            self._egl.eglDestroyContext(self._display, self._context)
            self._context = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def write_png(path, width, height, rgba):
    """An 8-bit RGB PNG from RGBA bytes, top row first (zlib and struct only)."""
    rgb = bytearray(width * height * 3)
    for c in range(3):
        rgb[c::3] = rgba[c::4]
    row = width * 3
    raw = b"".join(b"\x00" + rgb[y * row:(y + 1) * row] for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def green_fraction(rgba):
    """The fraction of pixels whose green exceeds red and blue by more than 8: grass."""
    r, g, b = rgba[0::4], rgba[1::4], rgba[2::4]
    return sum(1 for i in range(len(g)) if g[i] > r[i] + 8 and g[i] > b[i] + 8) / len(g)
