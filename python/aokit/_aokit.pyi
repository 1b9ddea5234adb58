"""Type stubs of the native module `aokit._aokit` (python/src/). Use the `aokit` package:
its functions turn numpy arrays into the float32 bytes these take."""

import os
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

__version__: str

_Matrix = Union[Sequence[Sequence[float]], Any]

class Camera:
    """A camera: image size, projection and placement, as camera.json describes them
    (docs/camera-json.md). Immutable; compare with ==."""

    @staticmethod
    def perspective(
        fov_y_deg: float,
        width: int,
        height: int,
        near: float = 0.1,
        far: Optional[float] = None,
        reverse_z: bool = True,
        view_from_world: Optional[_Matrix] = None,
        ndc_offset: Tuple[float, float] = (0.0, 0.0),
        guard_band: int = 0,
    ) -> "Camera":
        """A pinhole camera: full vertical field of view in degrees, image size in pixels,
        near and far planes (far None: infinite), the depth convention, the world-to-view
        matrix (4 x 4, row-major, translation in the last column; identity when None), and
        the pixels of overscan the depth and normals hold on each side (docs/python.md).
        Raises ValueError for an unusable projection or a non-finite matrix."""
    @staticmethod
    def orthographic(
        view_height: float,
        width: int,
        height: int,
        near: float = 0.1,
        far: float = 1000.0,
        reverse_z: bool = True,
        view_from_world: Optional[_Matrix] = None,
        ndc_offset: Tuple[float, float] = (0.0, 0.0),
        guard_band: int = 0,
    ) -> "Camera":
        """A parallel projection `view_height` world units tall; otherwise as `perspective`."""
    @staticmethod
    def from_json(source: Union[str, "os.PathLike[str]", Dict[str, Any]]) -> "Camera":
        """The camera of a camera.json file (a path) or of its parsed contents (a dict), as
        `aokit ao --camera-json` reads it. Raises OSError for an unreadable file and ValueError for
        contents that are not a valid camera.json."""
    def to_dict(self) -> Dict[str, Any]:
        """The camera.json contents, for `json.dump`."""
    @property
    def width(self) -> int:
        """Image width in pixels."""
    @property
    def height(self) -> int:
        """Image height in pixels."""
    @property
    def guard_band(self) -> int:
        """Pixels of overscan on each side of the depth and normals; the AO is width x height."""
    @property
    def projection(self) -> str:
        """`"perspective"` or `"orthographic"`."""
    @property
    def fov_y_deg(self) -> Optional[float]:
        """Vertical field of view in degrees (perspective), else None."""
    @property
    def ortho_height(self) -> Optional[float]:
        """Height of the view volume in world units (orthographic), else None."""
    @property
    def near(self) -> float:
        """Near plane distance."""
    @property
    def far(self) -> Optional[float]:
        """Far plane distance, None for an infinite far plane."""
    @property
    def reverse_z(self) -> bool:
        """Whether the depth buffer holds 1 at the near plane and 0 at the far plane."""
    @property
    def ndc_offset(self) -> Tuple[float, float]:
        """Where the view axis meets the image, in NDC (jitter, off-centre frustum)."""
    @property
    def view_from_world(self) -> List[List[float]]:
        """World-to-view matrix, row-major; turns world-space normals into view space."""

class Context:
    """A GPU device with the AO pipeline on it; see `aokit.Context`."""

    def __init__(self, adapter: str = "auto") -> None: ...
    @property
    def adapter(self) -> str: ...
    @property
    def software(self) -> bool: ...
    def run(
        self,
        frames: List[Tuple[bytes, Optional[bytes], Camera]],
        names: List[Tuple[str, str]],
        depth_kind: str,
        normal_space: Optional[str],
        method: str,
        preset: str,
        radius: Optional[float],
        settings: Optional[Dict[str, Union[bool, int, float, str]]],
        bent_normals: bool,
        first_frame: int,
    ) -> List[Tuple[bytearray, Optional[bytearray]]]:
        """Runs frames (float32 bytes, C order) as one sequence numbered from
        `first_frame`; returns per frame the AO and
        the bent normals (xyz) as float32 bytearrays."""

def resolve_settings(
    method: str = "gtao",
    preset: str = "high",
    radius: Optional[float] = None,
    settings: Optional[Dict[str, Union[bool, int, float, str]]] = None,
) -> Dict[str, Union[bool, int, float, str]]: ...
def setting_names() -> List[Tuple[str, str, str, str]]: ...
def reference(
    vertices: bytes,
    indices: bytes,
    camera: Camera,
    radius: float,
    spp: int,
    seed: int = 0,
    falloff: str = "none",
) -> Tuple[bytearray, bytearray, bytearray]: ...
def metrics(
    width: int, height: int, ao: bytes, reference: bytes, mask: Optional[bytes] = None
) -> Dict[str, float]: ...
def read_image(path: str, channels: int) -> Tuple[bytearray, int, int]: ...
def write_exr(
    path: str, width: int, height: int, values: bytes, channel: str = "Y"
) -> None: ...
