"""`Context.ao_batch` runs frames as one sequence on one pipeline."""

from __future__ import annotations

import threading
import time

import numpy as np

import aokit


def frames(gbuffer, count=3):
    """The G-buffer shifted a little each frame, as a camera pan would."""
    depths = np.stack([np.roll(gbuffer.depth, i, axis=1) for i in range(count)])
    normals = np.stack([np.roll(gbuffer.normals, i, axis=1) for i in range(count)])
    return depths, normals


def test_batch_equals_per_frame(ctx, gbuffer):
    depths, normals = frames(gbuffer)
    batch = ctx.ao_batch(depths, normals, cameras=gbuffer.camera, settings={"spatial.enabled": True})
    assert batch.shape == (3, 32, 48) and batch.dtype == np.float32
    for i in range(3):
        single = ctx.ao(
            depths[i], normals[i], camera=gbuffer.camera, settings={"spatial.enabled": True}, frame_index=i
        )
        np.testing.assert_array_equal(batch[i], single)
    # A sequence of arrays and a list of cameras do the same.
    listed = ctx.ao_batch(list(depths), list(normals), cameras=[gbuffer.camera] * 3, settings={"spatial.enabled": True})
    np.testing.assert_array_equal(listed, batch)
    # Numbered from first_frame.
    later = ctx.ao_batch(depths[1:], normals[1:], cameras=gbuffer.camera, settings={"spatial.enabled": True}, first_frame=1)
    np.testing.assert_array_equal(later, batch[1:])


def test_temporal_filter_carries_across_the_batch_and_starts_over(ctx, gbuffer):
    depths, normals = frames(gbuffer, 4)
    still = np.stack([gbuffer.depth] * 4)
    settings = {"temporal.enabled": True}
    batch = ctx.ao_batch(still, np.stack([gbuffer.normals] * 4), cameras=gbuffer.camera, settings=settings)
    first = ctx.ao(gbuffer.depth, gbuffer.normals, camera=gbuffer.camera, settings=settings)
    np.testing.assert_array_equal(batch[0], first)
    # Later frames blend in the history (other noise each frame), so they differ from frame 0.
    assert not np.array_equal(batch[3], batch[0])
    # The history starts over with each call: the same batch gives the same frames.
    again = ctx.ao_batch(still, np.stack([gbuffer.normals] * 4), cameras=gbuffer.camera, settings=settings)
    np.testing.assert_array_equal(again, batch)


def test_frames_of_other_sizes_come_back_as_a_list(ctx, gbuffer):
    small = aokit.Camera.perspective(60.0, 16, 12)
    depth_small = np.full((12, 16), 2.0, dtype=np.float32)
    out = ctx.ao_batch([gbuffer.depth, depth_small], cameras=[gbuffer.camera, small])
    assert isinstance(out, list) and out[0].shape == (32, 48) and out[1].shape == (12, 16)
    np.testing.assert_array_equal(out[0], ctx.ao(gbuffer.depth, camera=gbuffer.camera))
    np.testing.assert_array_equal(out[1], ctx.ao(depth_small, camera=small, frame_index=1))


def test_bent_normals_in_a_batch(ctx, gbuffer):
    depths, normals = frames(gbuffer, 2)
    ao, bent = ctx.ao_batch(depths, normals, cameras=gbuffer.camera, bent_normals=True)
    assert ao.shape == (2, 32, 48) and bent.shape == (2, 32, 48, 3)


def test_the_gil_is_released_while_the_gpu_works(ctx):
    # A Python thread keeps counting while the pipeline runs: with the GIL held it would not
    # count at all during the native call.
    camera = aokit.Camera.perspective(60.0, 256, 256)
    depth = np.full((4, 256, 256), 3.0, dtype=np.float32)
    ctx.ao_batch(depth, cameras=camera)
    count, done = [0], [False]

    def spin():
        while not done[0]:
            count[0] += 1

    spinner = threading.Thread(target=spin, daemon=True)
    spinner.start()
    try:
        time.sleep(0.05)
        started, before = time.perf_counter(), count[0]
        ctx.ao_batch(depth, cameras=camera)
        elapsed, during = time.perf_counter() - started, count[0] - before
        before = count[0]
        time.sleep(elapsed)
        idle = count[0] - before
    finally:
        done[0] = True
        spinner.join()
    assert during > 0.02 * idle, (during, idle)


def test_adapter_kinds():
    software = aokit.Context("software")
    assert software.software
    depth = np.full((12, 16), 2.0, dtype=np.float32)
    camera = aokit.Camera.perspective(60.0, 16, 12)
    assert np.all(software.ao(depth, camera=camera) > 0.99)
    try:
        hardware = aokit.Context("hardware")
    except RuntimeError as error:
        assert "no GPU adapter" in str(error) or "no adapter" in str(error), error
    else:
        assert not hardware.software
