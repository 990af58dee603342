#!/usr/bin/env python3
"""A depth camera with the zraster module: OpenCV intrinsics, metric depth as an ideal camera
and as a Kinect-style sensor sees it, and the point cloud, saved as .npy files.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/depth_camera.py [SCENE] [OUT_PREFIX]

SCENE is a mesh file or a procedural spec (default: builtin:default). Writes OUT_PREFIX-z.npy
(ideal metric depth, 0 where empty), OUT_PREFIX-kinect-z.npy (as the sensor measures it) and
OUT_PREFIX-points.npy ((N, 3) float32 world points of the sensor's pixels).
"""

import sys

import numpy as np

import zraster


def main():
    spec = sys.argv[1] if len(sys.argv) > 1 else "builtin:default"
    prefix = sys.argv[2] if len(sys.argv) > 2 else "depth-camera"
    scene = zraster.load(spec)
    width, height = 640, 480
    # A Kinect-like pinhole (525 px focal length) placed where the command's default camera is.
    pose = zraster.Camera.fit(scene, width, height).camera_to_world()  # OpenCV axes
    bounds_min, bounds_max = scene.bounds
    far = 4.0 * float(np.linalg.norm(np.asarray(bounds_max) - np.asarray(bounds_min))) + 1.0
    camera = zraster.Camera.from_intrinsics(525.0, 525.0, 319.5, 239.5, width, height,
                                            0.05, far, pose=pose)
    renderer = zraster.Renderer(width, height)
    ideal = renderer.render(scene, camera, ("z", "range"))
    # The default scene is tens of units across: a sensor that measures that far, with noise.
    sensor = zraster.StructuredLightSensor(max_range=far, noise=0.2, seed=1)
    measured = renderer.render(scene, camera, "z", sensor=sensor)["z"]
    points = zraster.unproject(measured, camera)
    np.save(f"{prefix}-z.npy", ideal["z"])
    np.save(f"{prefix}-kinect-z.npy", measured)
    np.save(f"{prefix}-points.npy", points)
    seen = ideal["z"] > 0
    print(f"{spec}: {seen.sum()} pixels see a surface, z {ideal['z'][seen].min():.3f} to "
          f"{ideal['z'][seen].max():.3f}; the sensor measures {(measured > 0).sum()} of them; "
          f"{len(points)} points")


if __name__ == "__main__":
    main()
