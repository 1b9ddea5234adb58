//! CPU mirrors of the WGSL normal encodings in `shaders/common/encoding.wgsl`, for tests and for
//! tools that decode G-buffers on the CPU.

use glam::{Vec2, Vec3};

fn oct_fold(p: Vec2) -> Vec2 {
    let sign = Vec2::new(
        if p.x >= 0.0 { 1.0 } else { -1.0 },
        if p.y >= 0.0 { 1.0 } else { -1.0 },
    );
    (Vec2::ONE - Vec2::new(p.y.abs(), p.x.abs())) * sign
}

/// Octahedral encoding of a unit vector into `[-1, 1]^2`.
pub fn oct_encode(n: Vec3) -> Vec2 {
    let p = Vec2::new(n.x, n.y) / (n.x.abs() + n.y.abs() + n.z.abs());
    if n.z >= 0.0 { p } else { oct_fold(p) }
}

/// Inverse of [`oct_encode`].
pub fn oct_decode(e: Vec2) -> Vec3 {
    let z = 1.0 - e.x.abs() - e.y.abs();
    let xy = if z >= 0.0 { e } else { oct_fold(e) };
    xy.extend(z).normalize()
}

/// `pack2x16unorm` as WGSL defines it: x in the low 16 bits.
fn pack2x16unorm(v: Vec2) -> u32 {
    let q = |x: f32| (x.clamp(0.0, 1.0) * 65535.0 + 0.5).floor() as u32;
    q(v.x) | (q(v.y) << 16)
}

fn unpack2x16unorm(bits: u32) -> Vec2 {
    Vec2::new(
        (bits & 0xffff) as f32 / 65535.0,
        (bits >> 16) as f32 / 65535.0,
    )
}

/// The `oct32` G-buffer encoding: octahedral coordinates as two 16-bit unorms in one `u32`.
pub fn pack_oct32(n: Vec3) -> u32 {
    pack2x16unorm(oct_encode(n) * 0.5 + 0.5)
}

/// Inverse of [`pack_oct32`].
pub fn unpack_oct32(bits: u32) -> Vec3 {
    oct_decode(unpack2x16unorm(bits) * 2.0 - 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Directions spread over the sphere by a Fibonacci lattice, poles and axes included.
    fn directions() -> impl Iterator<Item = Vec3> {
        let count = 20_000;
        let golden = std::f32::consts::PI * (3.0 - 5f32.sqrt());
        let lattice = (0..count).map(move |i| {
            let z = 1.0 - 2.0 * (i as f32 + 0.5) / count as f32;
            let r = (1.0 - z * z).sqrt();
            let phi = golden * i as f32;
            Vec3::new(r * phi.cos(), r * phi.sin(), z)
        });
        lattice.chain([
            Vec3::X,
            Vec3::NEG_X,
            Vec3::Y,
            Vec3::NEG_Y,
            Vec3::Z,
            Vec3::NEG_Z,
        ])
    }

    #[test]
    fn octahedral_mapping_round_trips_exactly_before_quantisation() {
        for n in directions() {
            let back = oct_decode(oct_encode(n));
            assert!((back - n).length() < 1e-5, "{n} -> {back}");
        }
    }

    #[test]
    fn oct32_error_is_below_a_hundredth_of_a_degree() {
        // In f64: an f32 acos near 1 alone is off by 0.02 degrees.
        let worst = directions()
            .map(|n| {
                let (a, b) = (n.as_dvec3(), unpack_oct32(pack_oct32(n)).as_dvec3());
                a.cross(b).length().atan2(a.dot(b)).to_degrees()
            })
            .fold(0.0f64, f64::max);
        assert!(worst < 0.01, "worst angular error {worst} degrees");
    }
}
