"""Ground truth, scores and image files: the CPU reference tracer, `aokit compare`'s metrics,
and the EXR/PFM/NPY passes `aokit ao` reads."""

from __future__ import annotations

import os
from typing import Dict, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import _aokit
from ._arrays import float32_bytes, image
from ._aokit import Camera

PathLike = Union[str, "os.PathLike[str]"]
Falloff = Literal["none", "linear", "quadratic"]


@overload
def reference(
    vertices: npt.ArrayLike,
    indices: npt.ArrayLike,
    camera: Camera,
    radius: float,
    spp: int = ...,
    *,
    seed: int = ...,
    falloff: Falloff = ...,
    gbuffer: Literal[False] = ...,
) -> np.ndarray: ...


@overload
def reference(
    vertices: npt.ArrayLike,
    indices: npt.ArrayLike,
    camera: Camera,
    radius: float,
    spp: int = ...,
    *,
    seed: int = ...,
    falloff: Falloff = ...,
    gbuffer: Literal[True],
) -> Tuple[np.ndarray, np.ndarray, np.ndarray]: ...


def reference(
    vertices: npt.ArrayLike,
    indices: npt.ArrayLike,
    camera: Camera,
    radius: float,
    spp: int = 256,
    *,
    seed: int = 0,
    falloff: Falloff = "none",
    gbuffer: bool = False,
) -> Union[np.ndarray, Tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Ray-traced ground-truth AO of a triangle mesh seen by `camera` (the CPU tracer behind
    `aokit reference`), on every core with the GIL released.

    vertices: N x 3 world-space positions; indices: M x 3 vertex indices (any integer dtype),
    counter-clockwise seen from the front. `radius` in world units, `spp` rays per pixel,
    `seed` the sample scrambling, `falloff` how a hit at distance t counts.

    Returns the AO (float32 H x W, 1 = unoccluded, 1 on background), or with `gbuffer=True`
    `(ao, depth, normals)`: the linear view depth (0 on background) and view-space normals of
    the primary hits, which `Context.ao` takes.
    """
    v, _ = float32_bytes(vertices, "vertices", (None, 3))
    i = np.asarray(indices)
    if i.dtype.kind not in "iu":
        raise TypeError(f"indices: expected an integer array, not {i.dtype}")
    if i.ndim != 2 or i.shape[1] != 3:
        raise ValueError(f"indices: expected shape M x 3, got {' x '.join(map(str, i.shape))}")
    count = len(v) // 12
    if i.size and (i.min() < 0 or i.max() >= count):
        raise ValueError(f"indices: values must lie in 0..{count - 1} (one per vertex)")
    index_bytes = np.ascontiguousarray(i, dtype=np.uint32).tobytes()
    if not isinstance(camera, Camera):
        raise TypeError(f"camera: expected an aokit.Camera, not {type(camera).__name__}")
    if spp < 1:
        raise ValueError(f"spp: rays per pixel must be at least 1, got {spp}")
    ao, depth, normals = _aokit.reference(
        v, index_bytes, camera, float(radius), int(spp), int(seed), falloff
    )
    h, w = camera.height, camera.width
    if not gbuffer:
        return image(ao, h, w)
    return image(ao, h, w), image(depth, h, w), image(normals, h, w, 3)


def metrics(
    ao: npt.ArrayLike, reference: npt.ArrayLike, mask: Optional[npt.ArrayLike] = None
) -> Dict[str, float]:
    """How far `ao` is from `reference` (both H x W in [0, 1]) over the pixels where `mask`
    (H x W, boolean) is set, all pixels without one: the statistics `aokit compare` reports.

    Returns a dict: `pixels` (scored), `rmse`, `mae`, `bias` (mean of ao - reference:
    positive under-occludes), `psnr` (dB) and `ssim` (mask-weighted). With no pixel scored,
    every statistic is NaN.
    """
    a = np.asarray(ao)
    if a.ndim != 2:
        raise ValueError(f"ao: expected shape H x W, got {' x '.join(map(str, a.shape))}")
    h, w = a.shape
    ao_bytes, _ = float32_bytes(a, "ao", (h, w))
    ref_bytes, _ = float32_bytes(reference, "reference", (h, w))
    mask_bytes = None
    if mask is not None:
        m = np.asarray(mask)
        if m.shape != (h, w):
            raise ValueError(
                f"mask: expected shape {h} x {w}, got {' x '.join(map(str, m.shape))}"
            )
        mask_bytes = np.ascontiguousarray(m, dtype=bool).astype(np.uint8).tobytes()
    return dict(_aokit.metrics(w, h, ao_bytes, ref_bytes, mask_bytes))


def read_depth(path: PathLike) -> np.ndarray:
    """A depth pass (EXR, PFM or NPY) as `aokit ao --depth` reads it: float32 H x W."""
    data, w, h = _aokit.read_image(os.fspath(path), 1)
    return image(data, h, w)


def read_normals(path: PathLike) -> np.ndarray:
    """A normal pass (EXR, PFM or NPY) as `aokit ao --normals` reads it: float32 H x W x 3."""
    data, w, h = _aokit.read_image(os.fspath(path), 3)
    return image(data, h, w, 3)


def write_exr(path: PathLike, values: npt.ArrayLike, channel: str = "Y") -> None:
    """Writes an H x W image as one 32-bit float EXR channel (`Y`, as `aokit ao` writes
    ao.exr)."""
    a = np.asarray(values)
    if a.ndim != 2:
        raise ValueError(f"values: expected shape H x W, got {' x '.join(map(str, a.shape))}")
    data, _ = float32_bytes(a, "values", a.shape)
    _aokit.write_exr(os.fspath(path), a.shape[1], a.shape[0], data, channel)
