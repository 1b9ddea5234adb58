"""Shared fixtures: one GPU context, the `aokit` CLI, and a small G-buffer export it wrote."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path
from typing import Callable, List

import numpy as np
import pytest

import aokit

REPO = Path(__file__).resolve().parents[2]


def _find_cli() -> str | None:
    """The `aokit` binary: $AOKIT_BIN, else a debug or release build of this checkout."""
    if os.environ.get("AOKIT_BIN"):
        return os.environ["AOKIT_BIN"]
    targets = [Path(os.environ["CARGO_TARGET_DIR"])] if os.environ.get("CARGO_TARGET_DIR") else []
    targets.append(REPO / "target")
    for target in targets:
        for profile in ("debug", "release"):
            candidate = target / profile / "aokit"
            if candidate.is_file():
                return str(candidate)
    return shutil.which("aokit")


@pytest.fixture(scope="session")
def ctx() -> aokit.Context:
    return aokit.Context()


@pytest.fixture(scope="session")
def cli() -> Callable[..., subprocess.CompletedProcess]:
    """Runs the `aokit` CLI; skipped without one unless AOKIT_REQUIRE_CLI is set (CI)."""
    binary = _find_cli()
    if binary is None:
        if os.environ.get("AOKIT_REQUIRE_CLI"):
            pytest.fail("no aokit binary: set AOKIT_BIN or build it with `cargo build -p aokit-cli`")
        pytest.skip("no aokit binary (set AOKIT_BIN)")

    def run(*args: str, cwd: Path, check: bool = True) -> subprocess.CompletedProcess:
        out = subprocess.run(
            [binary, *args], cwd=cwd, capture_output=True, text=True, check=False
        )
        if check and out.returncode != 0:
            raise AssertionError(f"aokit {' '.join(args)} failed:\n{out.stderr}")
        return out

    return run


class GBuffer:
    """`aokit render --gbuffer` of the stairs at 48x32: depth, normals and camera."""

    def __init__(self, directory: Path) -> None:
        self.dir = directory
        self.depth_path = directory / "depth.exr"
        self.normal_path = directory / "normal.exr"
        self.camera_path = directory / "camera.json"
        self.depth = aokit.read_depth(self.depth_path)
        self.normals = aokit.read_normals(self.normal_path)
        self.camera = aokit.Camera.from_json(self.camera_path)
        self.camera_dict = json.loads(self.camera_path.read_text())


@pytest.fixture(scope="session")
def gbuffer(cli, tmp_path_factory) -> GBuffer:
    root = tmp_path_factory.mktemp("gbuffer")
    cli("render", "--scene", "stairs", "--size", "48x32", "--gbuffer", "--out", "g", cwd=root)
    # The parity tests compare the package's defaults with the CLI's: without the settings the
    # render recorded (the stairs' radius 0.5), `aokit ao` runs its defaults too.
    (root / "g" / "ao-settings.json").unlink()
    return GBuffer(root / "g")


@pytest.fixture()
def cli_ao(cli, gbuffer, tmp_path) -> Callable[..., np.ndarray]:
    """`aokit ao` on the G-buffer (or other files), returning ao.exr."""

    def run(*args: str, depth: Path | None = None, normals: Path | None | bool = True) -> np.ndarray:
        files: List[str] = ["--depth", str(depth or gbuffer.depth_path)]
        if normals is True:
            files += ["--normals", str(gbuffer.normal_path)]
        elif normals:
            files += ["--normals", str(normals)]
        out = tmp_path / "out"
        cli("ao", *files, "--camera-json", str(gbuffer.camera_path), *args, "--out", str(out), cwd=tmp_path)
        return aokit.read_depth(out / "ao.exr")

    return run
