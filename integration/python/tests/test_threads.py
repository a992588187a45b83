"""Threads, as grass.h promises them: a context is externally synchronised, separate contexts
are independent. The binding serialises each context's calls with its own lock, so two
threads sharing a context never overlap inside the library, and each call's error is the one
its own call logged."""
import threading
import time

import pytest

import grass


def overhead_view():
    return grass.view_desc(eye=(8.0, 1.6, -1.0), target=(8.0, 0.0, 8.0), size=(320, 180))


def run_threads(*targets, seconds=1.5):
    """Runs each target(stop_event) in its own thread for `seconds`; returns what they raised."""
    stop, errors = threading.Event(), []

    def guard(target):
        try:
            target(stop)
        except BaseException as e:  # noqa: B036 - any escape is a failure, reported below
            errors.append(e)
            stop.set()
    threads = [threading.Thread(target=guard, args=(t,)) for t in targets]
    for t in threads:
        t.start()
    time.sleep(seconds)
    stop.set()
    for t in threads:
        t.join(60)
    return errors


def test_one_context_shared_by_two_threads_is_serialised_and_errors_stay_with_their_call():
    with grass.Context() as ctx:
        patch = ctx.create_patch(blade_count=256)
        counts = {"frames": 0, "refused": 0}

        def plan(stop):  # valid frames and objects: must never fail
            while not stop.is_set():
                with ctx.create_field(patch, cells_x=96, cells_z=96):
                    with ctx.frame(overhead_view()):  # holds the context for the whole frame
                        pass
                    assert ctx.frame_stats().blades_drawn > 0
                assert ctx.last_error == ""  # per thread: never the other thread's message
                counts["frames"] += 1

        def misuse(stop):  # invalid calls: must fail with their own message, every time
            while not stop.is_set():
                with pytest.raises(grass.GrassError) as e:
                    ctx.create_field(patch, cells_x=0, cells_z=4)
                assert e.value.message_id == grass.MessageId.GRASS_MSG_ZERO_CELLS, e.value
                assert "cells_x" in e.value.message, e.value
                assert ctx.last_error == e.value.message
                counts["refused"] += 1

        errors = run_threads(plan, misuse, plan)
        assert not errors, errors[0]
        assert counts["frames"] > 0 and counts["refused"] > 0, counts


def test_separate_contexts_in_separate_threads_are_independent():
    results = {}

    def own_context(stop, key):
        with grass.Context() as ctx:
            field = ctx.create_field(ctx.create_patch(blade_count=128), cells_x=48, cells_z=48)
            first = None
            while not stop.is_set():
                with ctx.frame(overhead_view()):
                    pass
                drawn = ctx.frame_stats().blades_drawn
                assert first is None or drawn == first  # the same plan every frame
                first = drawn
            field.destroy()
            results[key] = first

    errors = run_threads(lambda s: own_context(s, "a"), lambda s: own_context(s, "b"), seconds=1.0)
    assert not errors, errors[0]
    assert results["a"] == results["b"] > 0


def test_a_callback_calling_back_into_its_context_is_refused():
    with grass.Context() as ctx:
        patch = ctx.create_patch()

        def reenter(node):
            ctx.create_patch()
            return grass.GRASS_LOD_DRAW
        tier = grass.grass_tier_desc(kind=grass.GRASS_TIER_GEOMETRY)
        with ctx.create_field(patch, cells_x=64, cells_z=64, tiers=[tier], lod_tests=[grass.lod_test(reenter)]):
            with pytest.raises(grass.GrassError) as e:
                ctx.begin_frame(overhead_view())
            assert "inside" in str(e.value) and "callback" in str(e.value)
            ctx.end_frame()


def test_render_gl_from_a_thread_without_the_gl_context_is_refused():
    import grass.headless
    with grass.headless.Target(64, 64) as target:
        with grass.Context.gl(target.get_proc_address) as ctx:
            ctx.create_field(ctx.create_patch(blade_count=64), cells_x=16, cells_z=16)
            outcome = []

            def other_thread():
                try:
                    with ctx.frame(overhead_view()):
                        ctx.render_gl()
                    outcome.append("rendered")
                except grass.GrassError as e:
                    outcome.append(e)
            t = threading.Thread(target=other_thread)
            t.start()
            t.join(60)
            assert isinstance(outcome[0], grass.GrassError), outcome
            assert "GRASS_MSG_GL_CONTEXT_NOT_CURRENT" in str(outcome[0]), outcome
            with ctx.frame(overhead_view()):  # the owning thread still renders
                ctx.render_gl()
