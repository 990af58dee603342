# Type stubs of the zraster package (the compiled zraster._zraster and zraster/__init__.py).
import os
from typing import Literal, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str
RENDER_OPTIONS: tuple[str, ...]

ArrayLike = npt.ArrayLike
Vec3 = Union[str, Sequence[float], npt.NDArray[np.floating]]
Vec4 = Union[str, Sequence[float], npt.NDArray[np.floating]]
OutputName = Literal[
    "color", "rgba", "depth", "z", "range", "normal", "instance_id", "primitive_id"
]

class InputError(ValueError):
    source: str
    cause: str

class LimitExceeded(InputError):
    limit: str

class LoadWarning(UserWarning): ...

AlphaMode = Literal["opaque", "mask", "blend"]

class Material:
    @property
    def name(self) -> str: ...
    @property
    def base_color(self) -> tuple[float, float, float]: ...
    @property
    def opacity(self) -> float: ...
    @property
    def alpha_mode(self) -> AlphaMode: ...
    @property
    def alpha_cutoff(self) -> float: ...
    @property
    def has_texture(self) -> bool: ...
    @property
    def has_opacity_texture(self) -> bool: ...
    @property
    def texture_size(self) -> tuple[int, int] | None: ...
    @property
    def translucent_texture(self) -> bool: ...
    @property
    def ambient(self) -> float: ...
    @property
    def diffuse(self) -> float: ...
    @property
    def specular(self) -> tuple[float, float, float]: ...
    @property
    def shininess(self) -> float: ...

class Mesh:
    def __init__(
        self,
        positions: ArrayLike,
        indices: ArrayLike,
        normals: ArrayLike | None = None,
        uvs: ArrayLike | None = None,
        color: Sequence[float] | None = None,
        name: str = "",
        texture: npt.NDArray[np.uint8] | npt.NDArray[np.floating] | None = None,
        alpha_mode: AlphaMode | None = None,
        alpha_cutoff: float | None = None,
        colors: ArrayLike | None = None,
        double_sided: bool | None = None,
    ) -> None: ...
    @staticmethod
    def uv_sphere(
        radius: float = 1.0, stacks: int = 32, slices: int = 64, color: Sequence[float] | None = None
    ) -> Mesh: ...
    @staticmethod
    def box(half_extent: Sequence[float] = (0.5, 0.5, 0.5), color: Sequence[float] | None = None) -> Mesh: ...
    @property
    def positions(self) -> npt.NDArray[np.float32]: ...
    @property
    def indices(self) -> npt.NDArray[np.integer]: ...
    @property
    def normals(self) -> npt.NDArray[np.float32] | None: ...
    @property
    def uvs(self) -> npt.NDArray[np.float32] | None: ...
    @property
    def colors(self) -> npt.NDArray[np.float32] | None: ...
    @property
    def color(self) -> tuple[float, float, float, float] | None: ...
    @property
    def material(self) -> Material | None: ...
    @property
    def texture(self) -> npt.NDArray[np.uint8] | None: ...
    @property
    def name(self) -> str: ...
    @property
    def copied(self) -> dict[str, bool]: ...
    @property
    def computed_normals(self) -> bool: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def triangle_count(self) -> int: ...

class Scene:
    def __init__(
        self, items: Sequence[Mesh | Scene | tuple[Mesh | Scene, ArrayLike]]
    ) -> None: ...
    def __len__(self) -> int: ...
    @property
    def triangle_count(self) -> int: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def bounds(self) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    @property
    def source(self) -> str: ...
    @property
    def materials(self) -> list[Material]: ...
    @property
    def warnings(self) -> list[str]: ...

def load(
    path: str | os.PathLike[str],
    isolation: Literal["worker", "in-process"] = "worker",
    allow_outside_references: bool = False,
    max_instances: int = 1000000,
    max_triangles: int = 50000000,
    max_texture_side: int = 8192,
    max_texture_bytes: int | str = 536870912,
    max_geometry_bytes: int | str = 1073741824,
    max_triangulation_work: int = 268435456,
    max_materials: int = 20000,
) -> Scene: ...

class Camera:
    @staticmethod
    def fit(scene: Scene | Mesh, width: int, height: int) -> Camera: ...
    @staticmethod
    def orbit(
        scene: Scene | Mesh, azimuth: float, elevation: float, width: int, height: int, distance: float = 2.0
    ) -> Camera: ...
    @staticmethod
    def look_at(
        eye: ArrayLike,
        target: ArrayLike,
        up: ArrayLike = (0.0, 1.0, 0.0),
        fovy: float = 60.0,
        near: float = 0.1,
        far: float = 100.0,
        reversed_z: bool = False,
        infinite_far: bool = False,
        ortho_height: float | None = None,
    ) -> Camera: ...
    @staticmethod
    def from_intrinsics(
        fx: float,
        fy: float,
        cx: float,
        cy: float,
        width: int,
        height: int,
        near: float = 0.1,
        far: float = 100.0,
        pose: ArrayLike | None = None,
        convention: Literal["opencv", "opengl"] = "opencv",
    ) -> Camera: ...
    @staticmethod
    def from_matrices(
        view: ArrayLike,
        projection: ArrayLike,
        depth_range: Literal["-1..1", "0..1"] = "-1..1",
        reversed_z: bool = False,
    ) -> Camera: ...
    @property
    def eye(self) -> npt.NDArray[np.float64]: ...
    @property
    def target(self) -> npt.NDArray[np.float64]: ...
    @property
    def up(self) -> npt.NDArray[np.float64]: ...
    @property
    def view_direction(self) -> npt.NDArray[np.float64]: ...
    @property
    def fovy(self) -> float: ...
    @property
    def near(self) -> float: ...
    @property
    def far(self) -> float: ...
    @property
    def reversed_z(self) -> bool: ...
    @property
    def infinite_far(self) -> bool: ...
    @property
    def orthographic(self) -> bool: ...
    @property
    def ortho_height(self) -> float: ...
    def view_matrix(self) -> npt.NDArray[np.float64]: ...
    def projection_matrix(self, width: int, height: int) -> npt.NDArray[np.float64]: ...
    def intrinsics(
        self, width: int, height: int, convention: Literal["opencv", "opengl"] = "opencv"
    ) -> dict[str, float]: ...
    def camera_to_world(self, convention: Literal["opencv", "opengl"] = "opencv") -> npt.NDArray[np.float64]: ...

class StructuredLightSensor:
    def __init__(
        self,
        baseline: float = 0.075,
        disparity_step: float = 0.125,
        min_range: float = 0.5,
        max_range: float = 4.5,
        max_incidence: float = 75.0,
        noise: float = 0.0,
        seed: int = 0,
    ) -> None: ...
    @property
    def baseline(self) -> float: ...
    @property
    def disparity_step(self) -> float: ...
    @property
    def min_range(self) -> float: ...
    @property
    def max_range(self) -> float: ...
    @property
    def max_incidence(self) -> float: ...
    @property
    def noise(self) -> float: ...
    @property
    def seed(self) -> int: ...

Sensor = Union[None, Literal["ideal", "kinect"], StructuredLightSensor]

def unproject(z: npt.NDArray[np.floating], camera: Camera) -> npt.NDArray[np.float32]: ...

class Renderer:
    def __init__(self, width: int, height: int, threads: int = 0, max_pixels: int | None = None) -> None: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def threads(self) -> int: ...
    @property
    def stats(self) -> dict[str, float | int | bool | str] | None: ...
    # The keywords are the flags of `zraster render` (RENDER_OPTIONS, in its order).
    def render(
        self,
        scene: Scene | Mesh,
        camera: Camera | None = None,
        outputs: OutputName | Sequence[OutputName] = ("color", "depth"),
        sensor: Sensor = None,
        *,
        max_bin_bytes: int = ...,
        max_covered_samples: int = ...,
        max_frame_bytes: int | str = ...,
        eye: Vec3 = ...,
        target: Vec3 = ...,
        up: Vec3 = ...,
        orbit: Vec3 = ...,
        fovy: float = ...,
        near: float = ...,
        far: float = ...,
        ortho: bool = ...,
        ortho_height: float = ...,
        reversed_z: bool = ...,
        infinite_far: bool = ...,
        shading: Literal["flat", "gouraud", "phong", "unlit"] = ...,
        reflection: Literal["blinn-phong", "phong"] = ...,
        infinite_viewer: bool = ...,
        light_dir: Vec3 | Sequence[Vec3] = ...,
        point_light: Vec3 | Sequence[Vec3] = ...,
        cull: Literal["back", "front", "none"] = ...,
        no_cull: bool = ...,
        occlusion_cull: bool = ...,
        portal_cull: Literal["off", "rectangles", "frustum"] = ...,
        front_to_back: bool = ...,
        shading_strategy: Literal["auto", "forward", "deferred"] = ...,
        alpha_mode: Literal["auto", "opaque"] = ...,
        front_face: Literal["ccw", "cw"] = ...,
        depth_format: Literal["d32f", "d24", "d16"] = ...,
        depth_compare: Literal["never", "less", "lequal", "equal", "notequal", "gequal", "greater", "always"] = ...,
        no_depth_test: bool = ...,
        no_depth_write: bool = ...,
        interpolation: Literal["perspective", "linear"] = ...,
        texture_filter: Literal["nearest", "bilinear", "trilinear"] = ...,
        no_textures: bool = ...,
        clip_plane: Vec4 | Sequence[Vec4] = ...,
        background: Vec3 = ...,
        wireframe: bool = ...,
        hidden_line: bool = ...,
        edge_color: Vec3 = ...,
        max_painter_comparisons: int = ...,
        max_bsp_polygons: int = ...,
        max_bsp_classifications: int = ...,
        max_projected_polygons: int = ...,
        max_painted_fragments: int = ...,
        max_warnock_classifications: int = ...,
        max_abuffer_fragments: int = ...,
        visibility: Literal["zbuffer", "painter", "bsp", "warnock", "abuffer"] = ...,
        view: Literal[
            "none", "depth", "normals", "overdraw", "hiz", "tiles", "ids", "backfaces", "clipped",
            "zfight", "mip", "lod"
        ] = ...,
        aa: int = ...,
        msaa: bool = ...,
    ) -> dict[str, npt.NDArray[np.generic]]: ...

def render(
    scene: Scene | Mesh | str | os.PathLike[str],
    width: int = 1920,
    height: int = 1080,
    *,
    camera: Camera | None = None,
    outputs: OutputName | Sequence[OutputName] = ("color", "depth"),
    sensor: Sensor = None,
    threads: int = 0,
    isolation: Literal["worker", "in-process"] = "worker",
    **options: object,
) -> dict[str, npt.NDArray[np.generic]]: ...
