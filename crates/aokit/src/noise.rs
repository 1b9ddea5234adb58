//! Per-pixel noise on the CPU: the generators of the noise textures the AO kernels read, and
//! mirrors of every function in `shaders/common/noise.wgsl`, for tests and for the spectra in
//! docs/noise.md.
//!
//! Every kind gives two values in `[0, 1)` per pixel and frame ([`pixel_noise`]); the kernels
//! turn the first into a rotation of their directions and the second into a jitter of their
//! steps. The analytic kinds (interleaved gradient noise, GTAO's pattern, Bayer, Hilbert-R2) are
//! computed in the shader; `blue` and `white` read a tile ([`tile`]). All of it is deterministic:
//! fixed seeds, and integer arithmetic where floating point could differ between platforms.

use std::sync::OnceLock;

use crate::settings::{NoiseKind, NoiseSettings, TemporalOffset};

/// The Mersenne Twister MT19937 (Matsumoto and Nishimura 1998), the generator the Unity Asset
/// Store package "Horizon Based Ambient Occlusion" fills its 4x4 noise texture with.
///
/// ```
/// let mut rng = aokit::noise::Mt19937::new(5489);
/// assert_eq!(rng.next_u32(), 3499211612);
/// ```
#[derive(Clone)]
pub struct Mt19937 {
    state: [u32; 624],
    index: usize,
}

impl Mt19937 {
    /// Seeds the generator as the paper's 2002 initialisation does (`std::mt19937(seed)`).
    ///
    /// ```
    /// use aokit::noise::Mt19937;
    /// // The same seed gives the same stream on every platform.
    /// let (mut a, mut b) = (Mt19937::new(42), Mt19937::new(42));
    /// assert!((0..1000).all(|_| a.next_u32() == b.next_u32()));
    /// ```
    pub fn new(seed: u32) -> Self {
        let mut state = [0u32; 624];
        state[0] = seed;
        for i in 1..624 {
            let previous = state[i - 1];
            state[i] = 1_812_433_253u32
                .wrapping_mul(previous ^ (previous >> 30))
                .wrapping_add(i as u32);
        }
        Self { state, index: 624 }
    }

    /// The next 32 random bits.
    ///
    /// ```
    /// use aokit::noise::Mt19937;
    /// let mut rng = Mt19937::new(5489);
    /// // The C++ standard fixes the 10000th output of `std::mt19937` with the default seed.
    /// let ten_thousandth = (0..10_000).map(|_| rng.next_u32()).last();
    /// assert_eq!(ten_thousandth, Some(4123659995));
    /// ```
    pub fn next_u32(&mut self) -> u32 {
        if self.index == 624 {
            self.twist();
        }
        let mut y = self.state[self.index];
        self.index += 1;
        y ^= y >> 11;
        y ^= (y << 7) & 0x9d2c_5680;
        y ^= (y << 15) & 0xefc6_0000;
        y ^ (y >> 18)
    }

    /// A value in `[0, 1)` from the next 32 bits: their top 24, which an `f32` holds exactly.
    ///
    /// ```
    /// use aokit::noise::Mt19937;
    /// let mut rng = Mt19937::new(1);
    /// // Random rotations for a 4x4 noise tile.
    /// let angles: Vec<f32> = (0..16).map(|_| rng.next_f32() * std::f32::consts::TAU).collect();
    /// assert!(angles.iter().all(|a| (0.0..std::f32::consts::TAU).contains(a)));
    /// ```
    pub fn next_f32(&mut self) -> f32 {
        unit_from_fixed(self.next_u32())
    }

    fn twist(&mut self) {
        for i in 0..624 {
            let y = (self.state[i] & 0x8000_0000) | (self.state[(i + 1) % 624] & 0x7fff_ffff);
            let mag = if y & 1 == 1 { 0x9908_b0df } else { 0 };
            self.state[i] = self.state[(i + 397) % 624] ^ (y >> 1) ^ mag;
        }
        self.index = 0;
    }
}

/// A 32-bit binary fraction as a float in `[0, 1)`: its top 24 bits, exact in `f32`.
fn unit_from_fixed(bits: u32) -> f32 {
    (bits >> 8) as f32 / 16_777_216.0
}

fn fract(x: f32) -> f32 {
    x - x.floor()
}

/// Gaussian width of the void-and-cluster energy filter, in pixels: Ulichney's 1.5, wide enough
/// that neighbouring minority pixels repel and narrow enough that the result is blue at every
/// density.
const VOID_AND_CLUSTER_SIGMA: f64 = 1.5;

/// Energies are integers in units of 2^-40 of the filter's centre weight: sums are exact, so
/// the incremental updates never drift and ties break the same way on every platform. The
/// filter ends where its weight rounds to zero, 11 pixels out.
const ENERGY_SCALE: f64 = (1u64 << 40) as f64;

/// Fraction of the pixels set in the initial binary pattern. Any fraction up to one half works
/// (Ulichney 1993); a sparse one needs few swaps to relax.
const INITIAL_DENSITY: usize = 10;

/// The binary pattern of void-and-cluster and, per pixel, the filtered count of set pixels
/// around it on the torus.
#[derive(Clone)]
struct EnergyField {
    size: usize,
    set: Vec<bool>,
    energy: Vec<i64>,
    /// `(dx, dy, weight)` of every non-zero filter tap.
    filter: Vec<(isize, isize, i64)>,
    /// Rows within this distance of a changed pixel see their energies change.
    reach: isize,
    /// Per row, the best clear (index 0) and set (index 1) pixel of the last search, `None`
    /// for a row without such pixels. A change touches only the rows its filter reaches, so a
    /// search rescans those and compares one candidate from each other row: about five times
    /// fewer reads than scanning a 128x128 tile.
    row_best: [Vec<Option<usize>>; 2],
    /// Rows whose `row_best` is out of date.
    stale: [Vec<bool>; 2],
}

impl EnergyField {
    fn new(size: usize) -> Self {
        let weight = |d2: f64| {
            (ENERGY_SCALE * (-d2 / (2.0 * VOID_AND_CLUSTER_SIGMA * VOID_AND_CLUSTER_SIGMA)).exp())
                .round() as i64
        };
        // The first distance at which the weight is zero bounds the taps.
        let reach = (1..).find(|&r| weight((r * r) as f64) == 0).unwrap() as isize;
        assert!(
            2 * reach < size as isize,
            "a {size}x{size} tile is too small: the filter would overlap itself"
        );
        let mut filter = Vec::new();
        for dy in -reach..=reach {
            for dx in -reach..=reach {
                let w = weight((dx * dx + dy * dy) as f64);
                if w > 0 {
                    filter.push((dx, dy, w));
                }
            }
        }
        Self {
            size,
            set: vec![false; size * size],
            energy: vec![0; size * size],
            filter,
            reach,
            row_best: [vec![None; size], vec![None; size]],
            stale: [vec![true; size], vec![true; size]],
        }
    }

    /// Sets or clears pixel `p`, updating the energy of the pixels its filter reaches.
    fn assign(&mut self, p: usize, value: bool) {
        debug_assert_ne!(self.set[p], value);
        self.set[p] = value;
        let n = self.size as isize;
        let (px, py) = ((p % self.size) as isize, (p / self.size) as isize);
        let sign = if value { 1 } else { -1 };
        for &(dx, dy, w) in &self.filter {
            let q = (py + dy).rem_euclid(n) * n + (px + dx).rem_euclid(n);
            self.energy[q as usize] += sign * w;
        }
        for dy in -self.reach..=self.reach {
            let row = (py + dy).rem_euclid(n) as usize;
            self.stale[0][row] = true;
            self.stale[1][row] = true;
        }
    }

    /// The set pixel with the highest energy, the first in row-major order on ties.
    fn tightest_cluster(&mut self) -> usize {
        self.extreme(true, |e, best| e > best)
    }

    /// The clear pixel with the lowest energy, the first in row-major order on ties.
    fn largest_void(&mut self) -> usize {
        self.extreme(false, |e, best| e < best)
    }

    fn extreme(&mut self, among_set: bool, better: impl Fn(i64, i64) -> bool) -> usize {
        let which = usize::from(among_set);
        let mut best: Option<usize> = None;
        for row in 0..self.size {
            if self.stale[which][row] {
                let mut row_best: Option<usize> = None;
                for p in row * self.size..(row + 1) * self.size {
                    if self.set[p] == among_set
                        && row_best.is_none_or(|b| better(self.energy[p], self.energy[b]))
                    {
                        row_best = Some(p);
                    }
                }
                self.row_best[which][row] = row_best;
                self.stale[which][row] = false;
            }
            if let Some(p) = self.row_best[which][row]
                && best.is_none_or(|b| better(self.energy[p], self.energy[b]))
            {
                best = Some(p);
            }
        }
        best.expect("the pattern has a pixel of the kind asked for")
    }
}

/// A void-and-cluster dither array (Ulichney 1993, "The void-and-cluster method for dither
/// array generation"): the rank, `0..size*size`, of every pixel of a `size`x`size` tile, row
/// major. Thresholding the ranks at any count gives a pattern whose set pixels are spread as
/// evenly as the Gaussian filter (sigma 1.5, on a torus) can tell, so the tile is blue noise and
/// tiles seamlessly.
///
/// The initial binary pattern is a random tenth of the pixels (MT19937 seeded with `seed`),
/// relaxed by moving the tightest cluster into the largest void until the two coincide. Phase 1
/// removes tightest clusters from it, ranking downwards; phase 2 fills largest voids, ranking
/// upwards. Phase 3 (past half full, the clear pixels become the minority and their tightest
/// cluster is filled) needs no code of its own: the energy of the clear pixels is the filter's
/// total minus that of the set ones, so their tightest cluster is the largest void.
///
/// Integer energies make the relaxation terminate: each move either lowers the total energy of
/// the pattern or, at equal energy, moves a pixel to a lower index.
///
/// # Panics
/// When `size` is 24 or less: the filter would overlap itself on the torus.
///
/// ```
/// use aokit::noise::void_and_cluster;
/// let size = 32;
/// let ranks = void_and_cluster(size, 7);
/// // Thresholding at any count keeps that many pixels: a dither pattern of that density.
/// let quarter = ranks.iter().filter(|&&r| r < (size * size / 4) as u32).count();
/// assert_eq!(quarter, size * size / 4);
/// // Every pixel has its own rank.
/// let mut sorted = ranks.clone();
/// sorted.sort_unstable();
/// assert!(sorted.iter().enumerate().all(|(i, &r)| r == i as u32));
/// ```
pub fn void_and_cluster(size: usize, seed: u32) -> Vec<u32> {
    let count = size * size;
    let mut initial = EnergyField::new(size);
    let mut rng = Mt19937::new(seed);
    let mut placed = 0;
    while placed < count / INITIAL_DENSITY {
        let p = rng.next_u32() as usize % count;
        if !initial.set[p] {
            initial.assign(p, true);
            placed += 1;
        }
    }
    loop {
        let cluster = initial.tightest_cluster();
        initial.assign(cluster, false);
        let void = initial.largest_void();
        initial.assign(void, true);
        if void == cluster {
            break;
        }
    }

    let mut rank = vec![0u32; count];
    let mut field = initial.clone();
    let mut ones = placed;
    while ones > 0 {
        let cluster = field.tightest_cluster();
        field.assign(cluster, false);
        ones -= 1;
        rank[cluster] = ones as u32;
    }
    let mut field = initial;
    for ones in placed..count {
        let void = field.largest_void();
        field.assign(void, true);
        rank[void] = ones as u32;
    }
    rank
}

/// Seeds of the two blue-noise channels: any two distinct seeds give independent channels;
/// fixed ones keep the tiles the same from run to run.
const BLUE_SEEDS: [u32; 2] = [1, 2];

/// The blue-noise tile of side `size` (64 or 128, what [`NoiseSettings::blue_size`] allows):
/// two independent void-and-cluster channels, each value `rank / size^2`. Computed on first use
/// (0.3 s for 128 in a release build on 2 cores) and cached for the process.
///
/// # Panics
/// For other sizes.
///
/// ```
/// let tile = aokit::noise::blue_noise(64);
/// assert_eq!(tile.len(), 64 * 64);
/// // Both channels spread their values evenly over [0, 1): each rank appears once.
/// let below_half = tile.iter().filter(|t| t[0] < 0.5).count();
/// assert_eq!(below_half, 64 * 64 / 2);
/// ```
pub fn blue_noise(size: u32) -> &'static [[f32; 2]] {
    static TILES: [OnceLock<Vec<[f32; 2]>>; 2] = [OnceLock::new(), OnceLock::new()];
    let slot = match size {
        64 => 0,
        128 => 1,
        _ => panic!("blue-noise tiles are 64 or 128 texels wide, not {size}"),
    };
    TILES[slot].get_or_init(|| {
        let n = size as usize;
        // One channel per thread: the two are independent.
        let (a, b) = std::thread::scope(|scope| {
            let second = scope.spawn(|| void_and_cluster(n, BLUE_SEEDS[1]));
            let first = void_and_cluster(n, BLUE_SEEDS[0]);
            (
                first,
                second.join().expect("void-and-cluster does not panic"),
            )
        });
        let scale = 1.0 / (n * n) as f32;
        a.iter()
            .zip(&b)
            .map(|(&a, &b)| [a as f32 * scale, b as f32 * scale])
            .collect()
    })
}

/// Seed of the white-noise tile: MT19937's reference seed, so `std::mt19937` reproduces it.
const WHITE_SEED: u32 = 5489;

/// Side of the white-noise tile: the 4x4 noise texture of the HBAO package for Unity.
const WHITE_SIZE: u32 = 4;

/// The "Spatial Distribution" noise of the Unity Asset Store package "Horizon Based Ambient
/// Occlusion": a 4x4 tile of MT19937 values, texel by texel in row order, two per texel.
///
/// ```
/// use aokit::noise::{Mt19937, white_noise};
/// let tile = white_noise();
/// assert_eq!(tile.len(), 16);
/// // The twister's reference stream, two values per texel.
/// let mut rng = Mt19937::new(5489);
/// assert_eq!(tile[0], [rng.next_f32(), rng.next_f32()]);
/// ```
pub fn white_noise() -> &'static [[f32; 2]] {
    static TILE: OnceLock<Vec<[f32; 2]>> = OnceLock::new();
    TILE.get_or_init(|| {
        let mut rng = Mt19937::new(WHITE_SEED);
        (0..WHITE_SIZE * WHITE_SIZE)
            .map(|_| [rng.next_f32(), rng.next_f32()])
            .collect()
    })
}

/// A square tile of noise, two values per texel, row major, repeated over the image.
///
/// ```
/// use aokit::noise::{Tile, white_noise};
/// let tile = Tile { size: 4, texels: white_noise() };
/// // Two texels in the first row of the tile.
/// assert_eq!(tile.texel([1, 0]), tile.texels[1]);
/// assert_eq!(tile.texel([3, 0]), tile.texels[3]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Tile {
    /// Texels per side.
    pub size: u32,
    /// `size * size` texels.
    pub texels: &'static [[f32; 2]],
}

/// Format of an uploaded [`Tile`]: two 32-bit floats hold the ranks of a 128x128 tile exactly.
pub const TILE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rg32Float;

impl Tile {
    /// The tile as the [`TILE_FORMAT`] texture aokit's kernels read (binding 7 of
    /// `shaders/common/ao.wgsl`), for a kernel of one's own that reads noise the way they do.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device, queue: &wgpu::Queue) {
    /// use aokit::{NoiseKind, NoiseSettings};
    /// let settings =
    ///     NoiseSettings { kind: NoiseKind::Blue, blue_size: 128, ..NoiseSettings::default() };
    /// let tile = aokit::noise::tile(&settings).expect("blue noise is a tile");
    /// let texture = tile.upload(device, queue);
    /// assert_eq!(texture.width(), 128);
    /// # }
    /// ```
    pub fn upload(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> wgpu::Texture {
        crate::gpu::upload_texture_2d(
            device,
            queue,
            "aokit noise tile",
            [self.size; 2],
            TILE_FORMAT,
            bytemuck::cast_slice(self.texels),
        )
        .expect("a noise tile holds size * size texels")
    }

    /// The texel that lands on `pixel` when the tile repeats from the image's corner.
    ///
    /// ```
    /// use aokit::noise::tile;
    /// use aokit::{NoiseKind, NoiseSettings};
    /// let settings = NoiseSettings { kind: NoiseKind::White, ..NoiseSettings::default() };
    /// let white = tile(&settings).unwrap();
    /// // The pattern repeats every `size` pixels in both directions.
    /// assert_eq!(white.texel([1, 2]), white.texel([1 + white.size, 2 + 3 * white.size]));
    /// ```
    pub fn texel(&self, pixel: [u32; 2]) -> [f32; 2] {
        self.texels[((pixel[1] % self.size) * self.size + pixel[0] % self.size) as usize]
    }
}

/// The tile a noise kind reads from a texture: `None` for the kinds computed in the shader.
///
/// ```
/// use aokit::noise::tile;
/// use aokit::{NoiseKind, NoiseSettings};
/// let blue = NoiseSettings { kind: NoiseKind::Blue, blue_size: 64, ..NoiseSettings::default() };
/// assert_eq!(tile(&blue).map(|t| t.size), Some(64));
/// // Interleaved gradient noise needs no texture.
/// let ign = NoiseSettings { kind: NoiseKind::Ign, ..NoiseSettings::default() };
/// assert!(tile(&ign).is_none());
/// ```
pub fn tile(settings: &NoiseSettings) -> Option<Tile> {
    match settings.kind {
        NoiseKind::Blue => Some(Tile {
            size: settings.blue_size,
            texels: blue_noise(settings.blue_size),
        }),
        NoiseKind::White => Some(Tile {
            size: WHITE_SIZE,
            texels: white_noise(),
        }),
        NoiseKind::Ign | NoiseKind::Gtao | NoiseKind::Bayer | NoiseKind::HilbertR2 => None,
    }
}

/// The value of the `NOISE_*` constant in `shaders/common/noise.wgsl` that selects `kind`.
///
/// ```
/// use aokit::noise::{kind_code, temporal_code};
/// use aokit::{NoiseKind, NoiseSettings};
/// let settings = NoiseSettings { kind: NoiseKind::Blue, ..NoiseSettings::default() };
/// // The `kind` and `temporal` arguments of noise.wgsl's `pixel_noise`, for a shader of one's
/// // own to read from its uniform buffer.
/// let words = [kind_code(settings.kind), temporal_code(settings.temporal)];
/// let bytes: &[u8] = bytemuck::cast_slice(&words);
/// assert_eq!(words[0], 1);
/// ```
pub fn kind_code(kind: NoiseKind) -> u32 {
    match kind {
        NoiseKind::Ign => 0,
        NoiseKind::Blue => 1,
        NoiseKind::Gtao => 2,
        NoiseKind::Bayer => 3,
        NoiseKind::White => 4,
        NoiseKind::HilbertR2 => 5,
    }
}

/// The value of the `TEMPORAL_*` constant in `shaders/common/noise.wgsl` that selects `offset`.
///
/// ```
/// use aokit::TemporalOffset;
/// use aokit::noise::temporal_code;
/// let codes: Vec<u32> = TemporalOffset::ALL.map(temporal_code).to_vec();
/// assert_eq!(codes, [0, 1]);
/// ```
pub fn temporal_code(offset: TemporalOffset) -> u32 {
    match offset {
        TemporalOffset::GoldenRatio => 0,
        TemporalOffset::R2 => 1,
    }
}

/// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
/// Advanced Warfare") at a continuous pixel position. Jimenez's 52.9829189 is written as the
/// `f32` it rounds to.
///
/// ```
/// use aokit::noise::interleaved_gradient_noise;
/// // Values for a pixel row, each in [0, 1) and far from its neighbour's.
/// let row: Vec<f32> = (0..8).map(|x| interleaved_gradient_noise([x as f32, 0.0])).collect();
/// assert!(row.iter().all(|v| (0.0..1.0).contains(v)));
/// assert!(row.windows(2).all(|w| (w[0] - w[1]).abs() > 0.05));
/// ```
pub fn interleaved_gradient_noise(p: [f32; 2]) -> f32 {
    fract(52.982_918 * fract(p[0] * 0.067_110_56 + p[1] * 0.005_837_15))
}

/// Pixels interleaved gradient noise moves per frame: Jimenez's shift, over a 64-frame cycle.
const IGN_FRAME_SHIFT: f32 = 5.588_238;

/// Two interleaved-gradient values per pixel, the second from the pattern transposed: an offset
/// copy would only add a constant to the first value, locking each pixel's rotation to its
/// jitter. The pattern shifts 5.588238 pixels each frame (Jimenez's shift), over a 64-frame
/// cycle.
///
/// ```
/// use aokit::noise::ign_noise;
/// let pixel = [37, 12];
/// // Each frame shows the pixel new values, and the cycle closes after 64 frames.
/// assert_ne!(ign_noise(pixel, 0), ign_noise(pixel, 1));
/// assert_eq!(ign_noise(pixel, 3), ign_noise(pixel, 67));
/// ```
pub fn ign_noise(pixel: [u32; 2], frame: u32) -> [f32; 2] {
    let shift = IGN_FRAME_SHIFT * (frame % 64) as f32;
    let p = [pixel[0] as f32 + shift, pixel[1] as f32 + shift];
    [
        interleaved_gradient_noise(p),
        interleaved_gradient_noise([p[1], p[0]]),
    ]
}

/// GTAO's rotations over 6 frames (Jimenez et al. 2016, SIGGRAPH 2016 course), in degrees.
pub const GTAO_ROTATIONS: [f32; 6] = [60.0, 300.0, 180.0, 240.0, 120.0, 0.0];
/// GTAO's step offsets, each held for 6 frames (Jimenez et al. 2016, SIGGRAPH 2016 course).
pub const GTAO_OFFSETS: [f32; 4] = [0.0, 0.5, 0.25, 0.75];

/// GTAO's noise (Jimenez et al. 2016, as their SIGGRAPH 2016 course slides give it): a 4x4 spatial
/// pattern of the 16 multiples of 1/16 for the rotation and `((y - x) & 3) / 4` for the step
/// offset, turned by [`GTAO_ROTATIONS`] with the frame and offset by [`GTAO_OFFSETS`] every 6
/// frames, so the 24 frames of a cycle see every combination once.
///
/// ```
/// use aokit::noise::gtao_noise;
/// use std::collections::HashSet;
/// // One pixel over GTAO's 24-frame cycle: 6 rotations times 4 step offsets, all different.
/// let cycle: HashSet<[u32; 2]> = (0..24)
///     .map(|frame| gtao_noise([5, 9], frame).map(f32::to_bits))
///     .collect();
/// assert_eq!(cycle.len(), 24);
/// ```
pub fn gtao_noise(pixel: [u32; 2], frame: u32) -> [f32; 2] {
    let [x, y] = pixel;
    let spatial = ((((x.wrapping_add(y)) & 3) << 2) + (x & 3)) as f32 / 16.0;
    let offset = (y.wrapping_sub(x) & 3) as f32 / 4.0;
    let rotation = GTAO_ROTATIONS[(frame % 6) as usize] / 360.0;
    [
        fract(spatial + rotation),
        fract(offset + GTAO_OFFSETS[(frame / 6 % 4) as usize]),
    ]
}

/// The index, `0..16`, of the 4x4 Bayer dither matrix (Bayer 1973) at `pixel`: the 2x2 matrix
/// `[[0, 2], [3, 1]]` of the low coordinate bits, times 4, plus that of the next bits.
///
/// ```
/// use aokit::noise::bayer_index;
/// let first_row: Vec<u32> = (0..4).map(|x| bayer_index([x, 0])).collect();
/// assert_eq!(first_row, [0, 8, 2, 10]);
/// // The matrix repeats every 4 pixels.
/// assert_eq!(bayer_index([6, 5]), bayer_index([2, 1]));
/// ```
pub fn bayer_index(pixel: [u32; 2]) -> u32 {
    let level = |x: u32, y: u32| (((x ^ y) & 1) << 1) | (y & 1);
    4 * level(pixel[0], pixel[1]) + level(pixel[0] >> 1, pixel[1] >> 1)
}

/// The "Dither" noise of the Unity Asset Store package "Horizon Based Ambient Occlusion": the Bayer
/// index over 16, and its 4-bit reversal over 16 as the second value. Bit reversal is the radical
/// inverse, so a tile's 16 pairs are the 16-point Hammersley set: every box of area 1/16 with
/// power-of-two sides holds exactly one pair.
///
/// ```
/// use aokit::noise::bayer_noise;
/// // The index 8 is 0b1000: its 4-bit reversal is 1.
/// assert_eq!(bayer_noise([1, 0]), [8.0 / 16.0, 1.0 / 16.0]);
/// ```
pub fn bayer_noise(pixel: [u32; 2]) -> [f32; 2] {
    let index = bayer_index(pixel);
    [
        index as f32 / 16.0,
        (index.reverse_bits() >> 28) as f32 / 16.0,
    ]
}

/// 2^32 times R2's two generators 1/g and 1/g^2, g the plastic number 1.3247... (Roberts 2018,
/// "The Unreasonable Effectiveness of Quasirandom Sequences"), rounded: a wrapping product with
/// an integer `n` is fract(n * alpha) off by less than `n * 2^-33`, where an `f32` product loses
/// the fraction within a few thousand frames.
const R2_FIXED: [u32; 2] = [3_242_174_889, 2_447_445_414];

/// 2^32 times the golden ratio's fraction 0.618..., rounded.
const GOLDEN_FIXED: u32 = 2_654_435_769;

/// Point `index` of the R2 sequence (Roberts 2018): `fract(0.5 + index * (1/g, 1/g^2))`.
///
/// ```
/// use aokit::noise::r2;
/// assert_eq!(r2(0), [0.5, 0.5]);
/// // 16 points cover the square evenly: each quarter of it holds some.
/// let points: Vec<[f32; 2]> = (0..16).map(r2).collect();
/// for quarter in 0..4 {
///     let (x, y) = ((quarter % 2) as f32 * 0.5, (quarter / 2) as f32 * 0.5);
///     let inside = |p: &&[f32; 2]| p[0] >= x && p[0] < x + 0.5 && p[1] >= y && p[1] < y + 0.5;
///     assert!(points.iter().filter(inside).count() >= 2);
/// }
/// ```
pub fn r2(index: u32) -> [f32; 2] {
    R2_FIXED.map(|a| unit_from_fixed(index.wrapping_mul(a).wrapping_add(1 << 31)))
}

/// Side of the Hilbert-R2 tile is 2^this: 64 pixels, like the default blue-noise tile.
pub const HILBERT_ORDER: u32 = 6;

/// The distance along the Hilbert curve (Hilbert 1891) filling the `2^order` square to the
/// cell `(x, y)`: per level, the quadrant's place in the curve's U, then the coordinates turned
/// into that quadrant's orientation.
///
/// ```
/// use aokit::noise::hilbert_index;
/// // The order-1 curve is a U: (0, 0), (0, 1), (1, 1), (1, 0).
/// let u: Vec<u32> = [[0, 0], [0, 1], [1, 1], [1, 0]].map(|p| hilbert_index(p, 1)).to_vec();
/// assert_eq!(u, [0, 1, 2, 3]);
/// ```
pub fn hilbert_index(pixel: [u32; 2], order: u32) -> u32 {
    let n = 1u32 << order;
    let [mut x, mut y] = pixel.map(|c| c & (n - 1));
    let mut index = 0;
    let mut s = n >> 1;
    while s > 0 {
        let rx = u32::from(x & s != 0);
        let ry = u32::from(y & s != 0);
        index += s * s * ((3 * rx) ^ ry);
        if ry == 0 {
            if rx == 1 {
                x = n - 1 - x;
                y = n - 1 - y;
            }
            std::mem::swap(&mut x, &mut y);
        }
        s >>= 1;
    }
    index
}

/// The R2 point at the pixel's place along the Hilbert curve of a [`HILBERT_ORDER`] tile: the
/// curve keeps consecutive indices next to each other, so neighbouring pixels get R2's
/// well-spread consecutive points.
///
/// ```
/// use aokit::noise::{HILBERT_ORDER, hilbert_r2_noise};
/// let side = 1 << HILBERT_ORDER;
/// // A tile of the pattern: it repeats every `side` pixels.
/// assert_eq!(hilbert_r2_noise([3, 4]), hilbert_r2_noise([3 + side, 4]));
/// ```
pub fn hilbert_r2_noise(pixel: [u32; 2]) -> [f32; 2] {
    r2(hilbert_index(pixel, HILBERT_ORDER))
}

/// How far tiled noise moves at `frame`: frame times the golden ratio's fraction on both values,
/// or R2's frame-th step, `fract(frame * (1/g, 1/g^2))`. Frame 0 is not moved.
///
/// ```
/// use aokit::TemporalOffset;
/// use aokit::noise::temporal_offset;
/// assert_eq!(temporal_offset(TemporalOffset::R2, 0), [0.0, 0.0]);
/// // The golden ratio moves both values alike; R2 moves them apart.
/// let [a, b] = temporal_offset(TemporalOffset::GoldenRatio, 5);
/// assert_eq!(a, b);
/// let [a, b] = temporal_offset(TemporalOffset::R2, 5);
/// assert_ne!(a, b);
/// ```
pub fn temporal_offset(offset: TemporalOffset, frame: u32) -> [f32; 2] {
    match offset {
        TemporalOffset::GoldenRatio => [unit_from_fixed(frame.wrapping_mul(GOLDEN_FIXED)); 2],
        TemporalOffset::R2 => R2_FIXED.map(|a| unit_from_fixed(frame.wrapping_mul(a))),
    }
}

/// The two noise values of `pixel` at `frame`, as `pixel_noise` in `shaders/common/noise.wgsl`
/// computes them. Interleaved gradient noise and GTAO's pattern move with the frame their own
/// way; the tiled kinds (`blue`, `bayer`, `white`, `hilbert-r2`) move by [`temporal_offset`].
///
/// ```
/// use aokit::noise::pixel_noise;
/// use aokit::{NoiseKind, NoiseSettings};
/// // The rotation the kernels give pixel (10, 20) over 4 frames of Bayer noise.
/// let settings = NoiseSettings { kind: NoiseKind::Bayer, ..NoiseSettings::default() };
/// let angles: Vec<f32> = (0..4)
///     .map(|frame| pixel_noise(&settings, [10, 20], frame)[0] * std::f32::consts::TAU)
///     .collect();
/// assert!(angles.windows(2).all(|w| w[0] != w[1]));
/// ```
pub fn pixel_noise(settings: &NoiseSettings, pixel: [u32; 2], frame: u32) -> [f32; 2] {
    let tiled = match settings.kind {
        NoiseKind::Ign => return ign_noise(pixel, frame),
        NoiseKind::Gtao => return gtao_noise(pixel, frame),
        NoiseKind::Bayer => bayer_noise(pixel),
        NoiseKind::HilbertR2 => hilbert_r2_noise(pixel),
        NoiseKind::Blue | NoiseKind::White => tile(settings)
            .expect("blue and white noise have tiles")
            .texel(pixel),
    };
    let offset = temporal_offset(settings.temporal, frame);
    [fract(tiled[0] + offset[0]), fract(tiled[1] + offset[1])]
}

/// Point `index` of the first two dimensions of the Sobol sequence (Sobol 1967), in index
/// order (not Gray-code order), to 24 bits: `sobol_2d` in `shaders/common/noise.wgsl`.
///
/// ```
/// use aokit::noise::sobol_2d;
/// let first: Vec<[f32; 2]> = (0..4).map(sobol_2d).collect();
/// assert_eq!(first, [[0.0, 0.0], [0.5, 0.5], [0.25, 0.75], [0.75, 0.25]]);
/// ```
pub fn sobol_2d(index: u32) -> [f32; 2] {
    let mut i = index;
    let mut column = 0x8000_0000u32;
    let mut second = 0;
    while i != 0 {
        if i & 1 != 0 {
            second ^= column;
        }
        i >>= 1;
        column ^= column >> 1;
    }
    [
        unit_from_fixed(index.reverse_bits()),
        unit_from_fixed(second),
    ]
}

/// Radical inverse of `index` in base 3 (Halton 1960): `halton_3` in `shaders/common/noise.wgsl`.
///
/// ```
/// use aokit::noise::halton_3;
/// // 5 is 12 in base 3; mirrored about the point, 0.21 in base 3 = 2/3 + 1/9.
/// assert!((halton_3(5) - 7.0 / 9.0).abs() < 1e-7);
/// ```
pub fn halton_3(index: u32) -> f32 {
    let mut i = index;
    let mut scale = 1.0 / 3.0;
    let mut result = 0.0;
    while i != 0 {
        result += (i % 3) as f32 * scale;
        i /= 3;
        scale /= 3.0;
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use aokit_eval::spectrum;

    #[test]
    fn mersenne_twister_gives_the_reference_outputs() {
        // The first outputs for seed 5489 (Matsumoto and Nishimura's mt19937ar.c) and the
        // 10000th, which the C++ standard requires of std::mt19937.
        let mut rng = Mt19937::new(5489);
        let first: Vec<u32> = (0..5).map(|_| rng.next_u32()).collect();
        assert_eq!(
            first,
            [3499211612, 581869302, 3890346734, 3586334585, 545404204]
        );
        let mut rng = Mt19937::new(5489);
        assert_eq!((0..10_000).map(|_| rng.next_u32()).last(), Some(4123659995));
    }

    #[test]
    fn white_noise_is_the_twister_in_texel_order() {
        let tile = white_noise();
        assert_eq!(tile.len(), 16);
        assert_eq!(tile[0][0], (3499211612u32 >> 8) as f32 / 16777216.0);
        let mut rng = Mt19937::new(5489);
        for texel in tile {
            assert_eq!(*texel, [rng.next_f32(), rng.next_f32()]);
        }
    }

    #[test]
    fn void_and_cluster_ranks_every_pixel_once_per_channel() {
        for size in [64u32, 128] {
            let tile = blue_noise(size);
            let n = (size * size) as usize;
            assert_eq!(tile.len(), n);
            for channel in 0..2 {
                let mut ranks: Vec<usize> = tile
                    .iter()
                    .map(|t| (t[channel] * n as f32) as usize)
                    .collect();
                ranks.sort_unstable();
                assert!(
                    ranks.iter().enumerate().all(|(i, &r)| i == r),
                    "{size}: {channel}"
                );
            }
            assert_ne!(tile[0], tile[1]);
            assert!(tile.iter().any(|t| t[0] != t[1]), "channels must differ");
        }
    }

    #[test]
    fn void_and_cluster_is_deterministic() {
        assert_eq!(void_and_cluster(32, 7), void_and_cluster(32, 7));
        assert_ne!(void_and_cluster(32, 7), void_and_cluster(32, 8));
    }

    fn channel(tile: &[[f32; 2]], c: usize) -> Vec<f32> {
        tile.iter().map(|t| t[c]).collect()
    }

    #[test]
    fn blue_noise_has_little_power_at_low_frequencies() {
        let size = 64;
        let mut rng = Mt19937::new(1);
        let white: Vec<f32> = (0..size * size).map(|_| rng.next_f32()).collect();
        let white_rings = spectrum::radial_average(&spectrum::power_spectrum(&white, size), size);
        // Uniform values have variance 1/12: white noise's flat level.
        let white_low = white_rings[1..=4].iter().sum::<f64>() / 4.0;
        assert!((0.04..0.16).contains(&white_low), "white {white_low}");
        for c in 0..2 {
            let rings = spectrum::radial_average(
                &spectrum::power_spectrum(&channel(blue_noise(64), c), size),
                size,
            );
            for (r, &p) in rings.iter().enumerate().take(9).skip(1) {
                assert!(p < 0.1 / 12.0, "channel {c}, ring {r}: {p}");
            }
            // The power removed at low frequencies is at high ones: the total is the variance.
            let high = rings[20..].iter().sum::<f64>() / rings[20..].len() as f64;
            assert!(high > 1.1 / 12.0, "channel {c}: high rings {high}");
        }
    }

    #[test]
    fn r2_starts_as_roberts_gives_it() {
        let expected = [
            [0.5, 0.5],
            [0.254_877_67, 0.069_840_29],
            [0.009_755_33, 0.639_680_6],
            [0.764_633, 0.209_520_87],
        ];
        for (n, e) in expected.iter().enumerate() {
            let p = r2(n as u32);
            assert!(
                (p[0] - e[0]).abs() < 1e-6 && (p[1] - e[1]).abs() < 1e-6,
                "{n}: {p:?}"
            );
        }
    }

    #[test]
    fn sobol_matches_the_published_gray_code_table() {
        // Bratley and Fox 1988 and Joe and Kuo 2008 list the sequence in Gray-code order:
        // point n there is point n ^ (n >> 1) here.
        let published = [
            [0.0, 0.0],
            [0.5, 0.5],
            [0.75, 0.25],
            [0.25, 0.75],
            [0.375, 0.375],
            [0.875, 0.875],
            [0.625, 0.125],
            [0.125, 0.625],
        ];
        for (n, p) in published.iter().enumerate() {
            assert_eq!(sobol_2d((n ^ (n >> 1)) as u32), *p, "point {n}");
        }
    }

    #[test]
    fn halton_3_starts_as_the_radical_inverse() {
        let expected = [
            0.0,
            1.0 / 3.0,
            2.0 / 3.0,
            1.0 / 9.0,
            4.0 / 9.0,
            7.0 / 9.0,
            2.0 / 9.0,
        ];
        for (i, e) in expected.iter().enumerate() {
            assert!((halton_3(i as u32) - e).abs() < 1e-7, "{i}");
        }
    }

    #[test]
    fn gtao_spatial_values_are_the_sixteen_sixteenths() {
        let mut rotations: Vec<f32> = (0..4)
            .flat_map(|y| (0..4).map(move |x| gtao_noise([x, y], 5)[0]))
            .collect();
        rotations.sort_by(f32::total_cmp);
        let sixteenths: Vec<f32> = (0..16).map(|i| i as f32 / 16.0).collect();
        assert_eq!(rotations, sixteenths);
        // Frame 5 has no rotation and no offset; the pattern repeats every 4 pixels.
        assert_eq!(gtao_noise([1, 0], 5), [5.0 / 16.0, 0.75]);
        assert_eq!(gtao_noise([5, 4], 5), gtao_noise([1, 0], 5));
        // Frame 0 turns by 60 degrees; frame 6 is the second step offset.
        assert_eq!(gtao_noise([0, 0], 0), [60.0 / 360.0, 0.0]);
        assert_eq!(gtao_noise([0, 0], 6)[1], 0.5);
    }

    #[test]
    fn bayer_matches_the_4x4_matrix_and_pairs_stratify() {
        let matrix = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
        let mut pairs = Vec::new();
        for (y, row) in matrix.iter().enumerate() {
            for (x, &m) in row.iter().enumerate() {
                assert_eq!(bayer_index([x as u32, y as u32]), m);
                assert_eq!(bayer_index([x as u32 + 4, y as u32 + 8]), m);
                pairs.push(bayer_noise([x as u32, y as u32]));
            }
        }
        // A (0, 4, 2)-net: boxes of 1 x 1/16, 1/2 x 1/8, ..., 1/16 x 1 hold one pair each.
        for split in 0..=4 {
            let (cols, rows) = (1 << split, 16 >> split);
            let mut seen = [false; 16];
            for [a, b] in &pairs {
                let cell = (a * cols as f32) as usize * rows + (b * rows as f32) as usize;
                assert!(!seen[cell], "two pairs in one {cols}x{rows} box");
                seen[cell] = true;
            }
        }
    }

    #[test]
    fn the_hilbert_curve_visits_every_cell_through_neighbours() {
        let order = 4;
        let n = 1u32 << order;
        let mut cells = vec![None; (n * n) as usize];
        for y in 0..n {
            for x in 0..n {
                let d = hilbert_index([x, y], order) as usize;
                assert!(cells[d].is_none());
                cells[d] = Some((x as i32, y as i32));
            }
        }
        let cells: Vec<(i32, i32)> = cells.into_iter().map(Option::unwrap).collect();
        assert_eq!(cells[0], (0, 0));
        for w in cells.windows(2) {
            assert_eq!(
                (w[0].0 - w[1].0).abs() + (w[0].1 - w[1].1).abs(),
                1,
                "{w:?}"
            );
        }
        assert_eq!(
            hilbert_index([65, 2], HILBERT_ORDER),
            hilbert_index([1, 2], HILBERT_ORDER)
        );
    }

    #[test]
    fn temporal_offsets_start_at_zero_and_follow_their_sequences() {
        for offset in TemporalOffset::ALL {
            assert_eq!(temporal_offset(offset, 0), [0.0, 0.0]);
        }
        let golden = temporal_offset(TemporalOffset::GoldenRatio, 3)[0];
        assert!((golden - (3.0 * 0.618_034f64).fract() as f32).abs() < 1e-6);
        let r2_step = temporal_offset(TemporalOffset::R2, 1);
        let r2_first = r2(1);
        assert!((r2_step[0] + 0.5 - r2_first[0] - 1.0).abs() < 1e-6);
        // Right after a million frames, where an f32 product is off by up to 0.03.
        let late = temporal_offset(TemporalOffset::GoldenRatio, 1_000_000)[0];
        assert!((late - (1e6 * 0.618_033_988_749_894_9f64).fract() as f32).abs() < 2e-4);
    }

    #[test]
    fn wgsl_codes_are_the_rust_ones() {
        use wgpu::naga;
        let snippet = crate::shader::ShaderSource {
            name: "noise",
            parts: &[crate::shader::NOISE],
        };
        let module = snippet.validate().unwrap();
        let constant = |prefix: &str, name: &str| -> u32 {
            let name = format!("{prefix}_{}", name.to_uppercase().replace('-', "_"));
            let (_, c) = module
                .constants
                .iter()
                .find(|(_, c)| c.name.as_deref() == Some(name.as_str()))
                .unwrap_or_else(|| panic!("noise.wgsl has no {name}"));
            match module.global_expressions[c.init] {
                naga::Expression::Literal(naga::Literal::U32(v)) => v,
                ref e => panic!("{name} = {e:?}"),
            }
        };
        for kind in NoiseKind::ALL {
            assert_eq!(constant("NOISE", kind.name()), kind_code(kind));
        }
        for offset in TemporalOffset::ALL {
            assert_eq!(constant("TEMPORAL", offset.name()), temporal_code(offset));
        }
    }
}
