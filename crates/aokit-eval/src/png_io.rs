//! 8-bit PNG output, to files or to bytes for embedding in reports.

use std::path::Path;

use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder};

use crate::error::{EvalError, Result};

/// Float to 8-bit grey: clamped to [0, 1], NaN as black.
pub(crate) fn grey_bytes(values: &[f32]) -> Vec<u8> {
    values
        .iter()
        .map(|&v| {
            if v.is_nan() {
                0
            } else {
                (v.clamp(0.0, 1.0) * 255.0).round() as u8
            }
        })
        .collect()
}

/// Encodes after checking the size, since the encoder panics on a length mismatch.
fn encode(
    size: [u32; 2],
    bytes: &[u8],
    color: ExtendedColorType,
    channels: u64,
) -> Result<Vec<u8>, String> {
    let [width, height] = size;
    if width == 0 || height == 0 {
        return Err(format!("image size {width}x{height} has no pixels"));
    }
    let expected = u64::from(width) * u64::from(height) * channels;
    if bytes.len() as u64 != expected {
        return Err(format!(
            "{} bytes given for {width}x{height} pixels of {channels} byte(s) each ({expected} needed)",
            bytes.len()
        ));
    }
    let mut out = Vec::new();
    PngEncoder::new(&mut out)
        .write_image(bytes, width, height, color)
        .map_err(|e| e.to_string())?;
    Ok(out)
}

fn write(
    path: &Path,
    size: [u32; 2],
    bytes: &[u8],
    color: ExtendedColorType,
    channels: u64,
) -> Result<()> {
    let png =
        encode(size, bytes, color, channels).map_err(|problem| EvalError::data(path, problem))?;
    std::fs::write(path, png).map_err(|e| EvalError::io(path, "write", e))
}

/// Writes values as an 8-bit grey PNG: clamped to [0, 1], NaN as black, row-major from the top.
pub fn write_grey_png(path: &Path, size: [u32; 2], values: &[f32]) -> Result<()> {
    write(path, size, &grey_bytes(values), ExtendedColorType::L8, 1)
}

/// Writes interleaved RGBA8 pixels as a PNG.
pub fn write_rgba_png(path: &Path, size: [u32; 2], rgba: &[u8]) -> Result<()> {
    write(path, size, rgba, ExtendedColorType::Rgba8, 4)
}

/// Values as an 8-bit grey PNG in memory, mapped as in [`write_grey_png`].
pub fn encode_png_grey(size: [u32; 2], values: &[f32]) -> Result<Vec<u8>> {
    encode(size, &grey_bytes(values), ExtendedColorType::L8, 1)
        .map_err(|problem| EvalError::Encode { problem })
}

/// Interleaved RGB8 pixels as a PNG in memory.
pub fn encode_png_rgb(size: [u32; 2], rgb: &[u8]) -> Result<Vec<u8>> {
    encode(size, rgb, ExtendedColorType::Rgb8, 3).map_err(|problem| EvalError::Encode { problem })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grey_mapping_clamps_and_blackens_nan() {
        assert_eq!(
            grey_bytes(&[-1.0, 0.0, 0.5, 1.0, 2.0, f32::NAN]),
            [0, 0, 128, 255, 255, 0]
        );
    }

    #[test]
    fn wrong_lengths_are_errors() {
        assert!(encode_png_grey([2, 2], &[0.0; 3]).is_err());
        assert!(encode_png_rgb([0, 2], &[]).is_err());
        let png = encode_png_rgb([1, 1], &[1, 2, 3]).unwrap();
        assert!(png.starts_with(b"\x89PNG"));
    }
}
