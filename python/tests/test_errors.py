"""Every input `Context.ao` refuses raises, naming the argument; settings errors read as
`aokit ao --set`'s."""

from __future__ import annotations

import numpy as np
import pytest

import aokit

CAM = aokit.Camera.perspective(60.0, 16, 12)
DEPTH = np.full((12, 16), 2.0, dtype=np.float32)
NORMALS = np.tile(np.array([0, 0, 1], dtype=np.float32), (12, 16, 1))


@pytest.mark.parametrize(
    "kwargs, argument",
    [
        (dict(depth=np.zeros((16, 12))), "depth: expected shape 12 x 16"),
        (dict(depth=np.zeros((12, 16, 2))), "depth: expected shape 12 x 16"),
        (dict(depth=np.zeros(12)), "depth: expected shape 12 x 16"),
        (dict(normals=np.zeros((12, 16))), "normals: expected shape 12 x 16 x 3"),
        (dict(normals=np.zeros((12, 16, 4))), "normals: expected shape 12 x 16 x 3"),
        (dict(normals=np.zeros((12, 16, 3))), "normals"),
        (dict(depth_kind="ndc"), "depth: 192 of 192 pixels hold depth outside [0, 1]"),
        (dict(depth_kind="z"), "depth_kind: depth kind `z` is not one of linear, ndc"),
        (dict(normal_space="eye"), "normal_space: invalid setting `normals.space`"),
        (dict(method="vxao"), "method: "),
        (dict(preset="max"), "preset: "),
        (dict(radius=-1.0), "setting `radius` = -1 is out of range"),
        (dict(settings={"spatial.radius": 9}), "setting `spatial.radius` = 9 is out of range: an integer in 1..=8"),
        (dict(settings={"gtao.slices": 2}), "unknown setting `gtao.slices`: did you mean `gtao.slice_count`?"),
        (dict(settings={"gtao.slice_count": 2.5}), "invalid setting `gtao.slice_count`"),
        (dict(settings={"noise.kind": "pink"}), "invalid setting `noise.kind`"),
        (dict(method="ssao", bent_normals=True), "bent_normals"),
    ],
)
def test_bad_inputs_raise_value_error_naming_the_argument(ctx, kwargs, argument):
    args = dict(depth=DEPTH, normals=NORMALS, camera=CAM)
    args.update(kwargs)
    with pytest.raises(ValueError) as error:
        ctx.ao(args.pop("depth"), args.pop("normals"), **args)
    assert argument in str(error.value)


def test_non_float_arrays_raise_type_error(ctx):
    with pytest.raises(TypeError, match="depth: expected a float16, float32 or float64 array"):
        ctx.ao(DEPTH.astype(np.int32), camera=CAM)
    with pytest.raises(TypeError, match="camera: expected an aokit.Camera"):
        ctx.ao(DEPTH, camera="camera.json")
    with pytest.raises(TypeError, match=r'settings\["power"\]'):
        ctx.ao(DEPTH, camera=CAM, settings={"power": [1]})


def as_text(value):
    """`value` as a `--set` value: Python's text, `true`/`false` for a bool."""
    return str(value).lower() if isinstance(value, bool) else str(value)


def test_settings_errors_read_as_the_clis(cli, gbuffer, tmp_path, ctx):
    # Out-of-range values, rules between settings, and values of the wrong kind: each is read
    # from the text `--set` is given for it.
    cases = [
        ("spatial.radius", 9), ("gtao.slices", 2), ("radius", -1), ("temporal.blend", 1.5),
        ("spatial.enabled", 4), ("spatial.kind", True), ("gtao.slices", 2.5), ("radius", "far"),
    ]
    for key, value in cases:
        with pytest.raises(ValueError) as error:
            ctx.ao(gbuffer.depth, camera=gbuffer.camera, settings={key: value})
        out = cli(
            "ao", "--depth", str(gbuffer.depth_path), "--camera-json", str(gbuffer.camera_path),
            "--set", f"{key}={as_text(value)}", "--out", str(tmp_path / "o"),
            cwd=tmp_path, check=False,
        )
        assert out.returncode != 0
        assert str(error.value) in out.stderr, (str(error.value), out.stderr)


def test_world_normals_need_a_rotation(ctx):
    flat = aokit.Camera.perspective(60.0, 16, 12, view_from_world=np.zeros((4, 4)))
    with pytest.raises(ValueError, match="determinant 0"):
        ctx.ao(DEPTH, NORMALS, camera=flat, normal_space="world")
    # Without normals, or with view-space ones, the matrix is not used.
    ctx.ao(DEPTH, NORMALS, camera=flat)


def test_bad_cameras_are_refused(tmp_path):
    with pytest.raises(ValueError, match="camera"):
        aokit.Camera.perspective(60.0, 0, 12)
    with pytest.raises(ValueError, match="near"):
        aokit.Camera.perspective(60.0, 16, 12, near=-1.0)
    with pytest.raises(ValueError, match="view_from_world"):
        aokit.Camera.perspective(60.0, 16, 12, view_from_world=np.eye(3))
    with pytest.raises(ValueError, match="non-finite"):
        aokit.Camera.perspective(60.0, 16, 12, view_from_world=np.full((4, 4), np.nan))
    with pytest.raises(ValueError, match="unknown field"):
        aokit.Camera.from_json({**CAM.to_dict(), "fov": 3})
    with pytest.raises(ValueError, match="lacks fov_y_deg"):
        d = CAM.to_dict()
        del d["fov_y_deg"]
        aokit.Camera.from_json(d)
    with pytest.raises(OSError, match="cannot read"):
        aokit.Camera.from_json(tmp_path / "missing.json")


def test_batch_arguments_are_checked(ctx):
    with pytest.raises(ValueError, match="depths: no frames"):
        ctx.ao_batch([], cameras=CAM)
    with pytest.raises(ValueError, match="cameras: 1 cameras for 2 depth frames"):
        ctx.ao_batch([DEPTH, DEPTH], cameras=[CAM])
    with pytest.raises(ValueError, match="normals: 1 frames for 2 depth frames"):
        ctx.ao_batch([DEPTH, DEPTH], [NORMALS], cameras=CAM)
    with pytest.raises(ValueError, match=r"depths\[1\]: expected shape 12 x 16"):
        ctx.ao_batch([DEPTH, DEPTH[:4]], cameras=CAM)


def test_a_bad_frame_late_in_a_batch_raises_and_the_context_runs_on(ctx):
    # Frames are converted while the GPU runs the one before: the third frame's normals are
    # refused after two frames were submitted, and the next call is not disturbed by them.
    zero = np.zeros_like(NORMALS)
    with pytest.raises(ValueError, match=r"normals\[2\]: 192 pixels showing a surface have a normal that is zero"):
        ctx.ao_batch([DEPTH] * 4, [NORMALS, NORMALS, zero, NORMALS], cameras=CAM)
    with pytest.raises(ValueError, match=r"depths\[2\]: 192 of 192 pixels hold depth outside"):
        ctx.ao_batch([DEPTH * 0.1] * 2 + [DEPTH], cameras=CAM, depth_kind="ndc")
    fine = ctx.ao_batch([DEPTH] * 3, [NORMALS] * 3, cameras=CAM)
    for i in range(3):
        np.testing.assert_array_equal(fine[i], ctx.ao(DEPTH, NORMALS, camera=CAM, frame_index=i))


def test_no_adapter_raises_runtime_error(monkeypatch):
    monkeypatch.setenv("WGPU_ADAPTER_NAME", "no-such-adapter-anywhere")
    with pytest.raises(RuntimeError, match="no-such-adapter-anywhere"):
        aokit.Context()
    with pytest.raises(ValueError, match="adapter: `tpu`"):
        aokit.Context("tpu")


def test_resolved_settings_and_the_table():
    table = aokit.settings_table()
    keys = [row[0] for row in table]
    assert "gtao.slice_count" in keys and "spatial.enabled" in keys
    resolved = aokit.resolve_settings("hbao", "low", 0.5, {"spatial.enabled": True, "noise.kind": "blue"})
    assert set(resolved) == set(keys)
    assert resolved["method"] == "hbao" and resolved["radius"] == 0.5
    assert resolved["spatial.enabled"] is True and resolved["noise.kind"] == "blue"
    # Strings are read as `--set` reads them; numpy scalars are numbers.
    assert aokit.resolve_settings(settings={"gtao.slice_count": "4"})["gtao.slice_count"] == 4
    assert aokit.resolve_settings(settings={"gtao.slice_count": np.int64(5)})["gtao.slice_count"] == 5
    assert aokit.resolve_settings(settings={"power": np.float32(1.5)})["power"] == 1.5
    with pytest.raises(ValueError, match="out of range"):
        aokit.resolve_settings(settings={"gtao.slice_count": 0})


def test_orthographic_cameras_run(ctx):
    cam = aokit.Camera.orthographic(4.0, 16, 12, near=0.5, far=50.0)
    assert cam.projection == "orthographic" and cam.ortho_height == 4.0 and cam.far == 50.0
    assert aokit.Camera.from_json(cam.to_dict()) == cam
    ao = ctx.ao(DEPTH, NORMALS, camera=cam)
    assert ao.shape == (12, 16) and np.all(ao > 0.99)
