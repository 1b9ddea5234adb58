//! Angular error of every normal encoding over one million directions, as docs/normals.md
//! reports it: `cargo run --release --example normal_errors -p aokit`.
//!
//! Directions come from a spherical Fibonacci lattice (nearly uniform); each is encoded and
//! decoded with the CPU mirrors in `aokit::normals`, which match the WGSL bit for bit. Errors are
//! given over the whole sphere and over the hemisphere facing the eye (z >= 0), where the
//! normals of most visible surfaces lie and the only part `xy` represents.

use aokit::NormalEncoding;
use aokit::normals::{angle_degrees, decode_texel, encode_texel, fibonacci_directions};

const DIRECTIONS: u32 = 1_000_000;

/// Mean and largest error in degrees.
#[derive(Default)]
struct Errors {
    sum: f64,
    count: u64,
    max: f64,
}

impl Errors {
    fn add(&mut self, degrees: f64) {
        self.sum += degrees;
        self.count += 1;
        self.max = self.max.max(degrees);
    }

    fn mean(&self) -> f64 {
        self.sum / self.count as f64
    }
}

fn main() {
    println!(
        "| encoding | format | bits | mean, sphere | max, sphere | mean, z >= 0 | max, z >= 0 |"
    );
    println!("|---|---|---:|---:|---:|---:|---:|");
    let mut texel = Vec::new();
    for encoding in NormalEncoding::ALL {
        let (mut sphere, mut front) = (Errors::default(), Errors::default());
        for n in fibonacci_directions(DIRECTIONS) {
            texel.clear();
            encode_texel(encoding, n, &mut texel);
            let error = angle_degrees(n, decode_texel(encoding, &texel));
            sphere.add(error);
            if n.z >= 0.0 {
                front.add(error);
            }
        }
        println!(
            "| `{}` | `{:?}` | {} | {:.5} | {:.5} | {:.5} | {:.5} |",
            encoding.name(),
            encoding.texture_format(),
            encoding.bits(),
            sphere.mean(),
            sphere.max,
            front.mean(),
            front.max,
        );
    }
}
