// Normal encodings (CPU mirror in normals.rs).

// Octahedral mapping (Meyer et al. 2010; Cigolle et al. 2014): a unit vector to [-1, 1]^2.
// The lower hemisphere folds over the diagonals so the square is covered once.
fn oct_fold(p: vec2<f32>) -> vec2<f32> {
    let sign_p = select(vec2<f32>(-1.0), vec2<f32>(1.0), p >= vec2<f32>(0.0));
    return (1.0 - abs(p.yx)) * sign_p;
}

fn oct_encode(n: vec3<f32>) -> vec2<f32> {
    let p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    return select(oct_fold(p), p, n.z >= 0.0);
}

fn oct_decode(e: vec2<f32>) -> vec3<f32> {
    let z = 1.0 - abs(e.x) - abs(e.y);
    let xy = select(oct_fold(e), e, z >= 0.0);
    return normalize(vec3<f32>(xy, z));
}

// oct32: 16-bit unorm per octahedral coordinate, packed in one u32 (x in the low half).
fn pack_oct32(n: vec3<f32>) -> u32 {
    return pack2x16unorm(oct_encode(n) * 0.5 + 0.5);
}

fn unpack_oct32(bits: u32) -> vec3<f32> {
    return oct_decode(unpack2x16unorm(bits) * 2.0 - 1.0);
}
