//! The CPU mirrors of the normal encodings: every `NormalEncoding` packs a fixed set of random
//! unit normals into its texture's bytes and unpacks them again. `cargo bench -p aokit --bench
//! encodings`; results in docs/performance.md ("CPU parts").

use std::hint::black_box;

use aokit::NormalEncoding;
use aokit::noise::Mt19937;
use aokit::normals::{decode_texels, encode_texels};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;

/// 64K normals: about 1 MB in and out, so the arithmetic is timed rather than memory.
const COUNT: usize = 1 << 16;

/// Uniformly random view-space unit normals facing the camera (`z >= 0`), the ones a G-buffer
/// stores and every encoding covers, from a fixed seed.
fn normals() -> Vec<Vec3> {
    let mut rng = Mt19937::new(1);
    (0..COUNT)
        .map(|_| {
            let z = rng.next_f32();
            let phi = std::f32::consts::TAU * rng.next_f32();
            let r = (1.0 - z * z).sqrt();
            Vec3::new(r * phi.cos(), r * phi.sin(), z)
        })
        .collect()
}

fn round_trip(c: &mut Criterion) {
    let normals = normals();
    let mut group = c.benchmark_group("normal_round_trip");
    group.throughput(Throughput::Elements(COUNT as u64));
    group.sample_size(30);
    for encoding in NormalEncoding::ALL {
        group.bench_function(encoding.name(), |b| {
            b.iter(|| {
                // The encoding as a caller hands it in at run time.
                let encoding = black_box(encoding);
                decode_texels(encoding, &encode_texels(encoding, black_box(&normals)))
            })
        });
    }
    group.finish();
}

criterion_group!(benches, round_trip);
criterion_main!(benches);
