//! The in-memory float image every reader returns.

use std::path::Path;

use crate::error::{EvalError, Result};

/// A float image: `width * height` pixels of `channels` interleaved samples each, row-major from
/// the top-left pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct FloatImage {
    /// Pixels per row.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Samples per pixel (1 for depth and AO, 3 for normals).
    pub channels: u32,
    /// `width * height * channels` samples.
    pub data: Vec<f32>,
}

impl FloatImage {
    /// The sample at column `x`, row `y`, channel `c`, or `None` outside the image.
    pub fn get(&self, x: u32, y: u32, c: u32) -> Option<f32> {
        if x >= self.width || y >= self.height || c >= self.channels {
            return None;
        }
        let index =
            (y as usize * self.width as usize + x as usize) * self.channels as usize + c as usize;
        self.data.get(index).copied()
    }
}

/// The sample count of a `width x height x channels` image, refusing empty images and sizes whose
/// count does not fit in memory.
pub(crate) fn sample_count(path: &Path, width: u64, height: u64, channels: u64) -> Result<usize> {
    if width == 0 || height == 0 {
        return Err(EvalError::format(
            path,
            format!("image is {width}x{height}; it needs at least one pixel"),
        ));
    }
    if width > u64::from(u32::MAX) || height > u64::from(u32::MAX) {
        return Err(EvalError::format(
            path,
            format!("image size {width}x{height} is too large"),
        ));
    }
    width
        .checked_mul(height)
        .and_then(|n| n.checked_mul(channels))
        .and_then(|n| usize::try_from(n).ok())
        .ok_or_else(|| {
            EvalError::format(
                path,
                format!("image size {width}x{height}x{channels} is too large"),
            )
        })
}
