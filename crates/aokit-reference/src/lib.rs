//! # aokit-reference
//!
//! Ground truth for screen-space ambient occlusion: a CPU ray tracer that computes, for exactly
//! the pixels a rasteriser draws, the ambient occlusion every screen-space method approximates.
//!
//! At each pixel's primary hit it casts cosine-weighted rays over the hemisphere of the
//! geometric normal; AO is the fraction that travel the occlusion radius unblocked (or, with a
//! [`Falloff`], the obscurance variants where far hits count less). Rays come from a Sobol
//! sequence with per-pixel Owen scrambling, leave the surface through a robust offset, and run
//! against a compressed wide BVH ([`obvhs`]) on every core ([`rayon`]). No GPU is involved, so
//! the reference never shares a bug with the methods it scores.
//!
//! ```
//! use aokit_reference::{AoOptions, PixelSampler, Tracer};
//! use glam::Vec3;
//! // A floor and a ceiling 0.5 apart; radius 1: AO is (h / R)^2 = 0.25 (see docs/reference.md).
//! let quad = |y: f32| [-50.0f32, 50.0].iter().flat_map(move |&x| {
//!     [-50.0f32, 50.0].map(|z| Vec3::new(x, y, z))
//! }).collect::<Vec<_>>();
//! let positions = [quad(0.0), quad(0.5)].concat();
//! let tracer = Tracer::new(&positions, &[0, 1, 3, 0, 3, 2, 4, 5, 7, 4, 7, 6])?;
//! let options = AoOptions { radius: 1.0, spp: 4096, ..Default::default() };
//! let ao = tracer.ambient_occlusion(Vec3::ZERO, Vec3::Y, &options, &PixelSampler::new(0, 0));
//! assert!((ao - 0.25).abs() < 0.01);
//! # Ok::<(), aokit_reference::ReferenceError>(())
//! ```

#![warn(missing_docs)]

mod ao;
mod camera;
mod error;
mod offset;
mod options;
mod render;
mod sampling;
mod tracer;
mod watertight;

pub use camera::{Lens, PixelCamera, PrimaryRay};
pub use error::ReferenceError;
pub use offset::offset_origin;
pub use options::{AoOptions, Falloff, MAX_SPP};
pub use render::ReferenceImage;
pub use sampling::{PixelSampler, cosine_hemisphere, tangent_frame};
pub use tracer::{Hit, Tracer};

/// Most pixels a reference image may have: 8192x8192, the budget of `aokit::inputs::MAX_PIXELS`
/// (this crate does not depend on aokit). [`Tracer::render`] and [`Tracer::back_depth`] refuse
/// more before they allocate.
pub const MAX_PIXELS: u64 = 8192 * 8192;
