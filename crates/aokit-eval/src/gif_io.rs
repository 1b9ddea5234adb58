//! Animated GIF previews of frame sequences: a camera path at a glance, in any browser.

use std::path::Path;

use image::codecs::gif::{GifEncoder, Repeat};
use image::{Delay, Frame, RgbaImage};

use crate::error::{EvalError, Result};
use crate::png_io::grey_bytes;

/// Writes `frames` (RGBA8, row by row, each `size`) as a looping GIF, `delay_ms` per frame.
/// GIF keeps 256 colours per frame, plenty for AO and a fair preview of a lit image.
///
/// ```
/// let dir = tempfile::tempdir()?;
/// let red_then_blue = [[255, 0, 0, 255].repeat(4), [0, 0, 255, 255].repeat(4)];
/// aokit_eval::write_gif(&dir.path().join("a.gif"), [2, 2], &red_then_blue, 100)?;
/// assert!(std::fs::metadata(dir.path().join("a.gif"))?.len() > 0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_gif(path: &Path, size: [u32; 2], frames: &[Vec<u8>], delay_ms: u32) -> Result<()> {
    let data_error = |problem: String| EvalError::Data {
        path: path.to_path_buf(),
        problem,
    };
    if frames.is_empty() {
        return Err(data_error("no frames".to_string()));
    }
    let images = frames
        .iter()
        .enumerate()
        .map(|(i, rgba)| {
            RgbaImage::from_raw(size[0], size[1], rgba.clone()).ok_or_else(|| {
                data_error(format!(
                    "frame {i} has {} bytes, not {}x{} RGBA pixels",
                    rgba.len(),
                    size[0],
                    size[1]
                ))
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let file = std::fs::File::create(path).map_err(|error| EvalError::Io {
        path: path.to_path_buf(),
        action: "write",
        error,
    })?;
    let mut encoder = GifEncoder::new_with_speed(std::io::BufWriter::new(file), 10);
    encoder
        .set_repeat(Repeat::Infinite)
        .map_err(|e| data_error(e.to_string()))?;
    let delay = Delay::from_numer_denom_ms(delay_ms, 1);
    encoder
        .encode_frames(
            images
                .into_iter()
                .map(|image| Frame::from_parts(image, 0, 0, delay)),
        )
        .map_err(|e| data_error(e.to_string()))
}

/// Grey values in [0, 1] as RGBA8 (clamped, NaN as black), for [`write_gif`].
pub fn grey_to_rgba(values: &[f32]) -> Vec<u8> {
    grey_bytes(values)
        .into_iter()
        .flat_map(|g| [g, g, g, 255])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_of_the_wrong_size_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let err = write_gif(&dir.path().join("x.gif"), [2, 2], &[vec![0; 3]], 50).unwrap_err();
        assert!(err.to_string().contains("frame 0"), "{err}");
        assert!(write_gif(&dir.path().join("y.gif"), [2, 2], &[], 50).is_err());
        assert_eq!(
            grey_to_rgba(&[0.5, f32::NAN]),
            [128, 128, 128, 255, 0, 0, 0, 255]
        );
    }
}
