"""`aokit.Context`: AO of numpy depth and normal passes on one GPU device."""

from __future__ import annotations

from typing import Any, List, Literal, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import _aokit
from ._arrays import float32_bytes, image
from ._aokit import Camera

DepthKind = Literal["linear", "ndc"]
NormalSpace = Literal["view", "world"]
Adapter = Literal["auto", "software", "hardware"]
SettingValue = Union[bool, int, float, str]


class Context:
    """One GPU device with the AO pipeline compiled on it, reused by every call.

    Opening a context finds an adapter and creating the pipeline compiles its shaders; keep
    one context for all the images of a session. `adapter="auto"` takes a GPU where there is
    one, else the software rasteriser (lavapipe); `"software"` takes lavapipe even beside a
    GPU; `"hardware"` refuses to fall back. Raises RuntimeError when there is no such adapter.

    A context runs one call at a time: the GIL is released while the GPU works, and a call
    from another thread meanwhile raises RuntimeError (already borrowed). Use one context per
    thread to run in parallel.
    """

    def __init__(self, adapter: Adapter = "auto") -> None:
        self._native = _aokit.Context(adapter)

    @property
    def adapter(self) -> str:
        """The adapter: `name (backend, driver)`."""
        return self._native.adapter

    @property
    def software(self) -> bool:
        """Whether the adapter is a software rasteriser (lavapipe, llvmpipe)."""
        return self._native.software

    def __repr__(self) -> str:
        return f"aokit.Context({self.adapter!r})"

    @overload
    def ao(
        self,
        depth: npt.ArrayLike,
        normals: Optional[npt.ArrayLike] = ...,
        *,
        camera: Camera,
        depth_kind: DepthKind = ...,
        normal_space: Optional[NormalSpace] = ...,
        method: str = ...,
        preset: str = ...,
        radius: Optional[float] = ...,
        settings: Optional[Mapping[str, SettingValue]] = ...,
        bent_normals: Literal[False] = ...,
        frame_index: int = ...,
    ) -> np.ndarray: ...

    @overload
    def ao(
        self,
        depth: npt.ArrayLike,
        normals: Optional[npt.ArrayLike] = ...,
        *,
        camera: Camera,
        depth_kind: DepthKind = ...,
        normal_space: Optional[NormalSpace] = ...,
        method: str = ...,
        preset: str = ...,
        radius: Optional[float] = ...,
        settings: Optional[Mapping[str, SettingValue]] = ...,
        bent_normals: Literal[True],
        frame_index: int = ...,
    ) -> Tuple[np.ndarray, np.ndarray]: ...

    def ao(
        self,
        depth: npt.ArrayLike,
        normals: Optional[npt.ArrayLike] = None,
        *,
        camera: Camera,
        depth_kind: DepthKind = "linear",
        normal_space: Optional[NormalSpace] = None,
        method: str = "gtao",
        preset: str = "high",
        radius: Optional[float] = None,
        settings: Optional[Mapping[str, SettingValue]] = None,
        bent_normals: bool = False,
        frame_index: int = 0,
    ) -> Union[np.ndarray, Tuple[np.ndarray, np.ndarray]]:
        """Ambient occlusion of one view, as `aokit ao` computes it.

        depth: H x W (or H x W x 1) float16/32/64 array, C or Fortran order, of the size
            `camera` gives, with its `guard_band` on each side (the AO is of the frame
            inside). Linear view depth (`depth_kind="linear"`; 0, negative, NaN or inf
            where there is no surface) or depth-buffer values in [0, 1] (`"ndc"`, in the
            camera's convention; the far-plane value is background).
        normals: H x W x 3 unit normals in `normal_space` ("view": x right, y up, camera
            looking down -Z; "world": turned by `camera.view_from_world`), or None to
            reconstruct them from depth.
        method, preset, radius, settings: the settings, as `--method`, `--preset`,
            `--radius` and `--set KEY=VALUE` give them: `settings` maps dotted keys
            (`"spatial.enabled"`) to values, applied in order after the radius, with the
            checks and error text of `--set`. `normal_space` is the setting `normals.space`,
            applied before them.
        bent_normals: also return the bent normals (H x W x 3, view space; GTAO and the
            other slice methods only).
        frame_index: the frame's number in a sequence, which picks its noise pattern (as
            `aokit ao` runs frame 0); `ao_batch` numbers its frames 0, 1, 2, ...

        Returns the AO, float32 H x W in [0, 1] (1 = unoccluded), or `(ao, bent)`. Raises
        ValueError naming the argument for a shape, value or setting that is refused, and
        RuntimeError when the GPU fails. The GIL is released while the GPU works.
        """
        results = self._run(
            [depth],
            None if normals is None else [normals],
            [camera],
            batch=False,
            depth_kind=depth_kind,
            normal_space=normal_space,
            method=method,
            preset=preset,
            radius=radius,
            settings=settings,
            bent_normals=bent_normals,
            first_frame=frame_index,
        )
        ao, bent = results[0]
        if bent_normals:
            assert bent is not None, "the pipeline returned no bent normals"
            return ao, bent
        return ao

    def ao_batch(
        self,
        depths: Union[np.ndarray, Sequence[npt.ArrayLike]],
        normals: Optional[Union[np.ndarray, Sequence[npt.ArrayLike]]] = None,
        *,
        cameras: Union[Camera, Sequence[Camera]],
        depth_kind: DepthKind = "linear",
        normal_space: Optional[NormalSpace] = None,
        method: str = "gtao",
        preset: str = "high",
        radius: Optional[float] = None,
        settings: Optional[Mapping[str, SettingValue]] = None,
        bent_normals: bool = False,
        first_frame: int = 0,
    ) -> Any:
        """AO of a sequence of frames: `depths` is an N x H x W array or a sequence of H x W
        arrays, `normals` likewise (N x H x W x 3), `cameras` one camera for all frames or one
        per frame. The frames run in order as one sequence on one pipeline, numbered from
        `first_frame`: with `settings={"temporal.enabled": True}` the temporal filter carries
        from frame to frame (its history starts over at the first); otherwise frame i's AO is
        what `ao(..., frame_index=first_frame + i)` gives for it.

        The GPU is kept busy: each frame is converted and uploaded while the GPU runs the one
        before it, and read back while it runs the one after (one upload and one read-back per
        frame, the GIL released from the first conversion to the last read-back).

        Returns an N x H x W float32 array when all frames have one size, else a list of
        H x W arrays; with `bent_normals`, a pair `(ao, bent)`. Arguments and errors as `ao`.
        """
        depth_list = list(depths)
        count = len(depth_list)
        if count == 0:
            raise ValueError("depths: no frames")
        if isinstance(cameras, Camera):
            camera_list = [cameras] * count
        else:
            camera_list = list(cameras)
            if len(camera_list) != count:
                raise ValueError(f"cameras: {len(camera_list)} cameras for {count} depth frames")
        normal_list = None
        if normals is not None:
            normal_list = list(normals)
            if len(normal_list) != count:
                raise ValueError(f"normals: {len(normal_list)} frames for {count} depth frames")
        results = self._run(
            depth_list,
            normal_list,
            camera_list,
            batch=True,
            depth_kind=depth_kind,
            normal_space=normal_space,
            method=method,
            preset=preset,
            radius=radius,
            settings=settings,
            bent_normals=bent_normals,
            first_frame=first_frame,
        )
        aos = [ao for ao, _ in results]
        same_size = len({a.shape for a in aos}) == 1
        ao_out: Any = np.stack(aos) if same_size else aos
        if not bent_normals:
            return ao_out
        bents = [b for _, b in results if b is not None]
        return ao_out, (np.stack(bents) if same_size else bents)

    def _run(
        self,
        depths: Sequence[npt.ArrayLike],
        normals: Optional[Sequence[npt.ArrayLike]],
        cameras: Sequence[Camera],
        *,
        batch: bool,
        depth_kind: str,
        normal_space: Optional[str],
        method: str,
        preset: str,
        radius: Optional[float],
        settings: Optional[Mapping[str, SettingValue]],
        bent_normals: bool,
        first_frame: int,
    ) -> List[Tuple[np.ndarray, Optional[np.ndarray]]]:
        frames = []
        names = []
        for i, depth in enumerate(depths):
            camera = cameras[i]
            if not isinstance(camera, Camera):
                raise TypeError(
                    f"{'cameras[%d]' % i if batch else 'camera'}: expected an aokit.Camera, "
                    f"not {type(camera).__name__}"
                )
            # The depth and normals hold the frame and its guard band on each side.
            h, w = (side + 2 * camera.guard_band for side in (camera.height, camera.width))
            depth_name = f"depths[{i}]" if batch else "depth"
            normals_name = f"normals[{i}]" if batch else "normals"
            depth_bytes, _ = float32_bytes(depth, depth_name, (h, w))
            normal_bytes = None
            if normals is not None:
                normal_bytes, _ = float32_bytes(normals[i], normals_name, (h, w, 3))
            frames.append((depth_bytes, normal_bytes, camera))
            names.append((depth_name, normals_name))
        if settings is not None and not isinstance(settings, dict):
            settings = dict(settings)
        outputs = self._native.run(
            frames,
            names,
            depth_kind,
            normal_space,
            method,
            preset,
            None if radius is None else float(radius),
            settings,
            bent_normals,
            first_frame,
        )
        results = []
        for (ao, bent), camera in zip(outputs, cameras):
            h, w = camera.height, camera.width
            results.append(
                (image(ao, h, w), None if bent is None else image(bent, h, w, 3))
            )
        return results
