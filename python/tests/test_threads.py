"""Renders without the GIL: Renderers in separate threads, and one Renderer shared by two."""

import threading
import time

import numpy as np
import pytest

import zraster

W, H = 160, 120
FRAMES = 12


def cameras(scene):
    return [zraster.Camera.orbit(scene, 30 * i, 10 + 5 * (i % 3), W, H) for i in range(FRAMES)]


def sequential(scene, cams):
    r = zraster.Renderer(W, H, threads=1)
    return [r.render(scene, c, outputs=("color", "depth")) for c in cams]


def same(a, b):
    return np.array_equal(a["color"], b["color"]) and np.array_equal(a["depth"], b["depth"])


def run_threads(targets):
    errors = []

    def guarded(target):
        try:
            target()
        except BaseException as e:  # reported by the main thread
            errors.append(e)

    threads = [threading.Thread(target=guarded, args=(t,)) for t in targets]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors


def test_separate_renderers_in_threads_give_the_sequential_images():
    scenes = [zraster.load("sphere:20000"), zraster.load("city:500")]
    cams = [cameras(s) for s in scenes]
    expected = [sequential(s, c) for s, c in zip(scenes, cams)]
    results = [[], []]

    def work(k):
        r = zraster.Renderer(W, H, threads=1)
        for c in cams[k]:
            results[k].append(r.render(scenes[k], c, outputs=("color", "depth")))

    run_threads([lambda: work(0), lambda: work(1)])
    for k in range(2):
        assert all(same(a, b) for a, b in zip(results[k], expected[k]))


def test_one_renderer_shared_by_two_threads_serializes():
    scene = zraster.load("sphere:20000")
    cams = cameras(scene)
    expected = sequential(scene, cams)
    shared = zraster.Renderer(W, H, threads=2)
    results = [[None] * FRAMES, [None] * FRAMES]

    def work(k):
        order = range(FRAMES) if k == 0 else reversed(range(FRAMES))
        for i in order:
            results[k][i] = shared.render(scene, cams[i], outputs=("color", "depth"))
            assert shared.stats["triangles_in"] == scene.triangle_count

    run_threads([lambda: work(0), lambda: work(1)])
    for k in range(2):
        assert all(same(a, b) for a, b in zip(results[k], expected))


def test_the_gil_is_released_while_rendering():
    # A thread that needs the GIL for a moment every millisecond keeps running during one long
    # render call; were the GIL held, it would stall until the call returned.
    scene = zraster.load("sphere:300000")
    r = zraster.Renderer(1280, 960, threads=1)
    r.render(scene)
    done = threading.Event()
    ticks = [0]

    def tick():
        while not done.is_set():
            time.sleep(0.001)
            ticks[0] += 1

    t = threading.Thread(target=tick)
    t.start()
    time.sleep(0.05)
    before, start = ticks[0], time.perf_counter()
    r.render(scene)
    after, seconds = ticks[0], time.perf_counter() - start
    done.set()
    t.join()
    if seconds < 0.03:
        pytest.skip(f"the frame took {seconds * 1e3:.1f} ms, too quick to tell")
    # Held, the GIL would allow at most the one tick already under way when the call began.
    assert after - before >= 3, (after - before, seconds)
