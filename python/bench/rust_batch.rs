//! The Rust side of `overhead.py`: the frames `ao_batch` runs, run straight on
//! `aokit_scene::external::ExternalAo` as `Context.ao_batch` runs them (one pipeline, the passes
//! replaced each frame, the next submitted before the last is read), timed per batch.
//!
//! `cargo run --example rust_batch -p aokit-python -- DIR FRAMES REPEATS` reads
//! `DIR/depth_{i}.npy`, `DIR/normal_{i}.npy` and `DIR/camera.json`, runs the batch REPEATS
//! times after one warm-up and prints the mean milliseconds per batch.

use std::path::Path;
use std::time::Instant;

use aokit::{AoSettings, GpuContext, Method, Preset, Projection};
use aokit_eval::{read_depth, read_normals};
use aokit_scene::CameraFile;
use aokit_scene::external::{ExternalAo, Passes};
use glam::Vec3;

/// One frame's depth and normals with the camera's size and projection.
fn frame_passes(
    (depth, normals): &(Vec<f32>, Vec<Vec3>),
    size: [u32; 2],
    projection: Projection,
) -> Passes<'_> {
    Passes {
        size,
        linear_depth: depth,
        normals: Some(normals),
        back_depth: None,
        projection,
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let [_, dir, frames, repeats] = args.as_slice() else {
        return Err("usage: rust_batch DIR FRAMES REPEATS".into());
    };
    let dir = Path::new(dir);
    let (frames, repeats): (usize, usize) = (frames.parse()?, repeats.parse()?);
    let camera: CameraFile =
        serde_json::from_str(&std::fs::read_to_string(dir.join("camera.json"))?)?;
    let (projection, _) = camera.checked()?;
    let size = [camera.width, camera.height];
    let mut inputs = Vec::new();
    for i in 0..frames {
        let depth = read_depth(&dir.join(format!("depth_{i}.npy")))?.data;
        let normals: Vec<Vec3> = read_normals(&dir.join(format!("normal_{i}.npy")))?
            .data
            .chunks_exact(3)
            .map(Vec3::from_slice)
            .collect();
        inputs.push((depth, normals));
    }
    let passes = |frame| frame_passes(frame, size, projection);
    let gpu = GpuContext::headless()?;
    let mut external = ExternalAo::new(
        &gpu,
        &AoSettings::preset(Method::Gtao, Preset::High),
        &passes(&inputs[0]),
    )?;
    let mut run_batch = || -> Result<f32, Box<dyn std::error::Error>> {
        external.reset_history();
        let mut checksum = 0.0;
        // Each frame uploaded while the GPU runs the one before, and read back while it runs
        // the one after, as `ao_batch` does.
        let mut submitted = None;
        for (index, frame) in inputs.iter().enumerate() {
            external.set_passes(&gpu, &passes(frame))?;
            let run = external.submit(&gpu, index as u32, false)?;
            if let Some(previous) = submitted.replace(run) {
                checksum += previous.wait(&gpu)?.0[0];
            }
        }
        if let Some(last) = submitted {
            checksum += last.wait(&gpu)?.0[0];
        }
        Ok(checksum)
    };
    run_batch()?;
    let started = Instant::now();
    for _ in 0..repeats {
        run_batch()?;
    }
    let ms = started.elapsed().as_secs_f64() * 1e3 / repeats as f64;
    println!("{ms:.3}");
    Ok(())
}
