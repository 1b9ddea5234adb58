//! The CPU reference tracer (`aokit-reference`) on the scenes it traces for `aokit reference`:
//! building the BVH, and tracing a small image at 16 and 64 rays per pixel on all cores. It is
//! here rather than in aokit-reference because the scenes are here. `cargo bench -p aokit-scene
//! --bench tracer`; results in docs/performance.md ("CPU parts").

use aokit_reference::{AoOptions, Tracer};
use aokit_scene::{Camera, Scene, reference};
use criterion::{Criterion, SamplingMode, Throughput, criterion_group, criterion_main};

/// Width and height of the traced image.
const SIZE: [u32; 2] = [64, 36];

struct View {
    scene: Scene,
    camera: Camera,
}

/// The built-in `room` from its first camera, and Crytek Sponza from `atrium`, opened as the CLI
/// opens them (Sponza's cameras and radius come from `scenes/sponza-cameras.json`).
fn views() -> Vec<View> {
    let sponza = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes/sponza.obj");
    [("room", None), (sponza, Some("atrium"))]
        .into_iter()
        .map(|(spec, camera)| {
            let scene = Scene::open(spec).expect("scene opens");
            let camera = scene.camera(camera).expect("camera exists");
            View { scene, camera }
        })
        .collect()
}

fn bvh_build(c: &mut Criterion, views: &[View]) {
    let mut group = c.benchmark_group("bvh_build");
    // Sponza's build takes a good part of a second: one build per sample, ten samples.
    group.sampling_mode(SamplingMode::Flat).sample_size(10);
    for View { scene, .. } in views {
        let mesh = &scene.mesh;
        group.throughput(Throughput::Elements(mesh.triangle_count() as u64));
        group.bench_function(&scene.name, |b| {
            b.iter(|| Tracer::new(&mesh.positions, &mesh.indices).expect("BVH builds"))
        });
    }
    group.finish();
}

fn trace(c: &mut Criterion, views: &[View]) {
    let mut group = c.benchmark_group(format!("trace_{}x{}", SIZE[0], SIZE[1]));
    group.sample_size(10);
    for View { scene, camera } in views {
        let tracer = reference::tracer(scene).expect("BVH builds");
        let pixels = reference::pixel_camera(scene, camera, SIZE);
        let radius = scene.suggested_radius.unwrap_or(1.0);
        let options = |spp| AoOptions {
            radius,
            spp,
            ..AoOptions::default()
        };
        // Only pixels that show a surface cast AO rays: count those once.
        let hits = tracer
            .render(&pixels, &options(1), &|_| {})
            .expect("traces")
            .linear_depth
            .iter()
            .filter(|&&depth| depth > 0.0)
            .count() as u64;
        for spp in [16, 64] {
            group.throughput(Throughput::Elements(hits * u64::from(spp)));
            group.bench_function(format!("{}@{}/{spp}spp", scene.name, camera.name), |b| {
                b.iter(|| {
                    tracer
                        .render(&pixels, &options(spp), &|_| {})
                        .expect("traces")
                })
            });
        }
    }
    group.finish();
}

fn benches(c: &mut Criterion) {
    let views = views();
    bvh_build(c, &views);
    trace(c, &views);
}

criterion_group!(tracer, benches);
criterion_main!(tracer);
