"""Materials' sides from Python: glTF doubleSided as zraster.Material.double_sided, and a
double-sided plane seen from behind drawn where a single-sided one is culled."""

import numpy as np

import zraster
from model_files import plane_grid, write_gltf

W, H = 96, 72
BEHIND = zraster.Camera.look_at((0.2, -0.1, -1.5), (0, 0, 0), fovy=50.0)


def test_double_sided_materials_are_drawn_from_behind(tmp_path):
    positions, faces, normals, _ = plane_grid()
    plane = {"positions": positions, "faces": faces, "normals": normals,
             "color": (1, 0.5, 0.25, 1)}
    double = zraster.load(write_gltf(tmp_path, "double", [dict(plane, double_sided=True)]))
    single = zraster.load(write_gltf(tmp_path, "single", [dict(plane, double_sided=False)]))
    unsaid = zraster.load(write_gltf(tmp_path, "unsaid", [plane]))
    assert double.materials[1].double_sided
    assert "double-sided" in repr(double.materials[1])
    assert not single.materials[1].double_sided and not unsaid.materials[1].double_sided

    def covered(scene):
        frame = zraster.Renderer(W, H).render(scene, BEHIND, outputs=("instance_id",))
        return int(np.count_nonzero(frame["instance_id"] >= 0))

    assert covered(single) == 0 and covered(unsaid) == 0
    assert covered(double) > W * H // 4
