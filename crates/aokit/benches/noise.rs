//! Noise on the CPU: making the tiles the noise textures are filled with, and the per-pixel
//! mirrors of `shaders/common/noise.wgsl` over a 1080p frame. `cargo bench -p aokit --bench
//! noise`; results in docs/performance.md ("CPU parts").

use std::hint::black_box;

use aokit::noise::{self, Mt19937};
use aokit::{NoiseKind, NoiseSettings};
use criterion::{Criterion, SamplingMode, Throughput, criterion_group, criterion_main};

/// One channel of the blue-noise tile, as [`noise::blue_noise`] makes each of its two.
fn void_and_cluster(c: &mut Criterion) {
    let mut group = c.benchmark_group("void_and_cluster");
    // Tens to hundreds of milliseconds an iteration: one iteration per sample, ten samples.
    group.sampling_mode(SamplingMode::Flat).sample_size(10);
    for size in [64, 128] {
        group.throughput(Throughput::Elements((size * size) as u64));
        group.bench_function(format!("{size}x{size}"), |b| {
            b.iter(|| noise::void_and_cluster(black_box(size), 1))
        });
    }
    group.finish();
}

/// The white-noise tile (seed the generator, 16 texels of two values), and the generator's
/// steady output.
fn mersenne_twister(c: &mut Criterion) {
    let mut group = c.benchmark_group("mt19937");
    group.throughput(Throughput::Elements(16));
    group.bench_function("tile_4x4", |b| {
        b.iter(|| {
            let mut rng = Mt19937::new(black_box(5489));
            [(); 16].map(|_| [rng.next_f32(), rng.next_f32()])
        })
    });
    const VALUES: u32 = 1 << 16;
    group.throughput(Throughput::Elements(u64::from(VALUES)));
    let mut rng = Mt19937::new(5489);
    group.bench_function("next_u32", |b| {
        b.iter(|| (0..VALUES).fold(0u32, |acc, _| acc ^ rng.next_u32()))
    });
    group.finish();
}

const WIDTH: u32 = 1920;
const HEIGHT: u32 = 1080;

/// `f` summed over every pixel of a 1920x1080 frame, so none of it is optimised away.
fn over_frame(f: impl Fn([u32; 2]) -> [f32; 2]) -> f32 {
    let mut sum = 0.0;
    for y in 0..HEIGHT {
        for x in 0..WIDTH {
            let [a, b] = f([x, y]);
            sum += a + b;
        }
    }
    sum
}

/// [`noise::pixel_noise`] of every kind at every pixel of a 1080p frame, and the Sobol and
/// Halton sequences ([`noise::sobol_2d`], [`noise::halton_3`]) at as many indices.
fn per_pixel(c: &mut Criterion) {
    let mut group = c.benchmark_group("per_pixel_1920x1080");
    group.throughput(Throughput::Elements(u64::from(WIDTH * HEIGHT)));
    // 15 to 45 ms an iteration: ten samples keep a kind to a few seconds.
    group.sample_size(10);
    for kind in NoiseKind::ALL {
        let settings = NoiseSettings {
            kind,
            ..NoiseSettings::default()
        };
        // The blue tile is made on first use: make it before timing.
        noise::tile(&settings);
        group.bench_function(kind.name(), |b| {
            b.iter(|| over_frame(|pixel| noise::pixel_noise(black_box(&settings), pixel, 7)))
        });
    }
    let index = |[x, y]: [u32; 2]| black_box(y * WIDTH + x);
    group.bench_function("sobol_2d", |b| {
        b.iter(|| over_frame(|pixel| noise::sobol_2d(index(pixel))))
    });
    group.bench_function("halton_3", |b| {
        b.iter(|| over_frame(|pixel| [noise::halton_3(index(pixel)), 0.0]))
    });
    group.finish();
}

criterion_group!(benches, void_and_cluster, mersenne_twister, per_pixel);
criterion_main!(benches);
