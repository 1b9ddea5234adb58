"""`Context.ao` gives what `aokit ao` gives on the same passes, to the bit."""

from __future__ import annotations

import numpy as np
import pytest

import aokit


def test_default_settings_match_the_cli(ctx, gbuffer, cli_ao):
    ao = ctx.ao(gbuffer.depth, gbuffer.normals, camera=gbuffer.camera)
    assert ao.shape == (32, 48) and ao.dtype == np.float32
    assert 0.0 <= ao.min() and ao.max() <= 1.0 and ao.min() < 0.9
    np.testing.assert_array_equal(ao, cli_ao())


@pytest.mark.parametrize(
    "method, preset, radius, settings",
    [
        ("hbao", "low", 0.5, {"spatial.enabled": True}),
        ("ssao", "medium", None, {"noise.kind": "blue", "power": 1.5}),
        ("gtao", "ultra", 0.8, {"gtao.slice_count": 2, "normals.encoding": "oct16"}),
    ],
)
def test_methods_and_settings_match_the_cli(ctx, gbuffer, cli_ao, method, preset, radius, settings):
    ao = ctx.ao(
        gbuffer.depth,
        gbuffer.normals,
        camera=gbuffer.camera,
        method=method,
        preset=preset,
        radius=radius,
        settings=settings,
    )
    args = ["--method", method, "--preset", preset]
    if radius is not None:
        args += ["--radius", str(radius)]
    for key, value in settings.items():
        args += ["--set", f"{key}={str(value).lower() if isinstance(value, bool) else value}"]
    np.testing.assert_array_equal(ao, cli_ao(*args))


def test_reconstructed_normals_match_the_cli(ctx, gbuffer, cli_ao):
    ao = ctx.ao(gbuffer.depth, camera=gbuffer.camera)
    np.testing.assert_array_equal(ao, cli_ao(normals=False))


def test_ndc_depth_matches_the_cli(ctx, gbuffer, cli_ao, tmp_path):
    # Reverse-Z with an infinite far plane: ndc = near / depth, 0 (the far plane) on background.
    cam = gbuffer.camera
    assert cam.reverse_z and cam.far is None
    d = gbuffer.depth
    ndc = np.where(d > 0, cam.near / np.where(d > 0, d, 1), 0).astype(np.float32)
    np.save(tmp_path / "ndc.npy", ndc)
    ao = ctx.ao(ndc, gbuffer.normals, camera=cam, depth_kind="ndc")
    np.testing.assert_array_equal(ao, cli_ao("--depth-kind", "ndc", depth=tmp_path / "ndc.npy"))


def test_world_normals_match_the_cli(ctx, gbuffer, cli_ao, tmp_path):
    rotation = np.array(gbuffer.camera.view_from_world, dtype=np.float32)[:3, :3]
    world = (gbuffer.normals.reshape(-1, 3) @ rotation).reshape(gbuffer.normals.shape)
    np.save(tmp_path / "world.npy", world.astype(np.float32))
    ao = ctx.ao(gbuffer.depth, world, camera=gbuffer.camera, normal_space="world")
    expected = cli_ao("--normal-space", "world", normals=tmp_path / "world.npy")
    np.testing.assert_array_equal(ao, expected)
    same = ctx.ao(
        gbuffer.depth, world, camera=gbuffer.camera, settings={"normals.space": "world"}
    )
    np.testing.assert_array_equal(same, expected)


def test_camera_from_a_dict_or_built_is_the_files(ctx, gbuffer):
    assert aokit.Camera.from_json(gbuffer.camera_dict) == gbuffer.camera
    c = gbuffer.camera_dict
    built = aokit.Camera.perspective(
        c["fov_y_deg"],
        c["width"],
        c["height"],
        near=c["near"],
        far=c["far"],
        reverse_z=c["reverse_z"],
        view_from_world=np.array(c["view_from_world"]),
    )
    assert built == gbuffer.camera
    assert aokit.Camera.from_json(built.to_dict()) == built
    np.testing.assert_array_equal(
        ctx.ao(gbuffer.depth, gbuffer.normals, camera=built),
        ctx.ao(gbuffer.depth, gbuffer.normals, camera=gbuffer.camera),
    )


def test_dtypes_orders_and_backgrounds_give_the_same_ao(ctx, gbuffer):
    d, n, cam = gbuffer.depth, gbuffer.normals, gbuffer.camera
    base = ctx.ao(d, n, camera=cam)
    np.testing.assert_array_equal(ctx.ao(d.astype(np.float64), n.astype(np.float64), camera=cam), base)
    np.testing.assert_array_equal(ctx.ao(np.asfortranarray(d), np.asfortranarray(n), camera=cam), base)
    np.testing.assert_array_equal(ctx.ao(d[:, :, None], n, camera=cam), base)
    # float16 rounds the depth: the same AO as the rounded values in float32.
    half = d.astype(np.float16)
    np.testing.assert_array_equal(
        ctx.ao(half, n, camera=cam), ctx.ao(half.astype(np.float32), n, camera=cam)
    )
    background = d <= 0
    assert background.any()
    for value in (np.nan, np.inf, -1.0):
        np.testing.assert_array_equal(ctx.ao(np.where(background, value, d), n, camera=cam), base)


def test_bent_normals_come_with_the_same_ao(ctx, gbuffer):
    ao, bent = ctx.ao(gbuffer.depth, gbuffer.normals, camera=gbuffer.camera, bent_normals=True)
    assert bent.shape == (32, 48, 3) and bent.dtype == np.float32
    surface = gbuffer.depth > 0
    lengths = np.linalg.norm(bent[surface], axis=1)
    assert np.all(np.abs(lengths - 1) < 0.05)
    plain = ctx.ao(
        gbuffer.depth, gbuffer.normals, camera=gbuffer.camera, settings={"bent_normals": True}
    )
    np.testing.assert_array_equal(ao, plain)


def test_a_moving_sequence_with_the_temporal_filter_matches_ao_sequence(ctx, cli, tmp_path):
    # Three frames orbiting the room, as `render --frames 3 --gbuffer` exports them; the record
    # of their settings goes, so both sides run the defaults with the temporal filter named.
    cli(
        "render", "--scene", "room", "--size", "48x32", "--frames", "3", "--path", "orbit",
        "--gbuffer", "--out", "s", cwd=tmp_path,
    )
    frames = tmp_path / "s" / "frames"
    (frames / "ao-settings.json").unlink()
    names = [f"{i:03}" for i in range(3)]
    depths = [aokit.read_depth(frames / f"depth-{n}.exr") for n in names]
    normals = [aokit.read_normals(frames / f"normal-{n}.exr") for n in names]
    cameras = [aokit.Camera.from_json(frames / f"camera-{n}.json") for n in names]
    settings = {"temporal.enabled": True}
    ao = ctx.ao_batch(np.stack(depths), np.stack(normals), cameras=cameras, settings=settings)
    cli(
        "ao", "--sequence", str(frames), "--set", "temporal.enabled=true", "--out", "a",
        cwd=tmp_path,
    )
    for i, n in enumerate(names):
        expected = aokit.read_depth(tmp_path / "a" / "frames" / f"ao-{n}.exr")
        np.testing.assert_array_equal(ao[i], expected, err_msg=f"frame {i}")
    # The cameras' motion matters: held still, the same frames give another history.
    still = ctx.ao_batch(
        np.stack(depths), np.stack(normals), cameras=[cameras[0]] * 3, settings=settings
    )
    assert np.abs(still[2] - ao[2]).max() > 1e-3


def test_a_guard_band_matches_the_cli(ctx, cli, tmp_path):
    cli("render", "--scene", "stairs", "--size", "48x32", "--gbuffer", "--guard-band", "8",
        "--out", "g", cwd=tmp_path)
    g = tmp_path / "g"
    (g / "ao-settings.json").unlink()
    camera = aokit.Camera.from_json(g / "camera.json")
    assert (camera.width, camera.height, camera.guard_band) == (48, 32, 8)
    depth, normals = aokit.read_depth(g / "depth.exr"), aokit.read_normals(g / "normal.exr")
    assert depth.shape == (48, 64)
    ao = ctx.ao(depth, normals, camera=camera)
    assert ao.shape == (32, 48)
    files = ["--depth", str(g / "depth.exr"), "--normals", str(g / "normal.exr")]
    cli("ao", *files, "--camera-json", str(g / "camera.json"), "--out", "a", cwd=tmp_path)
    np.testing.assert_array_equal(ao, aokit.read_depth(tmp_path / "a" / "ao.exr"))
    # The band reaches the border: the inner frame's passes alone give other AO there.
    c = camera.to_dict()
    plain = aokit.Camera.perspective(c["fov_y_deg"], 48, 32, near=c["near"], far=c["far"],
                                     view_from_world=c["view_from_world"])
    cropped = ctx.ao(depth[8:-8, 8:-8], normals[8:-8, 8:-8], camera=plain)
    assert np.abs(cropped - ao).max() > 0.01
    built = aokit.Camera.perspective(c["fov_y_deg"], 48, 32, near=c["near"], far=c["far"],
                                     view_from_world=c["view_from_world"], guard_band=8)
    assert built == camera and "guard_band=8" in repr(built)
    with pytest.raises(ValueError, match="depth: expected shape 48 x 64"):
        ctx.ao(depth[8:-8, 8:-8], camera=camera)
