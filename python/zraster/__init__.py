"""zraster: an exact, fast CPU rasterizer for Python.

Scenes come from files or procedural specs (``load``) or from numpy arrays (``Mesh``, with
an optional texture and alpha), mixed in a ``Scene``; a ``Renderer`` draws them into numpy
arrays: color, depth, normals and ids.

    import zraster
    scene = zraster.load("bunny.obj")
    out = zraster.Renderer(640, 480).render(scene, outputs=("color", "depth"))
    out["color"]   # (480, 640, 3) uint8, row 0 at the top
    out["depth"]   # (480, 640) float32 window depth, 1.0 where empty

A depth camera: ``outputs=("z", "range")`` give metric depth and distance (0 where empty),
``sensor="kinect"`` measures them as a structured-light sensor would, and
``unproject(out["z"], camera)`` turns z into a point cloud.

The render keywords are the flags of ``zraster render`` (``help(zraster.Renderer.render)``).
"""

import os as _os

from . import _zraster
from ._zraster import (
    RENDER_OPTIONS,
    Camera,
    InputError,
    LimitExceeded,
    LoadWarning,
    Material,
    Mesh,
    Renderer,
    Scene,
    StructuredLightSensor,
    __version__,
    load,
    unproject,
)

from ._arguments import one_line_type_errors as _one_line_type_errors
from ._arguments import wrap_class as _wrap_class

# One-line TypeErrors for calls that match no signature (see _arguments.py).
for _cls in (Camera, Material, Mesh, Renderer, Scene, StructuredLightSensor):
    _wrap_class(_cls)
load = _one_line_type_errors(load)
unproject = _one_line_type_errors(unproject)

__all__ = [
    "Camera",
    "InputError",
    "LimitExceeded",
    "LoadWarning",
    "Material",
    "Mesh",
    "RENDER_OPTIONS",
    "Renderer",
    "Scene",
    "StructuredLightSensor",
    "__version__",
    "load",
    "render",
    "unproject",
]


def render(scene, width=1920, height=1080, *, camera=None, outputs=("color", "depth"),
           sensor=None, threads=0, isolation="worker", **options):
    """Renders one frame: ``Renderer(width, height, threads).render(scene, camera, outputs,
    sensor, **options)``, loading ``scene`` first when it is a path or a procedural spec (with
    ``isolation``, as ``load``). Returns {output name: numpy array}.

    For many frames keep a Renderer instead: it reuses its memory and threads. The sizes default
    to the command's (1920x1080).
    """
    if isinstance(scene, (str, _os.PathLike)):
        scene = load(scene, isolation=isolation)
    return Renderer(width, height, threads).render(scene, camera, outputs, sensor, **options)


render.__doc__ += ("\n    Options (the flags of `zraster render`, as for Renderer.render):\n\n"
                   + _zraster._render_options_doc)
