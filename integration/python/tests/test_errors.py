"""Every failure of the Pythonic layer is a GrassError that names the argument and its value:
nothing reaches ctypes unchecked, no buffer is read past its end, no callback hands grass a
garbage pointer, and a closed context or object says so. Calls that crashed the interpreter
run in a fresh one (conftest.run_python), so a crash fails the test instead of pytest."""
import pytest

import grass
from conftest import run_python


def overhead_view():
    return grass.view_desc(eye=(8.0, 1.6, -1.0), target=(8.0, 0.0, 8.0), size=(320, 180))


def raises(fn, *words):
    """fn() raises a GrassError whose message holds every one of `words`; returns it."""
    with pytest.raises(grass.GrassError) as e:
        fn()
    for word in words:
        assert word in str(e.value), (word, str(e.value))
    return e.value


CHECKED = """
import grass
try:
    {call}
except grass.GrassError as e:
    print("GrassError:", e)
    print("cause:", repr(e.__cause__))
else:
    print("no error")
"""


def run_checked(call, setup=""):
    result = run_python(setup + CHECKED.format(call=call))
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout


# ---- buffers -------------------------------------------------------------------------------

def test_a_short_buffer_for_a_large_map_is_refused_not_read():
    out = run_checked('grass.Context().create_map(b"\\x01" * 10, width=4096, height=4096)')
    assert "GrassError:" in out and "pixels" in out and "10 bytes" in out and "16777216" in out, out


def test_a_slightly_short_buffer_is_refused():
    with grass.Context() as ctx:
        raises(lambda: ctx.create_map(b"\x01" * 10, width=4, height=4), "pixels", "10 bytes", "16")
        raises(lambda: ctx.create_map(b"\x01" * 17, width=4, height=4), "17 bytes")
        raises(lambda: ctx.create_map(bytearray(64), width=4, height=4, format=grass.GRASS_MAP_FORMAT_RGBA16_UNORM),
               "64 bytes", "128")
        raises(lambda: ctx.create_map(b"\x01" * 16, width=4, height=4, row_pitch=8), "16 bytes", "28")
        ctx.create_map(b"\x01" * 28, width=4, height=4, row_pitch=8).destroy()
        ctx.create_map(memoryview(bytearray(16)), width=4, height=4).destroy()
        raises(lambda: ctx.create_map(memoryview(bytearray(32))[::2], width=4, height=4), "contiguous")
        raises(lambda: ctx.create_map("abcd", width=2, height=2), "pixels", "'abcd'")
        raises(lambda: ctx.create_map(b"\x01" * 4, width=-2, height=-2), "width", "-2")
        raises(lambda: ctx.create_map(b"\x01" * 4), "width")


def test_numpy_arrays_are_checked_for_dtype_shape_and_layout():
    np = pytest.importorskip("numpy")
    with grass.Context() as ctx:
        raises(lambda: ctx.create_map(np.zeros(16, np.uint8)), "pixels", "(16,)")
        raises(lambda: ctx.create_map(np.zeros((4, 4), np.int64)), "int64")
        raises(lambda: ctx.create_map(np.zeros((4, 4, 3), np.uint8)), "(4, 4, 3)")
        raises(lambda: ctx.create_map(np.zeros((0, 4), np.uint8)), "(0, 4)")
        raises(lambda: ctx.create_map(np.zeros((4, 4), np.uint8), format=grass.GRASS_MAP_FORMAT_R32_FLOAT), "format")
        raises(lambda: ctx.create_map(np.zeros((4, 4), np.uint8), width=8), "width", "8")
        patch = ctx.create_patch()
        raises(lambda: ctx.create_field(patch, cells_x=8, cells_z=8, density_map=np.ones(8, np.uint8)),
               "density_map", "(8,)")
        # A strided view is copied, not read as if it were packed: every other column is bare.
        full = np.full((16, 32), 255, np.uint8)
        full[:, 1::2] = 0
        drawn = []
        for pixels in (full[:, 0::2], np.ascontiguousarray(full[:, 0::2]), full[:, 1::2]):
            with ctx.create_map(pixels) as density:
                assert (density.width, density.height) == (16, 16)
                with ctx.create_field(patch, cells_x=64, cells_z=64, maps={"density": density}):
                    with ctx.frame(overhead_view()):
                        pass
                    drawn.append(ctx.frame_stats().blades_drawn)
        assert drawn[0] == drawn[1] > 0 == drawn[2]


def test_map_updates_check_their_region_and_buffer():
    with grass.Context() as ctx:
        with ctx.create_map(b"\xff" * 64, width=8, height=8) as m:
            raises(lambda: m.update(0, 0, b"\x00" * 3, width=2, height=2), "3 bytes", "4")
            raises(lambda: m.update(-1, 0, b"\x00" * 4, width=2, height=2), "x", "-1")
            raises(lambda: m.update(7, 7, b"\x00" * 4, width=2, height=2), "(7, 7)")
            raises(lambda: m.update(2 ** 32 - 1, 0, b"\x00" * 4, width=2, height=2), "4294967295")
            m.update(6, 6, b"\x00" * 4, width=2, height=2)


# ---- callbacks -----------------------------------------------------------------------------

def test_a_missing_gl_loader_is_refused():
    out = run_checked("grass.Context.gl(None)")
    assert "GrassError:" in out and "get_proc_address" in out and "None" in out, out


def test_a_gl_loader_that_raises_becomes_a_grass_error():
    out = run_checked("grass.Context.gl(loader)", setup="def loader(name):\n    raise KeyError(name)\n")
    assert "GrassError:" in out and "get_proc_address raised KeyError" in out and "cause: KeyError" in out, out
    out = run_checked("grass.Context.gl(lambda name: 'glFoo')")
    assert "GrassError:" in out and "'glFoo'" in out, out


def test_a_log_function_that_raises_becomes_a_grass_error_and_leaves_nothing_behind():
    def log(level, message_id, text):
        if message_id == grass.GRASS_MSG_PATCH_GENERATED:
            raise RuntimeError("log full")

    with grass.Context(log=log, log_level=grass.GRASS_LOG_INFO) as ctx:
        e = raises(lambda: ctx.create_patch(blade_count=64), "log raised RuntimeError", "log full")
        assert isinstance(e.__cause__, RuntimeError)
        assert ctx.memory_stats().host_bytes > 0
        before = ctx.memory_stats().host_allocations
        raises(lambda: ctx.create_patch(blade_count=64), "log full")
        assert ctx.memory_stats().host_allocations == before  # the patch made was destroyed


def test_a_lod_callback_that_raises_or_answers_nonsense_becomes_a_grass_error():
    def boom(node):
        raise ValueError("no such node")

    with grass.Context() as ctx:
        patch = ctx.create_patch()
        tier = grass.grass_tier_desc(kind=grass.GRASS_TIER_GEOMETRY)
        for fn, words in ((boom, ("lod test callback raised ValueError", "no such node")),
                          (lambda node: "draw", ("'draw'", "GRASS_LOD_")), (lambda node: 7, ("7",))):
            test = grass.lod_test(fn, tier=0)
            with ctx.create_field(patch, cells_x=16, cells_z=16, tiers=[tier], lod_tests=[test]):
                raises(lambda: ctx.begin_frame(overhead_view()), *words)
                ctx.end_frame()
        raw = grass.grass_lod_test(kind=grass.GRASS_LOD_TEST_CALLBACK, callback=grass.grass_lod_test_fn(boom))
        raises(lambda: ctx.create_field(patch, cells_x=16, cells_z=16, tiers=[tier], lod_tests=[raw]),
               "lod_tests[0].callback", "grass.lod_test")


# ---- arguments -----------------------------------------------------------------------------

def test_arguments_are_checked_before_ctypes_converts_them():
    with grass.Context() as ctx:
        patch = ctx.create_patch()
        e = raises(lambda: ctx.create_field(patch, cells_x=-5, cells_z=4), "cells_x", "-5")
        assert "4.29497e+09" not in str(e) and "4294967291" not in str(e)
        raises(lambda: ctx.create_field(patch, cells_x="8", cells_z=4), "cells_x", "'8'")
        raises(lambda: ctx.create_field(patch, cells_x=8, cells_z=4, density=1e40), "density", "1e+40")
        raises(lambda: ctx.create_field(patch, cells_x=8, cells_z=4, tiers=[3]), "tiers[0]", "3")
        raises(lambda: ctx.create_field(patch, cells_x=8, cells_z=4, maps={"hue": 1}), "maps", "'hue'")
        raises(lambda: ctx.create_field(object(), cells_x=8, cells_z=4), "patch")
        raises(lambda: ctx.create_patch(blade_count=2 ** 40), "blade_count", "1099511627776")
        raises(lambda: ctx.create_patch(root_color=(1, 2)), "root_color", "3 values")
        raises(lambda: ctx.create_patch(next=12345), "next")
        raises(lambda: grass.patch_desc(blade_cuont=3), "blade_cuont")
        raises(lambda: ctx.begin_frame(None), "view", "None")
        raises(lambda: ctx.apply_quality(17, 0.25), "quality", "17")
        raises(lambda: ctx.apply_quality(grass.GRASS_QUALITY_LOW, "a"), "cell_size", "'a'")
        raises(lambda: grass.Context(log_level=99), "log_level", "99")
        raises(lambda: grass.Context(log=3), "log", "3")
        raises(lambda: ctx.vk_record(None), "command_buffer", "None")


def test_the_04_name_of_vk_prepare_warns_and_calls_it():
    """grass_vk_prepare_frame became grass_vk_prepare (a desc) in 0.5: Context.vk_prepare_frame
    still works, with a DeprecationWarning, and reaches grass_vk_prepare (here refused: the
    context is no Vulkan context)."""
    with grass.Context() as ctx:
        e = raises(lambda: ctx.vk_prepare(1), "grass_vk_prepare")
        assert e.message_id == grass.MessageId.GRASS_MSG_WRONG_BACKEND
        with pytest.warns(DeprecationWarning, match="vk_prepare_frame was renamed"):
            raises(lambda: ctx.vk_prepare_frame(1), "grass_vk_prepare")
        raises(lambda: ctx.vk_prepare(None), "command_buffer", "None")


def test_the_development_name_of_collider_center_warns_and_is_center():
    """grass_collider.centre became center in 0.5 (as grass_lod_node.center): the old name is
    the same storage, read, written and as a constructor keyword, with a DeprecationWarning."""
    c = grass.grass_collider()
    with pytest.warns(DeprecationWarning, match="centre was renamed center"):
        c.centre[:] = (1.0, 2.0, 3.0)
    assert list(c.center) == [1.0, 2.0, 3.0]
    with pytest.warns(DeprecationWarning, match="centre was renamed center"):
        c = grass.grass_collider(shape=grass.GRASS_COLLIDER_SPHERE, centre=(4.0, 5.0, 6.0))
    assert list(c.center) == [4.0, 5.0, 6.0]
    with pytest.warns(DeprecationWarning, match="centre was renamed center"):
        assert list(c.centre) == [4.0, 5.0, 6.0]


def test_cameras_that_cannot_be_built_are_refused():
    raises(lambda: grass.view_desc(eye=(1, 2, 3), target=(1, 2, 3), size=(64, 64)), "eye", "target", "(1, 2, 3)")
    raises(lambda: grass.view_desc(eye=(0, 10, 0), target=(0, 0, 0), size=(64, 64)), "up")
    raises(lambda: grass.view_desc(eye=(0, 1, 0), target=(0, 0, 5), size=(0, 0)), "size", "(0, 0)")
    raises(lambda: grass.view_desc(eye=(0, 1, 0), target=(0, 0, 5), size=(64, 64), near=0), "near", "0")
    raises(lambda: grass.view_desc(eye=(0, 1), target=(0, 0, 5)), "eye", "(0, 1)")
    raises(lambda: grass.view_desc(eye=(0, 1, 0)), "target", "None")
    raises(lambda: grass.view_desc(eye=(0, float("nan"), 0), target=(0, 0, 5)), "eye", "nan")
    raises(lambda: grass.look_at((0, 0, 0), (0, 0, 0)), "eye", "target")
    raises(lambda: grass.perspective(0.9, 0, 0.1, 10), "aspect", "0")


def test_a_headless_target_of_a_bad_size_is_refused_before_gl():
    import grass.headless
    raises(lambda: grass.headless.Target(-1, 64), "width", "-1")
    raises(lambda: grass.headless.Target(64, 10 ** 6), "height", "1000000")
    raises(lambda: grass.headless.Target(64.5, 64), "width", "64.5")


# ---- closed contexts and objects ---------------------------------------------------------

def test_a_closed_context_or_object_says_so():
    ctx = grass.Context()
    patch = ctx.create_patch(blade_count=16)
    patch.destroy()
    raises(patch.info, "Patch", "destroyed")
    field_patch = ctx.create_patch(blade_count=16)
    ctx.destroy()
    for call in (ctx.create_patch, lambda: ctx.backend, lambda: ctx.last_error, ctx.end_frame,
                 lambda: ctx.begin_frame(overhead_view()), ctx.frame_stats, field_patch.info):
        e = raises(call, "closed")
        assert e.result == grass.Result.GRASS_ERROR_INVALID_HANDLE
    field_patch.destroy()  # its context destroyed it already: nothing to do
    ctx.destroy()


def test_a_grass_error_is_still_a_value_error_for_bad_arguments():
    with grass.Context() as ctx:
        with pytest.raises(ValueError):
            ctx.create_patch(blade_count=-1)
        with pytest.raises(TypeError):
            ctx.begin_frame("view")
