//! CPU mirrors of the WGSL normal encodings in `shaders/common/encoding.wgsl`: the same arithmetic
//! in the same order, quantisation included, for tests, for tools that decode G-buffers on the
//! CPU, and for uploading normals computed on the CPU. docs/normals.md has each encoding's
//! texture format and measured error.
//!
//! Each encoding has a `pack_*` / `unpack_*` pair on the texel as its format stores it, and
//! [`encode_texels`] / [`decode_texels`] convert whole images to and from the bytes of
//! [`NormalEncoding::texture_format`] textures.

use glam::{DVec3, Vec2, Vec3};

use crate::gpu::{f16_to_f32, f32_to_f16};
use crate::settings::NormalEncoding;

/// Largest stereographic radius stored, `STEREOGRAPHIC_RANGE` in WGSL: `|xy| / (1 + z) <= 4`
/// holds every normal within 152 degrees of +z (`z >= -15/17`), which covers the visible surfaces
/// of cameras up to 62 degrees from the view axis to the image corner.
///
/// ```
/// use aokit::normals::{
///     STEREOGRAPHIC_RANGE, angle_degrees, pack_stereographic, unpack_stereographic,
/// };
/// use glam::Vec3;
/// // The edge of the range: z = -15/17, where |xy| / (1 + z) = 4.
/// let edge = Vec3::new(8.0 / 17.0, 0.0, -15.0 / 17.0);
/// assert!((edge.x / (1.0 + edge.z) - STEREOGRAPHIC_RANGE).abs() < 1e-5);
/// assert!(angle_degrees(edge, unpack_stereographic(pack_stereographic(edge))) < 0.1);
/// ```
pub const STEREOGRAPHIC_RANGE: f32 = 4.0;

/// Shortest and longest vector taken for a unit normal (and normalised) where one is stored as
/// its components (`rgba16f`, `rgb10a2`, normals handed over on the CPU); `USABLE_LENGTH_MIN`
/// and `USABLE_LENGTH_MAX` in WGSL. Quantisation to 8 or 10 bits and interpolated normals left
/// unnormalised are off by far less; a vector outside is not a normal at all.
///
/// ```
/// use aokit::normals::USABLE_LENGTH;
/// // An 8-bit unorm component is off by up to 1/255: a unit normal stays well inside.
/// let worst = 3f32.sqrt() / 255.0;
/// assert!(USABLE_LENGTH.contains(&(1.0 - worst)) && USABLE_LENGTH.contains(&(1.0 + worst)));
/// assert!(!USABLE_LENGTH.contains(&0.0));
/// ```
pub const USABLE_LENGTH: std::ops::RangeInclusive<f32> = 0.5..=2.0;

/// Whether `n` can be taken for a normal: finite, with a length within [`USABLE_LENGTH`]. The
/// pipeline's decode reconstructs the normal from depth at a texel that fails this
/// (docs/normals.md, "Unusable normals").
///
/// ```
/// use aokit::normals::is_usable;
/// use glam::Vec3;
/// assert!(is_usable(Vec3::new(0.0, 0.0, 0.98)));
/// assert!(!is_usable(Vec3::ZERO));
/// assert!(!is_usable(Vec3::new(f32::NAN, 0.0, 1.0)));
/// assert!(!is_usable(Vec3::new(0.0, f32::INFINITY, 0.0)));
/// assert!(!is_usable(Vec3::new(3.0, 0.0, 0.0)));
/// ```
pub fn is_usable(n: Vec3) -> bool {
    n.is_finite() && USABLE_LENGTH.contains(&n.length())
}

impl NormalEncoding {
    /// The texture format that holds one encoded normal per texel.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device) {
    /// use aokit::NormalEncoding;
    /// // The G-buffer target a renderer draws its normals into.
    /// let encoding = NormalEncoding::Oct16;
    /// let normals = aokit::gpu::create_texture_2d(device, "normals", [1920, 1080],
    ///     encoding.texture_format(),
    ///     wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING);
    /// assert_eq!(normals.format(), wgpu::TextureFormat::Rg8Unorm);
    /// # }
    /// ```
    pub fn texture_format(self) -> wgpu::TextureFormat {
        use wgpu::TextureFormat as F;
        match self {
            NormalEncoding::Oct32
            | NormalEncoding::Xy
            | NormalEncoding::Spherical
            | NormalEncoding::Stereographic
            | NormalEncoding::Lambert => F::R32Uint,
            NormalEncoding::Oct24 => F::Rgba8Unorm,
            NormalEncoding::Oct16 => F::Rg8Unorm,
            NormalEncoding::Oct20 | NormalEncoding::Rgb10a2 => F::Rgb10a2Unorm,
            NormalEncoding::Rgba16f => F::Rgba16Float,
        }
    }

    /// Bits of the texel that hold the normal (the rest, if any, is free for other data).
    ///
    /// ```
    /// use aokit::NormalEncoding;
    /// // Encodings that leave a byte or more of their texel for something else.
    /// let spare: Vec<&str> = NormalEncoding::ALL
    ///     .into_iter()
    ///     .filter(|e| 8 * e.texel_size() as u32 - e.bits() >= 8)
    ///     .map(|e| e.name())
    ///     .collect();
    /// assert_eq!(spare, ["oct24", "oct20", "rgba16f"]);
    /// ```
    pub fn bits(self) -> u32 {
        match self {
            NormalEncoding::Oct16 => 16,
            NormalEncoding::Oct20 => 20,
            NormalEncoding::Oct24 => 24,
            NormalEncoding::Rgb10a2 => 30,
            NormalEncoding::Rgba16f => 48,
            NormalEncoding::Oct32
            | NormalEncoding::Xy
            | NormalEncoding::Spherical
            | NormalEncoding::Stereographic
            | NormalEncoding::Lambert => 32,
        }
    }

    /// The encoding's code in WGSL (`ENCODING_*` in `encoding.wgsl`), as `encode_normal_uint`,
    /// `decode_normal_float` and the other dispatching functions take it.
    ///
    /// ```
    /// use aokit::NormalEncoding;
    /// // For a shader of one's own with `override ENCODING: u32;` that calls
    /// // `encode_normal_uint(n, ENCODING)`: the encoding is fixed when the pipeline is made.
    /// let constants = [("ENCODING", f64::from(NormalEncoding::Oct32.shader_code()))];
    /// let options =
    ///     wgpu::PipelineCompilationOptions { constants: &constants, ..Default::default() };
    /// assert_eq!(options.constants, &[("ENCODING", 0.0)]);
    /// // One code per encoding, so that the override picks exactly one.
    /// let codes: Vec<u32> = NormalEncoding::ALL.iter().map(|e| e.shader_code()).collect();
    /// assert!(codes.iter().enumerate().all(|(i, code)| !codes[..i].contains(code)));
    /// ```
    pub fn shader_code(self) -> u32 {
        self as u32
    }

    /// Whether shaders read and write the texel as a `u32` (`encode_normal_uint`,
    /// `decode_normal_uint`) rather than as floats (`encode_normal_float`, `decode_normal_float`).
    ///
    /// ```
    /// use aokit::NormalEncoding;
    /// // A fragment shader writes `u32` targets and float targets from different entry points.
    /// let entry_point = |e: NormalEncoding| if e.is_uint() { "fs_uint" } else { "fs_float" };
    /// assert_eq!(entry_point(NormalEncoding::Lambert), "fs_uint");
    /// assert_eq!(entry_point(NormalEncoding::Oct24), "fs_float");
    /// ```
    pub fn is_uint(self) -> bool {
        self.texture_format() == wgpu::TextureFormat::R32Uint
    }

    /// Bytes of one texel.
    ///
    /// ```
    /// use aokit::NormalEncoding;
    /// // Memory of a 4K G-buffer's normals.
    /// let bytes = 3840 * 2160 * NormalEncoding::Rgba16f.texel_size();
    /// assert_eq!(bytes, 3840 * 2160 * 8);
    /// ```
    pub fn texel_size(self) -> usize {
        self.texture_format()
            .block_copy_size(None)
            .expect("normal formats are single-aspect") as usize
    }
}

fn oct_fold(p: Vec2) -> Vec2 {
    let sign = Vec2::new(
        if p.x >= 0.0 { 1.0 } else { -1.0 },
        if p.y >= 0.0 { 1.0 } else { -1.0 },
    );
    (Vec2::ONE - Vec2::new(p.y.abs(), p.x.abs())) * sign
}

/// Octahedral encoding of a unit vector into `[-1, 1]^2`.
///
/// ```
/// use aokit::normals::oct_encode;
/// use glam::{Vec2, Vec3};
/// // The front hemisphere fills the inner diamond; the back folds out to the corners.
/// assert_eq!(oct_encode(Vec3::Z), Vec2::ZERO);
/// assert_eq!(oct_encode(Vec3::X), Vec2::X);
/// assert_eq!(oct_encode(Vec3::NEG_Z), Vec2::ONE);
/// ```
pub fn oct_encode(n: Vec3) -> Vec2 {
    let p = Vec2::new(n.x, n.y) / (n.x.abs() + n.y.abs() + n.z.abs());
    if n.z >= 0.0 { p } else { oct_fold(p) }
}

/// Inverse of [`oct_encode`].
///
/// ```
/// use aokit::normals::{oct_decode, oct_encode};
/// use glam::Vec3;
/// let n = Vec3::new(-0.3, 0.8, -0.52).normalize();
/// // Exact up to rounding: the precision is lost only when the coordinates are quantised.
/// assert!((oct_decode(oct_encode(n)) - n).length() < 1e-6);
/// ```
pub fn oct_decode(e: Vec2) -> Vec3 {
    let z = 1.0 - e.x.abs() - e.y.abs();
    let xy = if z >= 0.0 { e } else { oct_fold(e) };
    xy.extend(z).normalize()
}

/// A value in `[0, 1]` as an integer of `levels` steps, rounded as WGSL's `pack4x8unorm` rounds.
fn unorm_steps(x: f32, levels: f32) -> u32 {
    (x.clamp(0.0, 1.0) * levels + 0.5).floor() as u32
}

/// `pack2x16unorm` as WGSL defines it: x in the low 16 bits.
fn pack2x16unorm(v: Vec2) -> u32 {
    unorm_steps(v.x, 65535.0) | (unorm_steps(v.y, 65535.0) << 16)
}

fn unpack2x16unorm(bits: u32) -> Vec2 {
    Vec2::new(
        (bits & 0xffff) as f32 / 65535.0,
        (bits >> 16) as f32 / 65535.0,
    )
}

/// `pack2x16snorm` as WGSL defines it: `floor(0.5 + 32767 * clamp(x, -1, 1))`, x low.
fn pack2x16snorm(v: Vec2) -> u32 {
    let q = |x: f32| ((x.clamp(-1.0, 1.0) * 32767.0 + 0.5).floor() as i16) as u16 as u32;
    q(v.x) | (q(v.y) << 16)
}

fn unpack2x16snorm(bits: u32) -> Vec2 {
    let s = |half: u32| (half as u16 as i16 as f32 / 32767.0).max(-1.0);
    Vec2::new(s(bits & 0xffff), s(bits >> 16))
}

/// Four 10-, 10-, 10- and 2-bit unorm steps as an `Rgb10a2Unorm` texel stores them, red lowest.
fn rgb10a2_bits(steps: [u32; 3]) -> u32 {
    steps[0] | (steps[1] << 10) | (steps[2] << 20)
}

/// The three 10-bit channels of an `Rgb10a2Unorm` texel, as the texture unit reads them.
fn rgb10a2_channels(bits: u32) -> Vec3 {
    let channel = |shift: u32| ((bits >> shift) & 1023) as f32 / 1023.0;
    Vec3::new(channel(0), channel(10), channel(20))
}

/// The octahedral coordinates of `n` in `[0, 1]^2`, as unorm encodings store them.
fn oct_unorm(n: Vec3) -> Vec2 {
    oct_encode(n) * 0.5 + 0.5
}

/// The `oct32` encoding: octahedral coordinates as two 16-bit unorms in one `u32`.
///
/// ```
/// use aokit::normals::pack_oct32;
/// use glam::Vec3;
/// // Facing the eye is the middle of the octahedral square: half of each 16-bit range.
/// assert_eq!(pack_oct32(Vec3::Z), 0x8000_8000);
/// // Texels for an `R32Uint` texture, x in the low half as `pack2x16unorm` puts it.
/// let texels: Vec<u32> = [Vec3::Z, Vec3::X].map(pack_oct32).to_vec();
/// assert_eq!(texels[1] & 0xffff, 0xffff);
/// ```
pub fn pack_oct32(n: Vec3) -> u32 {
    pack2x16unorm(oct_unorm(n))
}

/// Inverse of [`pack_oct32`].
///
/// ```
/// use aokit::normals::{angle_degrees, pack_oct32, unpack_oct32};
/// use glam::Vec3;
/// let n = Vec3::new(0.48, -0.6, 0.64);
/// // The finest octahedral encoding: under 0.004 degrees off (docs/normals.md).
/// assert!(angle_degrees(n, unpack_oct32(pack_oct32(n))) < 0.004);
/// ```
pub fn unpack_oct32(bits: u32) -> Vec3 {
    oct_decode(unpack2x16unorm(bits) * 2.0 - 1.0)
}

/// The `oct24` encoding as the bytes of an `Rgba8Unorm` texel: 12 bits per octahedral
/// coordinate, the low 8 bits of x in R and of y in G, the high 4 bits of x in B's low nibble
/// and of y in its high nibble; A is 0.
///
/// ```
/// use aokit::normals::{pack_oct24, unpack_oct24};
/// use glam::Vec3;
/// let n = Vec3::new(0.0, 0.6, 0.8);
/// // A is free: a G-buffer can keep a material id there, which decoding ignores.
/// let mut texel = pack_oct24(n);
/// texel[3] = 17;
/// assert!((unpack_oct24(texel) - n).length() < 1e-3);
/// ```
pub fn pack_oct24(n: Vec3) -> [u8; 4] {
    let e = oct_unorm(n);
    let (x, y) = (unorm_steps(e.x, 4095.0), unorm_steps(e.y, 4095.0));
    [x as u8, y as u8, ((x >> 8) | ((y >> 8) << 4)) as u8, 0]
}

/// Inverse of [`pack_oct24`].
///
/// ```
/// use aokit::normals::{angle_degrees, pack_oct24, unpack_oct24};
/// use glam::Vec3;
/// let n = Vec3::new(0.48, -0.6, 0.64);
/// assert!(angle_degrees(n, unpack_oct24(pack_oct24(n))) < 0.065);
/// ```
pub fn unpack_oct24(texel: [u8; 4]) -> Vec3 {
    let [r, g, b, _] = texel.map(u32::from);
    let q = Vec2::new((r | ((b & 15) << 8)) as f32, (g | ((b >> 4) << 8)) as f32);
    oct_decode(q / 4095.0 * 2.0 - 1.0)
}

/// The `oct16` encoding as the bytes of an `Rg8Unorm` texel.
///
/// ```
/// use aokit::normals::pack_oct16;
/// use glam::Vec3;
/// assert_eq!(pack_oct16(Vec3::Z), [128, 128]);
/// // The back of the sphere folds out to the square's corners.
/// assert_eq!(pack_oct16(Vec3::NEG_Z), [255, 255]);
/// ```
pub fn pack_oct16(n: Vec3) -> [u8; 2] {
    let e = oct_unorm(n);
    [unorm_steps(e.x, 255.0) as u8, unorm_steps(e.y, 255.0) as u8]
}

/// Inverse of [`pack_oct16`].
///
/// ```
/// use aokit::normals::{angle_degrees, pack_oct16, unpack_oct16};
/// use glam::Vec3;
/// let n = Vec3::new(0.48, -0.6, 0.64);
/// // 8 bits per coordinate: up to a degree off, enough for AO but not for sharp highlights.
/// assert!(angle_degrees(n, unpack_oct16(pack_oct16(n))) < 1.0);
/// ```
pub fn unpack_oct16(texel: [u8; 2]) -> Vec3 {
    let e = Vec2::new(f32::from(texel[0]), f32::from(texel[1])) / 255.0;
    oct_decode(e * 2.0 - 1.0)
}

/// The `oct20` encoding as an `Rgb10a2Unorm` texel: octahedral coordinates in R and G.
///
/// ```
/// use aokit::normals::{pack_oct20, unpack_oct20};
/// use glam::Vec3;
/// let n = Vec3::new(-0.6, 0.0, 0.8);
/// // B (10 bits) and A (2 bits) are free: here a roughness of 0.5 in B.
/// let texel = pack_oct20(n) | (512 << 20);
/// assert!((unpack_oct20(texel) - n).length() < 5e-3);
/// ```
pub fn pack_oct20(n: Vec3) -> u32 {
    let e = oct_unorm(n);
    rgb10a2_bits([unorm_steps(e.x, 1023.0), unorm_steps(e.y, 1023.0), 0])
}

/// Inverse of [`pack_oct20`].
///
/// ```
/// use aokit::normals::{angle_degrees, pack_oct20, unpack_oct20};
/// use glam::Vec3;
/// let n = Vec3::new(0.48, -0.6, 0.64);
/// assert!(angle_degrees(n, unpack_oct20(pack_oct20(n))) < 0.26);
/// ```
pub fn unpack_oct20(bits: u32) -> Vec3 {
    oct_decode(rgb10a2_channels(bits).truncate() * 2.0 - 1.0)
}

/// The `rgb10a2` encoding: `n * 0.5 + 0.5` as an `Rgb10a2Unorm` texel.
///
/// ```
/// use aokit::normals::pack_rgb10a2;
/// use glam::Vec3;
/// // x and y at mid-range (512 of 1023), z at the top, red in the low bits.
/// assert_eq!(pack_rgb10a2(Vec3::Z), 512 | (512 << 10) | (1023 << 20));
/// ```
pub fn pack_rgb10a2(n: Vec3) -> u32 {
    let e = n * 0.5 + 0.5;
    rgb10a2_bits([e.x, e.y, e.z].map(|c| unorm_steps(c, 1023.0)))
}

/// Inverse of [`pack_rgb10a2`].
///
/// ```
/// use aokit::normals::{angle_degrees, pack_rgb10a2, unpack_rgb10a2};
/// use glam::Vec3;
/// let n = Vec3::new(0.48, -0.6, 0.64);
/// assert!(angle_degrees(n, unpack_rgb10a2(pack_rgb10a2(n))) < 0.105);
/// ```
pub fn unpack_rgb10a2(bits: u32) -> Vec3 {
    (rgb10a2_channels(bits) * 2.0 - 1.0).normalize()
}

/// The `rgba16f` encoding: xyz as IEEE half floats (rounded to nearest, ties to even), w 0.
///
/// ```
/// use aokit::normals::pack_rgba16f;
/// use glam::Vec3;
/// // 1.0 is 0x3c00 as a half float.
/// assert_eq!(pack_rgba16f(Vec3::Z), [0, 0, 0x3c00, 0]);
/// ```
pub fn pack_rgba16f(n: Vec3) -> [u16; 4] {
    [f32_to_f16(n.x), f32_to_f16(n.y), f32_to_f16(n.z), 0]
}

/// Inverse of [`pack_rgba16f`]; a cleared texel (all zero) decodes to +z.
///
/// ```
/// use aokit::normals::unpack_rgba16f;
/// use glam::Vec3;
/// // Sky pixels of a G-buffer cleared to 0 still decode to a unit vector.
/// assert_eq!(unpack_rgba16f([0; 4]), Vec3::Z);
/// // Half floats hold 11 significant bits; decoding renormalises.
/// let n = unpack_rgba16f([0x38cd, 0, 0x3a66, 0]);
/// assert!((n - Vec3::new(0.6, 0.0, 0.8)).length() < 1e-3);
/// ```
pub fn unpack_rgba16f(texel: [u16; 4]) -> Vec3 {
    let v = Vec3::new(
        f16_to_f32(texel[0]),
        f16_to_f32(texel[1]),
        f16_to_f32(texel[2]),
    );
    if v == Vec3::ZERO {
        Vec3::Z
    } else {
        v.normalize()
    }
}

/// The `xy` encoding: x and y as two 16-bit snorms. Only right for normals with z >= 0:
/// [`unpack_xy`] takes z as facing the eye.
///
/// ```
/// use aokit::normals::{pack_xy, unpack_xy};
/// use glam::Vec3;
/// // A normal facing away from the eye comes back mirrored into the front hemisphere.
/// let back = Vec3::new(0.6, 0.0, -0.8);
/// assert!((unpack_xy(pack_xy(back)) - Vec3::new(0.6, 0.0, 0.8)).length() < 1e-4);
/// ```
pub fn pack_xy(n: Vec3) -> u32 {
    pack2x16snorm(Vec2::new(n.x, n.y))
}

/// Inverse of [`pack_xy`], with `z = +sqrt(1 - x^2 - y^2)`.
///
/// ```
/// use aokit::normals::{angle_degrees, pack_xy, unpack_xy};
/// use glam::Vec3;
/// let n = Vec3::new(0.48, -0.6, 0.64);
/// // Fine for the normals a camera sees, which face it.
/// assert!(angle_degrees(n, unpack_xy(pack_xy(n))) < 0.37);
/// ```
pub fn unpack_xy(bits: u32) -> Vec3 {
    let xy = unpack2x16snorm(bits);
    xy.extend((1.0 - xy.dot(xy)).max(0.0).sqrt()).normalize()
}

/// The `spherical` encoding: azimuth over the full turn and polar angle from +z, each as a
/// 16-bit unorm.
///
/// ```
/// use aokit::normals::pack_spherical;
/// use glam::Vec3;
/// // +z is polar angle 0: the high half is 0, whatever the (undefined) azimuth.
/// assert_eq!(pack_spherical(Vec3::Z) >> 16, 0);
/// assert_eq!(pack_spherical(Vec3::NEG_Z) >> 16, 0xffff);
/// ```
pub fn pack_spherical(n: Vec3) -> u32 {
    let pi = std::f32::consts::PI;
    let azimuth = n.y.atan2(n.x);
    let polar = Vec2::new(n.x, n.y).length().atan2(n.z);
    pack2x16unorm(Vec2::new(azimuth / (2.0 * pi) + 0.5, polar / pi))
}

/// Inverse of [`pack_spherical`].
///
/// ```
/// use aokit::normals::{angle_degrees, pack_spherical, unpack_spherical};
/// use glam::Vec3;
/// let n = Vec3::new(0.0, -0.6, -0.8);
/// // Accurate over the whole sphere, at the price of trigonometry in the shader.
/// assert!(angle_degrees(n, unpack_spherical(pack_spherical(n))) < 0.0034);
/// ```
pub fn unpack_spherical(bits: u32) -> Vec3 {
    let pi = std::f32::consts::PI;
    let e = unpack2x16unorm(bits);
    let azimuth = (e.x - 0.5) * 2.0 * pi;
    let polar = e.y * pi;
    (polar.sin() * Vec2::new(azimuth.cos(), azimuth.sin())).extend(polar.cos())
}

/// The unit direction of `xy`, +x for the zero vector (the -z pole, whose azimuth is arbitrary).
fn azimuth(xy: Vec2) -> Vec2 {
    let len = xy.length();
    if len > 0.0 { xy / len } else { Vec2::X }
}

/// The `stereographic` encoding: projection from the -z pole onto z = 0, `xy / (1 + z)`, radius
/// clamped to [`STEREOGRAPHIC_RANGE`], stored as two 16-bit unorms.
///
/// ```
/// use aokit::normals::{angle_degrees, pack_stereographic, unpack_stereographic};
/// use glam::Vec3;
/// // The pole it projects from cannot be stored: it comes back 28 degrees off.
/// let pole = unpack_stereographic(pack_stereographic(Vec3::NEG_Z));
/// assert!((angle_degrees(Vec3::NEG_Z, pole) - 28.07).abs() < 0.01);
/// ```
pub fn pack_stereographic(n: Vec3) -> u32 {
    let xy = Vec2::new(n.x, n.y);
    let s = if n.z >= 0.0 {
        xy / (1.0 + n.z)
    } else {
        // (1 - z) / |xy| equals |xy| / (1 + z) without the cancellation in 1 + z.
        let radius = (1.0 - n.z) / xy.length().max(1e-30);
        azimuth(xy) * radius.min(STEREOGRAPHIC_RANGE)
    };
    pack2x16unorm(s / (2.0 * STEREOGRAPHIC_RANGE) + 0.5)
}

/// Inverse of [`pack_stereographic`].
///
/// ```
/// use aokit::normals::{angle_degrees, pack_stereographic, unpack_stereographic};
/// use glam::Vec3;
/// let n = Vec3::new(0.48, -0.6, 0.64);
/// assert!(angle_degrees(n, unpack_stereographic(pack_stereographic(n))) < 0.011);
/// ```
pub fn unpack_stereographic(bits: u32) -> Vec3 {
    let s = (unpack2x16unorm(bits) - 0.5) * (2.0 * STEREOGRAPHIC_RANGE);
    let d = s.dot(s);
    (2.0 * s).extend(1.0 - d) / (1.0 + d)
}

/// The `lambert` encoding: Lambert azimuthal equal-area projection from the -z pole,
/// `xy * sqrt(2 / (1 + z))`, a disc of radius 2 stored as two 16-bit unorms.
///
/// ```
/// use aokit::normals::{angle_degrees, pack_lambert, unpack_lambert};
/// use glam::Vec3;
/// // Unlike the stereographic encoding, the far pole is on the disc's rim and survives.
/// let pole = unpack_lambert(pack_lambert(Vec3::NEG_Z));
/// assert!(angle_degrees(Vec3::NEG_Z, pole) < 0.6);
/// ```
pub fn pack_lambert(n: Vec3) -> u32 {
    let xy = Vec2::new(n.x, n.y);
    let s = if n.z >= 0.0 {
        xy * (2.0 / (1.0 + n.z)).sqrt()
    } else {
        // sqrt(2 (1 - z)) is the same radius without the cancellation in 1 + z.
        azimuth(xy) * (2.0 * (1.0 - n.z)).sqrt()
    };
    pack2x16unorm(s * 0.25 + 0.5)
}

/// Inverse of [`pack_lambert`].
///
/// ```
/// use aokit::normals::{angle_degrees, pack_lambert, unpack_lambert};
/// use glam::Vec3;
/// let n = Vec3::new(0.48, -0.6, 0.64);
/// assert!(angle_degrees(n, unpack_lambert(pack_lambert(n))) < 0.0038);
/// ```
pub fn unpack_lambert(bits: u32) -> Vec3 {
    let s = unpack2x16unorm(bits) * 4.0 - 2.0;
    let d = s.dot(s);
    (s * (1.0 - 0.25 * d).max(0.0).sqrt())
        .extend(1.0 - 0.5 * d)
        .normalize()
}

/// Appends the bytes of `n`'s texel in `encoding` (little-endian, as textures store them).
///
/// ```
/// use aokit::NormalEncoding;
/// use aokit::normals::{encode_texel, pack_oct32};
/// use glam::Vec3;
/// // Filling a staging buffer row by row, reusing its allocation.
/// let mut row = Vec::new();
/// for n in [Vec3::Z, Vec3::X] {
///     encode_texel(NormalEncoding::Oct32, n, &mut row);
/// }
/// assert_eq!(row[4..], pack_oct32(Vec3::X).to_le_bytes());
/// ```
pub fn encode_texel(encoding: NormalEncoding, n: Vec3, out: &mut Vec<u8>) {
    match encoding {
        NormalEncoding::Oct32 => out.extend(pack_oct32(n).to_le_bytes()),
        NormalEncoding::Oct24 => out.extend(pack_oct24(n)),
        NormalEncoding::Oct16 => out.extend(pack_oct16(n)),
        NormalEncoding::Oct20 => out.extend(pack_oct20(n).to_le_bytes()),
        NormalEncoding::Rgb10a2 => out.extend(pack_rgb10a2(n).to_le_bytes()),
        NormalEncoding::Rgba16f => out.extend(pack_rgba16f(n).iter().flat_map(|h| h.to_le_bytes())),
        NormalEncoding::Xy => out.extend(pack_xy(n).to_le_bytes()),
        NormalEncoding::Spherical => out.extend(pack_spherical(n).to_le_bytes()),
        NormalEncoding::Stereographic => out.extend(pack_stereographic(n).to_le_bytes()),
        NormalEncoding::Lambert => out.extend(pack_lambert(n).to_le_bytes()),
    }
}

/// Decodes the texel at the start of `texel` (at least [`NormalEncoding::texel_size`] bytes).
///
/// ```
/// use aokit::NormalEncoding;
/// use aokit::normals::{decode_texel, encode_texels};
/// use glam::Vec3;
/// let encoding = NormalEncoding::Oct24;
/// let (width, x, y) = (4, 1, 2);
/// let bytes = encode_texels(encoding, &vec![Vec3::Y; width * 3]);
/// // One pixel of a read-back image, without decoding the rest.
/// let at = (y * width + x) * encoding.texel_size();
/// assert!((decode_texel(encoding, &bytes[at..]) - Vec3::Y).length() < 1e-3);
/// ```
pub fn decode_texel(encoding: NormalEncoding, texel: &[u8]) -> Vec3 {
    let word = || u32::from_le_bytes([texel[0], texel[1], texel[2], texel[3]]);
    match encoding {
        NormalEncoding::Oct32 => unpack_oct32(word()),
        NormalEncoding::Oct24 => unpack_oct24([texel[0], texel[1], texel[2], texel[3]]),
        NormalEncoding::Oct16 => unpack_oct16([texel[0], texel[1]]),
        NormalEncoding::Oct20 => unpack_oct20(word()),
        NormalEncoding::Rgb10a2 => unpack_rgb10a2(word()),
        NormalEncoding::Rgba16f => unpack_rgba16f(std::array::from_fn(|i| {
            u16::from_le_bytes([texel[2 * i], texel[2 * i + 1]])
        })),
        NormalEncoding::Xy => unpack_xy(word()),
        NormalEncoding::Spherical => unpack_spherical(word()),
        NormalEncoding::Stereographic => unpack_stereographic(word()),
        NormalEncoding::Lambert => unpack_lambert(word()),
    }
}

/// The bytes of a [`NormalEncoding::texture_format`] texture holding `normals` (unit vectors),
/// ready for [`upload_texture_2d`](crate::gpu::upload_texture_2d).
///
/// ```no_run
/// # fn f(device: &wgpu::Device, queue: &wgpu::Queue, normals: &[glam::Vec3])
/// #     -> Result<(), aokit::GpuError> {
/// use aokit::NormalEncoding;
/// use aokit::normals::encode_texels;
/// // View-space normals computed on the CPU, as a G-buffer texture the pipeline reads.
/// let encoding = NormalEncoding::Oct32;
/// let texture = aokit::gpu::upload_texture_2d(device, queue, "normals", [640, 480],
///     encoding.texture_format(), &encode_texels(encoding, normals))?;
/// # Ok(()) }
/// ```
pub fn encode_texels(encoding: NormalEncoding, normals: &[Vec3]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(normals.len() * encoding.texel_size());
    for &n in normals {
        encode_texel(encoding, n, &mut bytes);
    }
    bytes
}

/// The normals in the bytes of a [`NormalEncoding::texture_format`] texture, as read back by
/// [`read_texture`](crate::gpu::read_texture).
///
/// ```
/// use aokit::NormalEncoding;
/// use aokit::normals::{decode_texels, encode_texels, fibonacci_directions};
/// let normals: Vec<_> = fibonacci_directions(100).collect();
/// let encoding = NormalEncoding::Oct16;
/// // What a renderer writing `oct16` normals loses: the largest error over the sphere.
/// let decoded = decode_texels(encoding, &encode_texels(encoding, &normals));
/// let worst = normals.iter().zip(&decoded)
///     .map(|(a, b)| aokit::normals::angle_degrees(*a, *b))
///     .fold(0.0, f64::max);
/// assert!(worst < 1.0);
/// ```
pub fn decode_texels(encoding: NormalEncoding, bytes: &[u8]) -> Vec<Vec3> {
    bytes
        .chunks_exact(encoding.texel_size())
        .map(|texel| decode_texel(encoding, texel))
        .collect()
}

/// `count` directions spread evenly over the sphere (a spherical Fibonacci lattice: Keinert et
/// al. 2015, "Spherical Fibonacci Mapping"), for measuring encodings.
///
/// ```
/// use aokit::normals::fibonacci_directions;
/// // Evenly spread: about half of them face the eye.
/// let front = fibonacci_directions(1000).filter(|d| d.z >= 0.0).count();
/// assert_eq!(front, 500);
/// assert!(fibonacci_directions(1000).all(|d| (d.length() - 1.0).abs() < 1e-6));
/// ```
pub fn fibonacci_directions(count: u32) -> impl Iterator<Item = Vec3> {
    let golden_angle = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..count).map(move |i| {
        let z = 1.0 - 2.0 * (f64::from(i) + 0.5) / f64::from(count);
        let r = (1.0 - z * z).sqrt();
        let phi = golden_angle * f64::from(i);
        DVec3::new(r * phi.cos(), r * phi.sin(), z).as_vec3()
    })
}

/// The angle between two directions in degrees, computed in f64 from the cross and dot
/// products: an f32 `acos` near 1 is alone off by 0.02 degrees.
///
/// ```
/// use aokit::normals::angle_degrees;
/// use glam::Vec3;
/// assert!((angle_degrees(Vec3::X, Vec3::Y) - 90.0).abs() < 1e-9);
/// // Tiny angles, where encodings are judged, keep their digits.
/// let tilted = Vec3::new(1e-5, 0.0, 1.0).normalize();
/// assert!((angle_degrees(Vec3::Z, tilted) - 1e-5f64.to_degrees()).abs() < 1e-8);
/// ```
pub fn angle_degrees(a: Vec3, b: Vec3) -> f64 {
    let (a, b) = (a.as_dvec3(), b.as_dvec3());
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lattice plus the axes, the octahedron's edges and the diagonals of the octants, where
    /// folds, poles and branch cuts of the encodings lie.
    fn directions() -> Vec<Vec3> {
        let mut all: Vec<Vec3> = fibonacci_directions(100_000).collect();
        for x in [-1.0f32, 0.0, 1.0] {
            for y in [-1.0f32, 0.0, 1.0] {
                for z in [-1.0f32, 0.0, 1.0] {
                    if (x, y, z) != (0.0, 0.0, 0.0) {
                        all.push(Vec3::new(x, y, z).normalize());
                    }
                }
            }
        }
        all
    }

    #[test]
    fn octahedral_mapping_round_trips_exactly_before_quantisation() {
        for n in directions() {
            let back = oct_decode(oct_encode(n));
            assert!((back - n).length() < 1e-5, "{n} -> {back}");
        }
    }

    /// Largest error in degrees of a round trip through `encoding`, over the directions `keep`
    /// accepts.
    fn worst_error(encoding: NormalEncoding, keep: impl Fn(Vec3) -> bool) -> f64 {
        let mut texel = Vec::new();
        directions()
            .into_iter()
            .filter(|&n| keep(n))
            .map(|n| {
                texel.clear();
                encode_texel(encoding, n, &mut texel);
                assert_eq!(texel.len(), encoding.texel_size(), "{encoding:?}");
                angle_degrees(n, decode_texel(encoding, &texel))
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn every_encoding_round_trips_within_its_measured_bound() {
        use NormalEncoding as E;
        // Bounds in degrees: the largest error over one million directions in docs/normals.md,
        // plus about a tenth. Over the whole sphere, and over the hemisphere facing the eye (z >= 0),
        // which is all that `xy` and `stereographic` represent.
        let bounds = [
            (E::Oct32, 0.004, 0.004),
            (E::Oct24, 0.065, 0.065),
            (E::Oct16, 1.0, 1.0),
            (E::Oct20, 0.26, 0.26),
            (E::Rgb10a2, 0.105, 0.105),
            (E::Rgba16f, 0.025, 0.025),
            // Below the equator z is mirrored: up to 180 degrees off.
            (E::Xy, 180.0, 0.37),
            (E::Spherical, 0.0034, 0.0034),
            // The -z pole is clamped to the range, at z = -15/17, 28 degrees away.
            (E::Stereographic, 28.1, 0.011),
            // Quantisation near the -z pole, which spreads over the disc's rim.
            (E::Lambert, 0.6, 0.0038),
        ];
        for (encoding, sphere, front) in bounds {
            let worst_sphere = worst_error(encoding, |_| true);
            let worst_front = worst_error(encoding, |n| n.z >= 0.0);
            assert!(
                worst_sphere <= sphere && worst_front <= front,
                "{encoding:?}: worst error {worst_sphere} degrees over the sphere (bound \
                 {sphere}), {worst_front} over z >= 0 (bound {front})"
            );
        }
    }

    #[test]
    fn encoding_codes_match_wgsl() {
        let module = crate::shader::DECODE_NORMALS_UINT.validate().unwrap();
        for encoding in NormalEncoding::ALL {
            let name = format!("ENCODING_{}", encoding.name().to_uppercase());
            assert_eq!(
                crate::shader::u32_constant(&module, &name),
                Some(encoding.shader_code()),
                "{name}"
            );
        }
    }

    #[test]
    fn usable_length_matches_wgsl() {
        let module = crate::shader::DECODE_NORMALS_FLOAT.validate().unwrap();
        let constant = |name: &str| {
            let (_, constant) = module
                .constants
                .iter()
                .find(|(_, c)| c.name.as_deref() == Some(name))
                .unwrap();
            match module.global_expressions[constant.init] {
                wgpu::naga::Expression::Literal(wgpu::naga::Literal::F32(value)) => value,
                ref other => panic!("{name}: {other:?}"),
            }
        };
        assert_eq!(constant("USABLE_LENGTH_MIN"), *USABLE_LENGTH.start());
        assert_eq!(constant("USABLE_LENGTH_MAX"), *USABLE_LENGTH.end());
    }

    #[test]
    fn texel_sizes_match_the_formats_and_bits_fit() {
        for encoding in NormalEncoding::ALL {
            let size = encoding.texel_size();
            assert!(encoding.bits() as usize <= 8 * size, "{encoding:?}");
            assert_eq!(
                encode_texels(encoding, &[Vec3::Z, Vec3::NEG_Y]).len(),
                2 * size
            );
        }
    }

    #[test]
    fn cleared_texels_decode_to_unit_vectors() {
        for encoding in NormalEncoding::ALL {
            let n = decode_texel(encoding, &[0; 8]);
            assert!(
                n.is_finite() && (n.length() - 1.0).abs() < 1e-5,
                "{encoding:?}: {n}"
            );
        }
    }
}
