"""Column-major camera matrices, as grass_view_desc takes them (pure Python)."""
import math


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
    """World-to-eye matrix looking from `eye` at `target`, right-handed, down -z."""
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(x * x for x in f))
    f = [x / n for x in f]
    s = [f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]]
    n = math.sqrt(sum(x * x for x in s))
    s = [x / n for x in s]
    u = [s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]]
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))  # noqa: E731
    return [s[0], u[0], -f[0], 0.0, s[1], u[1], -f[1], 0.0, s[2], u[2], -f[2], 0.0,
            -dot(s, eye), -dot(u, eye), dot(f, eye), 1.0]


def perspective(fovy, aspect, near, far, clip_z_zero_to_one=False):
    """Eye-to-clip matrix: GL's clip z in -1..1 (gluPerspective), or 0..1 for Vulkan."""
    f = 1.0 / math.tan(0.5 * fovy)
    m = [0.0] * 16
    m[0], m[5], m[11] = f / aspect, f, -1.0
    if clip_z_zero_to_one:
        m[10], m[14] = far / (near - far), far * near / (near - far)
    else:
        m[10], m[14] = (far + near) / (near - far), 2.0 * far * near / (near - far)
    return m
