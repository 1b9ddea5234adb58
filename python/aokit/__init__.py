"""aokit: screen-space ambient occlusion on numpy depth and normal passes.

    import aokit
    ctx = aokit.Context()
    camera = aokit.Camera.from_json("camera.json")
    ao = ctx.ao(aokit.read_depth("depth.exr"), aokit.read_normals("normal.exr"), camera=camera)

`Context.ao` runs the GTAO, HBAO, SSAO, ... pipeline of the `aokit` Rust crate on the GPU
(or lavapipe) as `aokit ao` does; `reference` traces ground truth on the CPU and `metrics`
scores one against the other as `aokit compare` does. See docs/python.md.
"""

from typing import Dict, List, Mapping, Optional, Tuple, Union

from . import _aokit
from ._aokit import Camera
from ._context import Context
from ._eval import metrics, read_depth, read_normals, reference, write_exr

__version__: str = _aokit.__version__

__all__ = [
    "Camera",
    "Context",
    "metrics",
    "read_depth",
    "read_normals",
    "reference",
    "resolve_settings",
    "settings_table",
    "write_exr",
]


def resolve_settings(
    method: str = "gtao",
    preset: str = "high",
    radius: Optional[float] = None,
    settings: Optional[Mapping[str, Union[bool, int, float, str]]] = None,
) -> Dict[str, Union[bool, int, float, str]]:
    """Every setting's value, by dotted key, that these arguments of `Context.ao` resolve to;
    raises ValueError as `Context.ao` would for a key or value it refuses."""
    return dict(
        _aokit.resolve_settings(method, preset, radius, None if settings is None else dict(settings))
    )


def settings_table() -> List[Tuple[str, str, str, str]]:
    """Every setting as `(key, type, range, help)`, as `aokit settings` lists them."""
    return list(_aokit.setting_names())
