//! Image files: 8-bit PNG for looking at, 32-bit float EXR for measuring.

use std::path::Path;

use anyhow::{Context, Result};
use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer, LayerAttributes, SmallVec,
    WritableImage,
};

/// A single-channel image as 8-bit grey, values clamped to [0, 1].
pub fn write_grey_png(path: &Path, size: [u32; 2], values: &[f32]) -> Result<()> {
    let bytes: Vec<u8> = values
        .iter()
        .map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)
        .collect();
    image::save_buffer(path, &bytes, size[0], size[1], image::ExtendedColorType::L8)
        .with_context(|| format!("cannot write {}", path.display()))
}

/// RGBA8 pixels as PNG.
pub fn write_rgba_png(path: &Path, size: [u32; 2], rgba: &[u8]) -> Result<()> {
    image::save_buffer(
        path,
        rgba,
        size[0],
        size[1],
        image::ExtendedColorType::Rgba8,
    )
    .with_context(|| format!("cannot write {}", path.display()))
}

/// Named 32-bit float channels of equal size as one EXR layer.
pub fn write_exr(path: &Path, size: [u32; 2], channels: &[(&str, Vec<f32>)]) -> Result<()> {
    let channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = channels
        .iter()
        .map(|(name, data)| AnyChannel::new(*name, FlatSamples::F32(data.clone())))
        .collect();
    let layer = Layer::new(
        (size[0] as usize, size[1] as usize),
        LayerAttributes::default(),
        Encoding::FAST_LOSSLESS,
        AnyChannels::sort(channels),
    );
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .with_context(|| format!("cannot write {}", path.display()))
}
