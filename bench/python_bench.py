"""What the Python module costs over the C++ Renderer, and how Renderers scale over threads.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py [MESH] [--frames N]

MESH defaults to ../shared/data/meshes/obj/bunny.obj (the bunny of BENCHMARKS.md), else the
procedural sphere:70000. Prints, for 640x480 frames:
  - the median wall time of Renderer.render per frame (color + depth, Phong, 2 threads), the
    median time the C++ Renderer took inside it (Renderer.stats["total_ms"]) and their ratio;
  - the same with every output (color, depth, z, range, normals, ids), and with each alone;
  - frames per second of one thread running one single-threaded Renderer, and of two Python
    threads each running its own (the GIL is released while a frame renders), and their ratio.
"""

import argparse
import pathlib
import statistics
import threading
import time

import zraster

ROOT = pathlib.Path(__file__).resolve().parents[1]


def frame_times(renderer, scene, camera, frames, outputs):
    wall, inside = [], []
    renderer.render(scene, camera, outputs)  # first frame: allocations, cluster bounds
    for _ in range(frames):
        start = time.perf_counter()
        renderer.render(scene, camera, outputs)
        wall.append((time.perf_counter() - start) * 1e3)
        inside.append(renderer.stats["total_ms"])
    return statistics.median(wall), statistics.median(inside)


def frames_per_second(scene, threads, seconds=3.0):
    counts = [0] * threads
    stop = time.perf_counter() + seconds

    camera = zraster.Camera.fit(scene, 640, 480)

    def run(k):
        renderer = zraster.Renderer(640, 480, threads=1)
        renderer.render(scene, camera, ("color", "depth"))
        while time.perf_counter() < stop:
            renderer.render(scene, camera, ("color", "depth"))
            counts[k] += 1

    workers = [threading.Thread(target=run, args=(k,)) for k in range(threads)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    return sum(counts) / seconds


def main():
    parser = argparse.ArgumentParser()
    default = ROOT.parent / "shared" / "data" / "meshes" / "obj" / "bunny.obj"
    parser.add_argument("mesh", nargs="?", default=str(default) if default.is_file()
                        else "sphere:70000")
    parser.add_argument("--frames", type=int, default=200)
    args = parser.parse_args()
    scene = zraster.load(args.mesh)
    print(f"{args.mesh}: {scene.triangle_count} triangles, 640x480, Phong")
    renderer = zraster.Renderer(640, 480, threads=2)
    # One camera for every frame, as a render loop holds it (camera=None fits the scene's
    # bounding sphere anew each call).
    camera = zraster.Camera.fit(scene, 640, 480)
    for outputs in (("color", "depth"),
                    ("color", "depth", "z", "range", "normal", "instance_id", "primitive_id")):
        wall, inside = frame_times(renderer, scene, camera, args.frames, outputs)
        print(f"  {'+'.join(outputs)}: {wall:.3f} ms per call, C++ Renderer {inside:.3f} ms "
              f"inside it: overhead {wall - inside:.3f} ms ({(wall / inside - 1) * 100:.1f}%)")
    for output in ("color", "depth", "instance_id", "z", "range", "normal"):
        wall, inside = frame_times(renderer, scene, camera, args.frames, (output,))
        print(f"  {output} alone: {wall:.3f} ms per call, C++ Renderer {inside:.3f} ms")
    one = frames_per_second(scene, 1)
    two = frames_per_second(scene, 2)
    print(f"  one thread, one Renderer(threads=1): {one:.1f} frames/s; two threads with a "
          f"Renderer each: {two:.1f} frames/s ({two / one:.2f}x)")


if __name__ == "__main__":
    main()
