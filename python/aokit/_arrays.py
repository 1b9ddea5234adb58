"""Arrays in: numpy arrays of float16/32/64 in C or Fortran order become the float32 bytes the
native module reads, with their shapes checked and named in errors."""

from __future__ import annotations

from typing import Any, Optional, Tuple

import numpy as np
import numpy.typing as npt

_FLOATS = (np.float16, np.float32, np.float64)


def float32_bytes(
    array: npt.ArrayLike, name: str, shape: Tuple[Optional[int], ...]
) -> Tuple[bytes, Tuple[int, ...]]:
    """`array` as C-ordered native float32 bytes, and its shape.

    `shape` gives the expected size of each axis (None: any). A depth of shape H x W x 1 is
    taken as H x W. Raises ValueError naming `name` for another dimensionality or size, and
    TypeError for a dtype that is not floating point.
    """
    a = np.asarray(array)
    if a.dtype.kind != "f" or a.dtype.type not in _FLOATS:
        raise TypeError(f"{name}: expected a float16, float32 or float64 array, not {a.dtype}")
    if len(shape) == 2 and a.ndim == 3 and a.shape[2] == 1:
        a = a[:, :, 0]
    if a.ndim != len(shape) or any(
        want is not None and got != want for got, want in zip(a.shape, shape)
    ):
        want = " x ".join("?" if s is None else str(s) for s in shape)
        got = " x ".join(str(s) for s in a.shape) or "a scalar"
        raise ValueError(f"{name}: expected shape {want} (H x W{' x 3' if len(shape) == 3 else ''}), got {got}")
    return np.ascontiguousarray(a, dtype=np.float32).tobytes(), a.shape


def image(data: Any, height: int, width: int, channels: int = 1) -> np.ndarray:
    """A float32 bytearray from the native module as an H x W (x channels) array (no copy)."""
    a = np.frombuffer(data, dtype=np.float32)
    return a.reshape((height, width) if channels == 1 else (height, width, channels))
