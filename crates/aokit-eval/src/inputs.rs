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
        Kind::Exr => read_depth_exr(path, None),
        Kind::Pfm => pfm::parse(path, &read_file(path)?, 1),
        Kind::Npy => npy::parse(path, &read_file(path)?, 1),
    }
}

/// Reads a depth pass from a file's contents held in memory, as [`read_depth`] reads the file:
/// `path` picks the format by its extension and names the file in errors; nothing is read from
/// it.
///
/// ```
/// use std::path::Path;
/// // A 2x1 grey PFM, little-endian (negative scale), as another program might send it.
/// let mut pfm = b"Pf\n2 1\n-1.0\n".to_vec();
/// for depth in [1.5f32, 2.0] {
///     pfm.extend(depth.to_le_bytes());
/// }
/// let depth = aokit_eval::parse_depth(Path::new("depth.pfm"), &pfm)?;
/// assert_eq!((depth.width, depth.height, depth.data), (2, 1, vec![1.5, 2.0]));
/// assert!(aokit_eval::parse_depth(Path::new("depth.pfm"), b"Pf\n2 1\n-1.0\n").is_err());
/// # Ok::<(), aokit_eval::EvalError>(())
/// ```
pub fn parse_depth(path: &Path, bytes: &[u8]) -> Result<FloatImage> {
    match kind(path)? {
        Kind::Exr => read_depth_exr(path, Some(bytes)),
        Kind::Pfm => pfm::parse(path, bytes, 1),
        Kind::Npy => npy::parse(path, bytes, 1),
    }
}

/// Reads a normal pass (three channels) from `.exr` (channels `X, Y, Z` or `R, G, B`, plain or
/// layer-qualified such as `Normal.X`, preferring a layer whose name mentions "normal"),
/// `.pfm` (`PF`) or `.npy` (`(H, W, 3)`).
pub fn read_normals(path: &Path) -> Result<FloatImage> {
    match kind(path)? {
        Kind::Exr => read_normals_exr(path, None),
        Kind::Pfm => pfm::parse(path, &read_file(path)?, 3),
        Kind::Npy => npy::parse(path, &read_file(path)?, 3),
    }
}

/// Reads a normal pass from a file's contents held in memory, as [`read_normals`] reads the
/// file: `path` picks the format by its extension and names the file in errors.
///
/// ```
/// use std::path::Path;
/// // One pixel facing the camera, big-endian (positive scale).
/// let mut pfm = b"PF\n1 1\n1.0\n".to_vec();
/// for c in [0.0f32, 0.0, 1.0] {
///     pfm.extend(c.to_be_bytes());
/// }
/// let normals = aokit_eval::parse_normals(Path::new("normals.pfm"), &pfm)?;
/// assert_eq!((normals.channels, normals.data), (3, vec![0.0, 0.0, 1.0]));
/// # Ok::<(), aokit_eval::EvalError>(())
/// ```
pub fn parse_normals(path: &Path, bytes: &[u8]) -> Result<FloatImage> {
    match kind(path)? {
        Kind::Exr => read_normals_exr(path, Some(bytes)),
        Kind::Pfm => pfm::parse(path, bytes, 3),
        Kind::Npy => npy::parse(path, bytes, 3),
    }
}
