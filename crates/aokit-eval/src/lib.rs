//! # aokit-eval
//!
//! Image I/O and error metrics for scoring ambient occlusion against a reference.
//!
//! AO values are in [0, 1] with 1 = unoccluded and 0 = fully occluded. Every image is row-major
//! from the top-left pixel. The crate reads depth and normal passes ([`read_depth`],
//! [`read_normals`]: EXR, PFM or NPY) and AO images ([`read_scalar_exr`]), writes EXR and PNG,
//! scores an AO image against a reference over a pixel mask ([`compare`], [`surface_mask`],
//! [`depth_edge_mask`]), draws signed error maps ([`error_map_rgb`], [`legend_rgb`]) and
//! renders comparison reports ([`report::Report`]). It does not depend on wgpu.
//!
//! ```
//! use aokit_eval::{compare, error_map_rgb, surface_mask};
//!
//! let size = [2, 2];
//! let depth = [1.0, 1.0, 0.0, 2.0]; // the third pixel is background
//! let reference = [1.0, 0.5, 0.0, 0.25];
//! let ao = [1.0, 0.6, 0.9, 0.25];
//! let mask = surface_mask(&depth);
//! let m = compare(size, &ao, &reference, &mask);
//! assert_eq!(m.pixels, 3);
//! assert!((m.bias - 0.1 / 3.0).abs() < 1e-6); // positive: the method under-occludes
//! let rgb = error_map_rgb(&ao, &reference, &mask, 0.25);
//! assert_eq!(&rgb[6..9], &[128, 128, 128]); // background is grey
//! ```

#![warn(missing_docs)]

mod base64;
mod channel_pick;
mod colormap;
mod error;
mod exr_io;
mod float_image;
mod gif_io;
mod inputs;
mod masks;
mod metrics;
mod npy;
mod pfm;
mod png_io;
pub mod report;
pub mod spectrum;
mod ssim;

pub use colormap::{error_map_rgb, legend_rgb};
pub use error::{EvalError, Result};
pub use exr_io::{read_scalar_exr, write_exr};
pub use float_image::FloatImage;
pub use gif_io::{grey_to_rgba, write_gif};
pub use inputs::{parse_depth, parse_normals, read_depth, read_normals};
pub use masks::{depth_edge_mask, grazing_mask, surface_mask};
pub use metrics::{Metrics, SequenceMetrics, compare, rmse};
pub use png_io::{encode_png_grey, encode_png_rgb, write_grey_png, write_rgba_png};
