"""Column-major camera matrices, as grass_view_desc takes them (pure Python). A camera that
cannot be built (eye at the target, up along the view, a zero aspect) is an ArgumentError."""
import math

from . import _checks


def look_at(eye, target, up=(0.0, 1.0, 0.0), where="grass.look_at"):
    """World-to-eye matrix looking from `eye` at `target`, right-handed, down -z."""
    given = (eye, target, up)
    eye = _checks.vector(where, "eye", eye, 3)
    target = _checks.vector(where, "target", target, 3)
    up = _checks.vector(where, "up", up, 3)
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(x * x for x in f))
    if not n > 0 or not math.isfinite(n):
        _checks.fail(where, "eye", given[0], f"it must differ from target {_checks.short(given[1])} (a view direction)",
                     _checks._MSG["GRASS_MSG_ZERO_VECTOR"])
    f = [x / n for x in f]
    s = [f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]]
    n = math.sqrt(sum(x * x for x in s))
    if not n > 1e-9 * math.sqrt(sum(x * x for x in up)) or not math.isfinite(n):
        _checks.fail(where, "up", given[2], f"it must not be parallel to the view direction {tuple(f)} (pass "
                     "another up)", _checks._MSG["GRASS_MSG_ZERO_VECTOR"])
    s = [x / n for x in s]
    u = [s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]]
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))  # noqa: E731
    return [s[0], u[0], -f[0], 0.0, s[1], u[1], -f[1], 0.0, s[2], u[2], -f[2], 0.0,
            -dot(s, eye), -dot(u, eye), dot(f, eye), 1.0]


def perspective(fovy, aspect, near, far, clip_z_zero_to_one=False, where="grass.perspective"):
    """Eye-to-clip matrix: GL's clip z in -1..1 (gluPerspective), or 0..1 for Vulkan."""
    fovy = _checks.real(where, "fovy", fovy, low=0.0, low_open=True)
    if fovy >= math.pi:
        _checks.fail(where, "fovy", fovy, "it must be below pi radians")
    aspect = _checks.real(where, "aspect", aspect, low=0.0, low_open=True)
    near = _checks.real(where, "near", near, low=0.0, low_open=True)
    far = _checks.real(where, "far", far)
    if not far > near:
        _checks.fail(where, "far", far, f"it must be greater than near ({near})")
    f = 1.0 / math.tan(0.5 * fovy)
    m = [0.0] * 16
    m[0], m[5], m[11] = f / aspect, f, -1.0
    if clip_z_zero_to_one:
        m[10], m[14] = far / (near - far), far * near / (near - far)
    else:
        m[10], m[14] = (far + near) / (near - far), 2.0 * far * near / (near - far)
    return m
