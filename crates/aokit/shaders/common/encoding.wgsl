// Normal encodings (CPU mirror in normals.rs; docs/normals.md has each one's format and error).
//
// Every encoding stores a unit vector in one texel of the format `NormalEncoding::texture_format`
// names. Encodings into `R32Uint` return the texel's bits; encodings into unorm formats return the
// value a shader writes, already rounded to the format's grid, so that the fixed-function
// conversion on the way into the texture is exact and the CPU mirror can reproduce the bits
// (half floats are left to the texture's rounding, which the mirror takes as to nearest).
// Normal textures are read with textureLoad, never filtered: a filtered texel mixes the encodings
// of different surfaces, which decodes to a direction none of them has (ybniaobu 2025,
// "Screen-space ambient occlusion (1): SSAO", a blog post in Chinese, section "Normal Encoding").

// Encoding codes, `NormalEncoding::shader_code` in Rust (a test compares the two).
const ENCODING_OCT32: u32 = 0u;
const ENCODING_OCT24: u32 = 1u;
const ENCODING_OCT16: u32 = 2u;
const ENCODING_OCT20: u32 = 3u;
const ENCODING_RGB10A2: u32 = 4u;
const ENCODING_RGBA16F: u32 = 5u;
const ENCODING_XY: u32 = 6u;
const ENCODING_SPHERICAL: u32 = 7u;
const ENCODING_STEREOGRAPHIC: u32 = 8u;
const ENCODING_LAMBERT: u32 = 9u;

const ENCODING_PI: f32 = 3.14159265;

// Largest stereographic radius stored: |xy| / (1 + z) <= 4 holds every normal within 152 degrees
// of +z (z >= -15/17), which covers the visible surfaces of cameras up to 62 degrees from the
// view axis to the image corner; beyond it the radius is clamped, keeping the azimuth.
const STEREOGRAPHIC_RANGE: f32 = 4.0;

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

// Values in [0, 1] as integers of `levels` steps, rounded as WGSL's pack4x8unorm rounds.
fn unorm_steps(x: vec4<f32>, levels: f32) -> vec4<f32> {
    return floor(saturate(x) * levels + 0.5);
}

// unorm_steps divided back: what a unorm texel of `levels` steps stores exactly.
fn unorm_grid(x: vec4<f32>, levels: f32) -> vec4<f32> {
    return unorm_steps(x, levels) / levels;
}

// oct32: 16-bit unorm per octahedral coordinate, packed in one u32 (x in the low half).
fn pack_oct32(n: vec3<f32>) -> u32 {
    return pack2x16unorm(oct_encode(n) * 0.5 + 0.5);
}

fn unpack_oct32(bits: u32) -> vec3<f32> {
    return oct_decode(unpack2x16unorm(bits) * 2.0 - 1.0);
}

// oct24: 12 bits per octahedral coordinate in the RGB bytes of an Rgba8Unorm texel: the low
// 8 bits of x in R, of y in G, the high 4 bits of x in B's low nibble and of y in its high one.
fn pack_oct24(n: vec3<f32>) -> vec4<f32> {
    let q = vec2<u32>(unorm_steps(vec4<f32>(oct_encode(n) * 0.5 + 0.5, 0.0, 0.0), 4095.0).xy);
    let bytes = vec3<u32>(q & vec2<u32>(255u), (q.x >> 8u) | ((q.y >> 8u) << 4u));
    return vec4<f32>(vec3<f32>(bytes) / 255.0, 0.0);
}

fn unpack_oct24(texel: vec4<f32>) -> vec3<f32> {
    let bytes = vec3<u32>(texel.rgb * 255.0 + 0.5);
    let q = vec2<u32>(bytes.r | ((bytes.b & 15u) << 8u), bytes.g | ((bytes.b >> 4u) << 8u));
    return oct_decode(vec2<f32>(q) / 4095.0 * 2.0 - 1.0);
}

// xy: x and y as two 16-bit snorms; z is taken as facing the eye (+z), which mirrors normals of
// visible surfaces that face away from the view axis (possible off-centre at grazing angles).
fn pack_xy(n: vec3<f32>) -> u32 {
    return pack2x16snorm(n.xy);
}

fn unpack_xy(bits: u32) -> vec3<f32> {
    let xy = unpack2x16snorm(bits);
    return normalize(vec3<f32>(xy, sqrt(max(0.0, 1.0 - dot(xy, xy)))));
}

// spherical: azimuth over the full turn and polar angle from +z, each as a 16-bit unorm.
// atan2 of the two sides keeps the polar angle precise near the poles, where acos(z) is not.
fn pack_spherical(n: vec3<f32>) -> u32 {
    let azimuth = atan2(n.y, n.x);
    let polar = atan2(length(n.xy), n.z);
    return pack2x16unorm(vec2<f32>(azimuth / (2.0 * ENCODING_PI) + 0.5, polar / ENCODING_PI));
}

fn unpack_spherical(bits: u32) -> vec3<f32> {
    let e = unpack2x16unorm(bits);
    let azimuth = (e.x - 0.5) * 2.0 * ENCODING_PI;
    let polar = e.y * ENCODING_PI;
    return vec3<f32>(sin(polar) * vec2<f32>(cos(azimuth), sin(azimuth)), cos(polar));
}

// The unit direction of `xy`, +x for the zero vector (the -z pole, whose azimuth is arbitrary).
fn encoding_azimuth(xy: vec2<f32>) -> vec2<f32> {
    let len = length(xy);
    return select(vec2<f32>(1.0, 0.0), xy / len, len > 0.0);
}

// stereographic: projection from the -z pole (away from the eye, where no visible normal points)
// onto the plane z = 0, xy / (1 + z), clamped to STEREOGRAPHIC_RANGE. Below the equator the radius
// is computed as (1 - z) / |xy|, which equals it without the cancellation in 1 + z.
fn pack_stereographic(n: vec3<f32>) -> u32 {
    var s: vec2<f32>;
    if n.z >= 0.0 {
        s = n.xy / (1.0 + n.z);
    } else {
        // max() keeps the -z pole finite; min() clamps it and its neighbours to the range.
        let radius = (1.0 - n.z) / max(length(n.xy), 1e-30);
        s = encoding_azimuth(n.xy) * min(radius, STEREOGRAPHIC_RANGE);
    }
    return pack2x16unorm(s / (2.0 * STEREOGRAPHIC_RANGE) + 0.5);
}

fn unpack_stereographic(bits: u32) -> vec3<f32> {
    let s = (unpack2x16unorm(bits) - 0.5) * (2.0 * STEREOGRAPHIC_RANGE);
    let d = dot(s, s);
    return vec3<f32>(2.0 * s, 1.0 - d) / (1.0 + d);
}

// lambert: Lambert azimuthal equal-area projection from the -z pole, xy * sqrt(2 / (1 + z)), a
// disc of radius 2 stored as two 16-bit unorms. Below the equator the radius is computed as
// sqrt(2 (1 - z)), which equals it without the cancellation in 1 + z.
fn pack_lambert(n: vec3<f32>) -> u32 {
    var s: vec2<f32>;
    if n.z >= 0.0 {
        s = n.xy * sqrt(2.0 / (1.0 + n.z));
    } else {
        s = encoding_azimuth(n.xy) * sqrt(2.0 * (1.0 - n.z));
    }
    return pack2x16unorm(s * 0.25 + 0.5);
}

fn unpack_lambert(bits: u32) -> vec3<f32> {
    let s = unpack2x16unorm(bits) * 4.0 - 2.0;
    let d = dot(s, s);
    return normalize(vec3<f32>(s * sqrt(max(0.0, 1.0 - 0.25 * d)), 1.0 - 0.5 * d));
}

// Encodings stored in R32Uint texels: oct32, xy, spherical, stereographic, lambert.
fn encode_normal_uint(n: vec3<f32>, encoding: u32) -> u32 {
    switch encoding {
        case ENCODING_XY: { return pack_xy(n); }
        case ENCODING_SPHERICAL: { return pack_spherical(n); }
        case ENCODING_STEREOGRAPHIC: { return pack_stereographic(n); }
        case ENCODING_LAMBERT: { return pack_lambert(n); }
        default: { return pack_oct32(n); }
    }
}

fn decode_normal_uint(bits: u32, encoding: u32) -> vec3<f32> {
    switch encoding {
        case ENCODING_XY: { return unpack_xy(bits); }
        case ENCODING_SPHERICAL: { return unpack_spherical(bits); }
        case ENCODING_STEREOGRAPHIC: { return unpack_stereographic(bits); }
        case ENCODING_LAMBERT: { return unpack_lambert(bits); }
        default: { return unpack_oct32(bits); }
    }
}

// Shortest and longest stored vector taken for a unit normal (`normals::USABLE_LENGTH` in Rust;
// a test compares them): 8- and 10-bit quantisation and interpolated, unrenormalised normals are
// off by far less, and a vector outside is not a normal at all (a cleared or garbage texel).
const USABLE_LENGTH_MIN: f32 = 0.5;
const USABLE_LENGTH_MAX: f32 = 2.0;

// Whether every component of `v` is finite. Tested on the bits: WGSL lets the compiler assume
// floats are never NaN or infinite, so a comparison may be folded away.
fn all_finite(v: vec3<f32>) -> bool {
    let exponent = vec3<u32>(0x7f800000u);
    return all((bitcast<vec3<u32>>(v) & exponent) != exponent);
}

// Whether a texel of a float encoding holds a normal. The encodings that store the vector itself
// (rgb10a2, rgba16f) can hold one that is zero, NaN, infinite or of any length; the octahedral
// ones store a direction, which every texel decodes to.
fn normal_texel_usable(texel: vec4<f32>, encoding: u32) -> bool {
    var v: vec3<f32>;
    switch encoding {
        case ENCODING_RGB10A2: { v = texel.xyz * 2.0 - 1.0; }
        case ENCODING_RGBA16F: { v = texel.xyz; }
        default: { return true; }
    }
    let length_squared = dot(v, v);
    return all_finite(v) && length_squared >= USABLE_LENGTH_MIN * USABLE_LENGTH_MIN
        && length_squared <= USABLE_LENGTH_MAX * USABLE_LENGTH_MAX;
}

// Encodings stored in unorm or float texels: oct24, oct16, oct20, rgb10a2, rgba16f. The value
// written is what the texture holds: oct16 in an Rg8Unorm texel keeps only its first two channels.
fn encode_normal_float(n: vec3<f32>, encoding: u32) -> vec4<f32> {
    let oct = vec4<f32>(oct_encode(n) * 0.5 + 0.5, 0.0, 0.0);
    switch encoding {
        case ENCODING_OCT24: { return pack_oct24(n); }
        case ENCODING_OCT16: { return unorm_grid(oct, 255.0); }
        case ENCODING_OCT20: { return unorm_grid(oct, 1023.0); }
        case ENCODING_RGB10A2: { return unorm_grid(vec4<f32>(n * 0.5 + 0.5, 0.0), 1023.0); }
        default: { return vec4<f32>(n, 0.0); }
    }
}

fn decode_normal_float(texel: vec4<f32>, encoding: u32) -> vec3<f32> {
    switch encoding {
        case ENCODING_OCT24: { return unpack_oct24(texel); }
        case ENCODING_OCT16, ENCODING_OCT20: { return oct_decode(texel.xy * 2.0 - 1.0); }
        case ENCODING_RGB10A2: { return normalize(texel.xyz * 2.0 - 1.0); }
        // A cleared texel (no surface) decodes to +z rather than normalize's undefined result.
        default: { return normalize(select(texel.xyz, vec3<f32>(0.0, 0.0, 1.0), all(texel.xyz == vec3<f32>(0.0)))); }
    }
}
