//! Portable Float Map files: `Pf` (grey) and `PF` (RGB) 32-bit floats.
//!
//! The header is three whitespace-separated tokens (type, width height, scale) followed by one
//! whitespace byte; the sign of the scale gives the byte order (negative = little-endian) and rows
//! are stored from the bottom of the image up.

use std::path::Path;

use crate::error::{EvalError, Result};
use crate::float_image::{FloatImage, sample_count};

/// Longest header token accepted; real headers have a handful of digits.
const MAX_TOKEN: usize = 64;

struct Header<'a> {
    bytes: &'a [u8],
    pos: usize,
}

impl<'a> Header<'a> {
    /// The next whitespace-delimited token, or `None` at the end of the data.
    fn token(&mut self) -> Option<&'a str> {
        while self
            .bytes
            .get(self.pos)
            .is_some_and(u8::is_ascii_whitespace)
        {
            self.pos += 1;
        }
        let start = self.pos;
        while self
            .bytes
            .get(self.pos)
            .is_some_and(|b| !b.is_ascii_whitespace())
            && self.pos - start < MAX_TOKEN
        {
            self.pos += 1;
        }
        std::str::from_utf8(&self.bytes[start..self.pos])
            .ok()
            .filter(|t| !t.is_empty())
    }

    /// The next token parsed as a `T`, or why not.
    fn field<T: std::str::FromStr>(&mut self, what: &str, kind: &str) -> Result<T, String> {
        let token = self
            .token()
            .ok_or_else(|| format!("PFM header ends before the {what}"))?;
        token
            .parse()
            .map_err(|_| format!("PFM {what} {token:?} is not {kind}"))
    }
}

/// Parses a PFM with `channels` (1 or 3) samples per pixel into a top-row-first image.
pub(crate) fn parse(path: &Path, bytes: &[u8], channels: u32) -> Result<FloatImage> {
    let bad = |problem: String| EvalError::format(path, problem);
    let mut header = Header { bytes, pos: 0 };
    let file_channels = match header.token() {
        Some("Pf") => 1,
        Some("PF") => 3,
        _ => {
            return Err(bad(
                "not a PFM file (it must start with \"Pf\" or \"PF\")".to_string()
            ));
        }
    };
    if file_channels != channels {
        let (want, kind) = if channels == 1 {
            ("Pf", "depth")
        } else {
            ("PF", "normals")
        };
        return Err(bad(format!(
            "PFM has {file_channels} channel(s); {kind} need a {want} file with {channels}"
        )));
    }
    let width: u32 = header.field("width", "a whole number").map_err(bad)?;
    let height: u32 = header.field("height", "a whole number").map_err(bad)?;
    let scale: f32 = header.field("scale", "a number").map_err(bad)?;
    if !scale.is_finite() || scale == 0.0 {
        return Err(bad(format!(
            "PFM scale {scale} must be finite and non-zero; its sign gives the byte order"
        )));
    }
    // Exactly one whitespace byte separates the header from the samples.
    if !bytes.get(header.pos).is_some_and(u8::is_ascii_whitespace) {
        return Err(bad(
            "PFM header is not followed by a whitespace byte".to_string()
        ));
    }
    let data = &bytes[header.pos + 1..];
    let count = sample_count(path, width.into(), height.into(), channels.into())?;
    let expected = count
        .checked_mul(4)
        .ok_or_else(|| bad(format!("PFM size {width}x{height} is too large")))?;
    if data.len() != expected {
        return Err(bad(format!(
            "PFM data is {} bytes but {width}x{height}x{channels} floats need {expected}",
            data.len()
        )));
    }
    let little_endian = scale < 0.0;
    let row_len = width as usize * channels as usize;
    let mut samples = Vec::with_capacity(count);
    // Flip: the file's last row is the image's top row.
    for row in data.chunks_exact(row_len * 4).rev() {
        samples.extend(row.chunks_exact(4).map(|b| {
            let b = [b[0], b[1], b[2], b[3]];
            if little_endian {
                f32::from_le_bytes(b)
            } else {
                f32::from_be_bytes(b)
            }
        }));
    }
    Ok(FloatImage {
        width,
        height,
        channels,
        data: samples,
    })
}
