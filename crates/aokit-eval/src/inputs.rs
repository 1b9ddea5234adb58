//! Depth and normal passes from files, chosen by extension.

use std::path::Path;

use crate::error::{EvalError, Result, read_file};
use crate::exr_io::{read_depth_exr, read_normals_exr};
use crate::float_image::FloatImage;
use crate::{npy, pfm};

#[derive(Clone, Copy)]
enum Kind {
    Exr,
    Pfm,
    Npy,
}

fn kind(path: &Path) -> Result<Kind> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("exr") => Ok(Kind::Exr),
        Some("pfm") => Ok(Kind::Pfm),
        Some("npy") => Ok(Kind::Npy),
        _ => Err(EvalError::format(
            path,
            "unsupported file type; expected .exr, .pfm or .npy",
        )),
    }
}

/// Reads a depth pass (one channel) from `.exr`, `.pfm` (`Pf`) or `.npy` (`(H, W)` or
/// `(H, W, 1)`), extension matched case-insensitively.
///
/// Values are kept as stored, so background pixels stay 0, infinite or NaN for the caller to
/// interpret. In an EXR, the first layer with a matching channel is used: a bare `Z` or a name
/// with a `depth` part (`Depth.V`, `ViewLayer.Depth.Z`) first, then a bare `Y`, `R`, `V` or
/// `depth`, then a layer-qualified name ending in one of those; a file with a single channel is
/// read whatever its name. Half- and single-precision samples are both accepted.
pub fn read_depth(path: &Path) -> Result<FloatImage> {
    match kind(path)? {
        Kind::Exr => read_depth_exr(path),
        Kind::Pfm => pfm::parse(path, &read_file(path)?, 1),
        Kind::Npy => npy::parse(path, &read_file(path)?, 1),
    }
}

/// Reads a normal pass (three channels) from `.exr` (channels `X, Y, Z` or `R, G, B`, plain or
/// layer-qualified such as `Normal.X`, preferring a layer whose name mentions "normal"),
/// `.pfm` (`PF`) or `.npy` (`(H, W, 3)`).
pub fn read_normals(path: &Path) -> Result<FloatImage> {
    match kind(path)? {
        Kind::Exr => read_normals_exr(path),
        Kind::Pfm => pfm::parse(path, &read_file(path)?, 3),
        Kind::Npy => npy::parse(path, &read_file(path)?, 3),
    }
}
