"""The CPU reference tracer against closed forms, and the metrics of `aokit compare`."""

from __future__ import annotations

import numpy as np
import pytest

import aokit


def quad(y: float, half: float = 50.0):
    """A horizontal square at height y, facing up."""
    v = np.array([[-half, y, -half], [half, y, -half], [half, y, half], [-half, y, half]])
    return v, np.array([[0, 2, 1], [0, 3, 2]])


def looking_down(eye_height: float, size=(24, 16)) -> aokit.Camera:
    # View axes in world space: x right = +X, y up = -Z, looking down -Y (view +Z = world +Y).
    rotation = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], dtype=np.float64)
    view = np.eye(4)
    view[:3, :3] = rotation
    view[:3, 3] = -rotation @ np.array([0.0, eye_height, 0.0])
    return aokit.Camera.perspective(50.0, size[0], size[1], near=0.01, view_from_world=view)


def test_an_open_plane_is_unoccluded():
    vertices, indices = quad(0.0)
    ao, depth, normals = aokit.reference(vertices, indices, looking_down(3.0), radius=1.0, spp=16, gbuffer=True)
    assert ao.shape == (16, 24) and ao.dtype == np.float32
    assert np.all(depth > 0)
    np.testing.assert_allclose(depth, 3.0, rtol=1e-5)
    np.testing.assert_allclose(normals, np.tile([0, 0, 1], (16, 24, 1)), atol=1e-5)
    assert np.all(ao == 1.0)


def test_between_two_planes_ao_is_the_squared_height_ratio():
    # Cosine-weighted rays from a floor with a ceiling h above, radius R >= h: the unoccluded
    # fraction is (h / R)^2 (docs/reference.md).
    floor_v, floor_i = quad(0.0)
    ceiling_v, ceiling_i = quad(0.5)
    vertices = np.concatenate([floor_v, ceiling_v]).astype(np.float32)
    indices = np.concatenate([floor_i, ceiling_i + 4]).astype(np.int64)
    ao = aokit.reference(vertices, indices, looking_down(0.25, (8, 8)), radius=1.0, spp=1024)
    assert abs(float(ao.mean()) - 0.25) < 0.01


def test_reference_inputs_are_checked():
    vertices, indices = quad(0.0)
    camera = looking_down(3.0)
    with pytest.raises(ValueError, match="vertices: expected shape"):
        aokit.reference(vertices[:, :2], indices, camera, 1.0, 4)
    with pytest.raises(ValueError, match="indices: values must lie in 0..3"):
        aokit.reference(vertices, indices + 4, camera, 1.0, 4)
    with pytest.raises(TypeError, match="indices: expected an integer array"):
        aokit.reference(vertices, indices.astype(float), camera, 1.0, 4)
    with pytest.raises(ValueError, match="spp"):
        aokit.reference(vertices, indices, camera, 1.0, 0)
    with pytest.raises(ValueError, match="radius"):
        aokit.reference(vertices, indices, camera, -1.0, 4)


def test_metrics_of_known_errors():
    rng = np.random.default_rng(1)
    reference = rng.uniform(0.2, 0.8, (20, 30)).astype(np.float32)
    same = aokit.metrics(reference, reference)
    assert same["pixels"] == 600 and same["rmse"] == 0 and same["mae"] == 0
    assert same["ssim"] == pytest.approx(1.0)
    brighter = aokit.metrics(reference + 0.1, reference)
    assert brighter["bias"] == pytest.approx(0.1, abs=1e-6)
    assert brighter["rmse"] == pytest.approx(0.1, abs=1e-6)
    assert brighter["mae"] == pytest.approx(0.1, abs=1e-6)
    mask = np.zeros((20, 30), dtype=bool)
    mask[:5] = True
    assert aokit.metrics(reference, reference, mask)["pixels"] == 150
    assert np.isnan(aokit.metrics(reference, reference, np.zeros_like(mask))["rmse"])
    with pytest.raises(ValueError, match="reference: expected shape 20 x 30"):
        aokit.metrics(reference, reference[:4])
    with pytest.raises(ValueError, match="mask: expected shape 20 x 30"):
        aokit.metrics(reference, reference, mask[:4])


def test_exr_round_trip(tmp_path):
    values = np.linspace(0, 1, 12 * 7, dtype=np.float32).reshape(7, 12)
    aokit.write_exr(tmp_path / "ao.exr", values)
    np.testing.assert_array_equal(aokit.read_depth(tmp_path / "ao.exr"), values)
    with pytest.raises(OSError):
        aokit.read_depth(tmp_path / "missing.exr")
